#version 450 core
// Part `part` (1, 2, ...) of the light lists longer than a part, for the clustered and tiled
// techniques, after their lighting of part 0 (clustered.frag, every_tile_lighting.comp). One
// workgroup per tile that cluster_long_lists.comp listed (an indirect dispatch: the CPU does
// not know how many; lib/listed_dispatch.glsl), an invocation per pixel; pixels whose
// cluster's list is shorter than the part store nothing, the others add the part to the lit
// image (lib/list_pixel.glsl). Built without GLOBAL_LIGHT_LIST: part 0 walks the global list.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
// The status before lib/cluster_lists.glsl, which includes it only when counting work: the
// later parts read the number of tiles listed.
#include "lib/cluster_list_status.glsl"
#include "lib/cluster_lists.glsl"
#include "lib/listed_dispatch.glsl"
#include "lib/lighting_stage.glsl"
#include "lib/list_pixel.glsl"

layout(local_size_x = CLUSTER_TILE_SIZE, local_size_y = CLUSTER_TILE_SIZE) in;
layout(location = CLUSTER_LIST_PART_LOCATION) uniform uint part;
layout(std430, binding = CLUSTER_LONG_TILES_BUFFER_BINDING) readonly buffer LongListTiles {
    uint longListTile[];
};

void main()
{
    uint listed = listedGroup();
    if (listed >= longTiles)
        return;
    uint tile = longListTile[listed];
    uvec2 lo;
    uvec2 hi;
    clusterTilePixels(tile, lo, hi);
    ivec2 pixel = ivec2(lo + gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), hi)) || !isLitPixel(pixel))
        return;
    Surface s = gbufferSurface(pixel);
    uint cluster = clusterOfSurface(s, tile);
    if (clusterListCount[cluster] <= part * uint(CLUSTER_LIST_PART))
        return;
    storeLitPixel(pixel, shadeListPixel(pixel, s, cluster, part, false), true);
}
