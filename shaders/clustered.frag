#version 450 core
// clustered: each covered pixel shades the global terms and the lights of its cluster in
// the current light batch (lib/cluster_lights.glsl walks the cluster's bit mask).
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_lights.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    uint tile = clusterTileOfPixel(uvec2(gl_FragCoord.xy));
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
    uint evaluated = 0u;
    color += shadeClusterLights(cluster, s, V, evaluated);
    recordLightEvaluations(evaluated);
    outColor = vec4(color, 1.0);
}
