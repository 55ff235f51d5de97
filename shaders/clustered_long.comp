#version 450 core
// clustered: part CLUSTER_LIST_PART_LOCATION's `part` (1, 2, ...) of the long light lists
// (lib/cluster_lists.glsl), added to the lit image. One workgroup per tile that
// cluster_long_lists.comp listed, an invocation per pixel; a dispatch per part, each as large
// as the number of such tiles (an indirect dispatch: the CPU does not know it). Pixels whose
// cluster's list is shorter than the part add nothing and store nothing. Loop iterations:
// CLUSTER_LIST_PART.
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_lists.glsl"

layout(local_size_x = CLUSTER_TILE_SIZE, local_size_y = CLUSTER_TILE_SIZE) in;
layout(location = CLUSTER_LIST_PART_LOCATION) uniform uint part;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = LIT_IMAGE_UNIT, rgba32f) uniform image2D litImage;
layout(std430, binding = CLUSTER_LONG_TILES_BUFFER_BINDING) readonly buffer LongListTiles {
    uint longListTile[];
};

void main()
{
    uint tile = longListTile[gl_WorkGroupID.x];
    uvec2 lo;
    uvec2 hi;
    clusterTilePixels(tile, lo, hi);
    ivec2 pixel = ivec2(lo + gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), hi)) || texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return;
    Surface s = gbufferSurface(pixel);
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
    if (clusterListCount[cluster] <= part * uint(CLUSTER_LIST_PART))
        return;
    vec3 V = viewVector(s.position);
    uint evaluated = 0u;
    vec3 color = shadeClusterListPart(cluster, part, s, V, evaluated);
    recordLightEvaluationsAt(pixel, evaluated);
    imageStore(litImage, pixel, vec4(imageLoad(litImage, pixel).rgb + color, 1.0));
}
