#version 450 core
// clustered: each covered pixel shades the global terms, the global lights and the first part
// of its cluster's light list (lib/list_pixel.glsl); long_list_lighting.comp adds the later
// parts of long lists.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_lists.glsl"
#include "lib/lighting_stage.glsl"
#include "lib/list_pixel.glsl"

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface s = gbufferSurface(pixel);
    uint cluster = clusterOfSurface(s, clusterTileOfPixel(uvec2(gl_FragCoord.xy)));
    outColor = vec4(shadeListPixel(pixel, s, cluster, 0u, true), 1.0);
}
