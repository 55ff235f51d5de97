#version 450 core
// clustered: each covered pixel shades the global terms, the global lights and the first part
// of its cluster's light list (lib/cluster_lists.glsl); list_lighting.comp adds the later parts
// of long lists.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_lists.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = shadeGlobal(s, V);
    uint tile = clusterTileOfPixel(uvec2(gl_FragCoord.xy));
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
    uint evaluated = 0u;
#ifdef GLOBAL_LIGHT_LIST
    color += shadeGlobalLights(s, V, evaluated);
#endif
    color += shadeClusterListPart(cluster, 0u, s, V, evaluated);
    recordLightEvaluations(evaluated);
    outColor = vec4(color, 1.0);
}
