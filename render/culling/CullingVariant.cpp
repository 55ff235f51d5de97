#include "render/culling/CullingVariant.h"

#include <string>

#include "core/Error.h"
#include "render/culling/ClusterLists.h"
#include "render/culling/GpuScan.h"
#include "render/culling/LightTiles.h"

namespace manylights {

gl::Defines CullingVariant::toDefines(gl::Defines defines) const
{
    if (lightTiles)
        defines.emplace_back("LIGHT_TILE_LANES", std::to_string(kLightTileLanes));
    if (grid) {
        ML_ASSERT(grid->tileSize >= 4 && grid->tileSize <= 32);
        defines.emplace_back("CLUSTER_TILE_SIZE", std::to_string(grid->tileSize));
        ML_ASSERT(grid->slices >= 1 && grid->slices <= 32);
        defines.emplace_back("CLUSTER_SLICES", std::to_string(grid->slices));
        if (grid->surfaceBounds)
            defines.emplace_back("CLUSTER_SURFACE_BOUNDS", "1");
    }
    if (gridTexels)
        defines.emplace_back("CLUSTER_GRID_TEXELS", "1");
    if (lightLists)
        defines.emplace_back("CLUSTER_LIST_PART", std::to_string(kClusterListPart));
    if (lightLists || globalLights)
        defines.emplace_back("GLOBAL_LIGHT_CAPACITY", std::to_string(kGlobalLightCapacity));
    if (pairRun) {
        // The narrow lights set their bits as they are counted; the wide lights in a run after.
        const bool emit = *pairRun == PairRun::Write || (*pairRun == PairRun::Mask && lightTiles);
        defines.emplace_back("CLUSTER_PAIR_NARROW_TILES", std::to_string(kNarrowLightTiles));
        defines.emplace_back("EMIT_PAIRS", emit ? "1" : "0");
        if (lightTiles)
            defines.emplace_back("WIDE_LIGHTS", "1");
        if (*pairRun == PairRun::Mask)
            defines.emplace_back("CLUSTER_MASKS", "1");
    }
    if (sortPass) {
        defines.emplace_back("PAIR_SORT_CHUNK", std::to_string(kSortChunk));
        defines.emplace_back("PAIR_SORT_RADIX", std::to_string(1 << kSortRadixBits));
        if (*sortPass != SortPass::Count)
            defines.emplace_back("PAIR_SORT_SCATTER", "1");
        if (*sortPass == SortPass::ScatterGather)
            defines.emplace_back("PAIR_SORT_GATHER", "1");
    }
    if (scanStep) {
        defines.emplace_back("SCAN_STEP", std::to_string(static_cast<int>(*scanStep)));
        defines.emplace_back("SCAN_BLOCK", std::to_string(kScanBlock));
    }
    return defines;
}

}  // namespace manylights
