#version 450 core
// clustered: each covered pixel shades the global terms and the lights of its cluster.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = shadeGlobal(s, V);
    uint cluster = clusterIndex(clusterOfPixel(gl_FragCoord.xy, viewDepth(s.position)));
    uint offset = clusterOffsets[cluster];
    uint count = clusterCounts[cluster];
    for (uint i = 0u; i < count; ++i)
        color += shadeLocal(clusterLightIndices[offset + i], s, V);
    recordLightEvaluations(count);
    outColor = vec4(color, 1.0);
}
