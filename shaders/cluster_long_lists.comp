#version 450 core
// Clustered, once per frame after the lists are sorted (render/culling/ClusterLists.h): one invocation
// per tile notes the frame's longest list and lists the tiles with a list longer than one
// part (CLUSTER_LIST_PART lights, what one invocation of the lighting may walk): the later
// parts of those lists are lit by passes over those tiles only (long_list_lighting.comp), the
// rest of the image by the one lighting pass, a workgroup per listed tile (x, then z past
// 32,768: an 8K image has 129,600 tiles, and a scene whose lights all reach every cluster may
// list them all). Loop iterations: CLUSTER_SLICES.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_list_status.glsl"
#include "lib/listed_dispatch.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = CLUSTER_LIST_COUNTS_BUFFER_BINDING) readonly buffer ClusterListCounts {
    uint clusterListCount[];
};
layout(std430, binding = CLUSTER_LONG_TILES_BUFFER_BINDING) writeonly buffer LongListTiles {
    uint longListTile[];
};

void main()
{
    uvec2 grid = clusterTileGrid();
    uint tile = gl_GlobalInvocationID.x;
    if (tile >= grid.x * grid.y)
        return;
    uint longest = 0u;
    for (uint k = 0u; k < uint(CLUSTER_SLICES); ++k)
        longest = max(longest, clusterListCount[tile * uint(CLUSTER_SLICES) + k]);
    if (longest == 0u)
        return;
    atomicMax(longestList, longest);
    if (longest > uint(CLUSTER_LIST_PART)) {
        uint listed = atomicAdd(longTiles, 1u);
        longListTile[listed] = tile;
        uvec2 growth = listedDispatchGrowth(listed, 1u);
        if (growth.x != 0u)
            atomicAdd(longTileGroups[0], 1u);
        if (growth.y != 0u)
            atomicAdd(longTileGroups[2], 1u);
    }
}
