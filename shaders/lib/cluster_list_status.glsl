// What the light-list passes of a frame found (render/culling/ClusterLists.h: ClusterLists::Status): the
// CPU sets it before the passes and reads it after the frame, when the renderer has waited
// for the frame anyway. The groups are indirect dispatches: their x (and z) count what the
// GPU found.
// The global lights (lib/cluster_lists.glsl) are the lights cluster_pairs.comp found covering
// most of the grid: at most GLOBAL_LIGHT_CAPACITY of them, all or none (ClusterLists.h says why).
layout(std430, binding = CLUSTER_LIST_STATUS_BUFFER_BINDING) buffer ClusterListStatus {
    // The tiles holding a list longer than a part, a workgroup each (x, then z past 32,768 in
    // x) of long_list_lighting.comp; their count is longTiles.
    uint longTileGroups[3];
    uint pairsNeeded;        // (cluster, light) pairs of the frame: the list storage it needs
    uint longestList;        // the longest cluster list
    // The lights covering more tiles than one invocation takes, a workgroup each (x, then z past
    // 32,768 in x) per band (y).
    uint wideLightGroups[3];
    uint listVisits;          // --count-work: list entries the lighting walked, all pixels
    uint wideLights;
    // cluster_pairs.comp's writing run of narrow lights: 64 lights a workgroup (x, then z past
    // 32,768 in x).
    uint pairedLightGroups[3];
    uint pairedLights;  // the narrow lights with pairs
    uint globalLightCandidates;  // lights covering enough of the grid to be global, all of them
    uint longTiles;              // the tiles cluster_long_lists.comp listed
};

#ifdef GLOBAL_LIGHT_CAPACITY
// The lights of the global list: every candidate, or none where they are more than it holds
// (they are then wide lights, given pairs like any other).
uint globalLightCount()
{
    return globalLightCandidates <= uint(GLOBAL_LIGHT_CAPACITY) ? globalLightCandidates : 0u;
}
#endif
