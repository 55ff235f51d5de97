// The cluster grid of the clustered technique (render/techniques/ClusteredTechnique.h): screen tiles of
// CLUSTER_TILE_SIZE pixels, each cut into CLUSTER_SLICES depth slices spaced exponentially
// from the nearest surface seen through that tile to the farthest (so no slice is spent on
// empty depth before or after the tile's surfaces).
//
// Per tile: its depth range and which of its slices hold a surface. Per cluster and light
// batch: a bit mask over the batch's lights (bit i: light first + i may reach the cluster)
// and, one bit per mask word, which words are not empty, so that shading skips empty words.
// Bit masks rather than lists: building them needs no counting pass, prefix sum or sort,
// their size is known before the frame (nothing can overflow, nothing is read back), and a
// pixel walks its lights in index order, the order forward adds them in.
#include "lib/bindings.glsl"
layout(std430, binding = CLUSTER_TILE_DEPTHS_BUFFER_BINDING) buffer ClusterTileDepths {
    // x, y: the view depths where the tile's slice 0 starts and its last slice ends (0 when
    // the tile is empty); z: the log of x; w: CLUSTER_SLICES / log(y / x), so that the slice
    // of a depth costs one log (tileSlicing makes it).
    vec4 tileDepthRange[];
};
layout(std430, binding = CLUSTER_TILE_SLICES_BUFFER_BINDING) buffer ClusterTileSlices {
    uint tileOccupiedSlices[];  // bit k: slice k holds at least one pixel's surface
};
#ifdef CLUSTER_SURFACE_BOUNDS
// The view-space box around the surfaces each occupied cluster holds, set by
// cluster_tiles.comp: [2 · c] the low corner, [2 · c + 1] the high one. Far tighter than the frustum's section where lights
// are small: a light floating above the ground misses the box of the ground's pixels though
// it reaches into their slice of the frustum.
layout(std430, binding = CLUSTER_BOUNDS_BUFFER_BINDING) buffer ClusterBounds {
    vec4 clusterBounds[];
};
#endif
layout(std430, binding = CLUSTER_LIGHT_MASKS_BUFFER_BINDING) buffer ClusterLightMasks {
    // cluster c, word w of its mask of W words: [c * W + w]; W is lightBatchMaskWords() for the
    // transparency grid, a word per 32 lights of the frame for the light lists
    uint clusterLightMasks[];
};
layout(std430, binding = CLUSTER_MASK_SUMMARIES_BUFFER_BINDING) buffer ClusterMaskSummaries {
    uint clusterMaskSummaries[];  // cluster c: [c * clusterMaskSummaryWords(W) + w / 32], bit w % 32
};

// The summary words of a cluster mask of `words` words: a bit per mask word.
uint clusterMaskSummaryWords(uint words)
{
    return (words + 31u) / 32u;
}

// Sets bit `bit` of word `word` of cluster `cluster`'s mask of `words` words. With
// `summarised`, the first bit set in a word marks the word in the cluster's summary (the
// transparency grid's masks always have one; the light lists' from 33 words:
// cluster_mask_lists.comp says why).
void setClusterMaskBit(uint cluster, uint words, uint word, uint bit, bool summarised)
{
    if (atomicOr(clusterLightMasks[cluster * words + word], bit) == 0u && summarised)
        atomicOr(clusterMaskSummaries[cluster * clusterMaskSummaryWords(words) + word / 32u], 1u << (word % 32u));
}

// Whether the light lists' masks of `words` words a cluster have summaries
// (cluster_pairs.comp, cluster_mask_lists.comp).
bool listMaskSummarised(uint words)
{
    return words > 32u;
}

uvec2 clusterTileGrid()
{
    return (uvec2(frame.viewport.xy) + uint(CLUSTER_TILE_SIZE - 1)) / uint(CLUSTER_TILE_SIZE);
}

// The pixels of tile `tile`: lo ≤ pixel < hi, cut at the image's edge.
void clusterTilePixels(uint tile, out uvec2 lo, out uvec2 hi)
{
    uvec2 grid = clusterTileGrid();
    lo = uvec2(tile % grid.x, tile / grid.x) * uint(CLUSTER_TILE_SIZE);
    hi = min(lo + uint(CLUSTER_TILE_SIZE), uvec2(frame.viewport.xy));
}

uint clusterTileOfPixel(uvec2 pixel)
{
    uvec2 tile = pixel / uint(CLUSTER_TILE_SIZE);
    return tile.y * clusterTileGrid().x + tile.x;
}

// A tile's slicing (tileDepthRange) for its surfaces' depth range: the range divided evenly
// in log space. (A floor on the ratio, slices no thinner than 5% of their depth, was measured:
// it culled worse and shaded slower, docs/techniques.md.)
vec4 tileSlicing(vec2 range)
{
    return vec4(range, log(range.x), float(CLUSTER_SLICES) / log(range.y / range.x));
}

// The slice coordinate of a view depth whose log is logDepth, in a tile sliced by `slicing`:
// slice k holds k ≤ coordinate < k + 1. Depths outside the range fall in the end slices.
float sliceCoordinateOfLog(float logDepth, vec4 slicing)
{
    return (max(logDepth, slicing.z) - slicing.z) * slicing.w;
}

float sliceCoordinate(float z, vec4 slicing)
{
    return sliceCoordinateOfLog(log(z), slicing);
}

uint sliceOfDepth(float z, vec4 slicing)
{
    return uint(clamp(floor(sliceCoordinate(z, slicing)), 0.0, float(CLUSTER_SLICES - 1)));
}
