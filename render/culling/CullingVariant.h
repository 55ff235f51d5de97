// One typed key for the culling's programs (issue 46): what a program of the cluster grid,
// the light lists, the pair sort or the prefix sum is compiled for, one field per dimension,
// with one toDefines(). The programs that vary from frame to frame are cached by it
// (ProgramVariants<CullingVariant>, render/programs/ProgramVariants.h: cluster_pairs.comp's);
// those made once compile from it at construction. The lighting programs that read the grid
// or the lists take its defines as their own (render/programs/LightingPrograms.h).
#pragma once

#include <compare>
#include <cstdint>
#include <optional>

#include "gl/Program.h"
#include "render/culling/ClusterGrid.h"

namespace manylights {

// What a program of cluster_pairs.comp does with the pairs it finds: counts them, writes them
// to their slots, or sets them in the masks (and counts each cluster's).
enum class PairRun : std::uint8_t { Count, Write, Mask };
// A pass of pair_sort.comp: counting a digit, scattering by it, or scattering by the last
// digit with the lights' spheres.
enum class SortPass : std::uint8_t { Count, Scatter, ScatterGather };
// A step of scan.comp (render/culling/GpuScan.h): each block's sum, the sum of the top level,
// the sums spread back over the blocks (SCAN_STEP 0, 1, 2).
enum class ScanStep : std::uint8_t { Reduce, Top, Spread };

struct CullingVariant {
    // Programs that include lib/clusters.glsl: the grid's shape (CLUSTER_TILE_SIZE,
    // CLUSTER_SLICES, CLUSTER_SURFACE_BOUNDS).
    std::optional<ClusterGridShape> grid{};
    // The grid's tiles and boxes read as texels (CLUSTER_GRID_TEXELS, ClusterGrid::hasTexels).
    bool gridTexels = false;
    // A workgroup per light and band of tile rows (LIGHT_TILE_LANES, render/culling/LightTiles.h);
    // of cluster_pairs.comp, the wide lights' programs (WIDE_LIGHTS).
    bool lightTiles = false;
    // Programs that include lib/cluster_lists.glsl: a list's part and the global list's
    // capacity (CLUSTER_LIST_PART, GLOBAL_LIGHT_CAPACITY).
    bool lightLists = false;
    // Programs that fill the global list (GLOBAL_LIGHT_CAPACITY).
    bool globalLights = false;
    // cluster_pairs.comp's run (CLUSTER_PAIR_NARROW_TILES, EMIT_PAIRS, CLUSTER_MASKS).
    std::optional<PairRun> pairRun{};
    std::optional<SortPass> sortPass{};  // pair_sort.comp (PAIR_SORT_CHUNK, PAIR_SORT_RADIX, ...)
    std::optional<ScanStep> scanStep{};  // scan.comp (SCAN_STEP, SCAN_BLOCK)

    auto operator<=>(const CullingVariant&) const = default;

    // `defines` plus this variant's.
    gl::Defines toDefines(gl::Defines defines = {}) const;
};

}  // namespace manylights
