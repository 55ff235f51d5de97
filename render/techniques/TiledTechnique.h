// tiled: compute-shader tiled deferred shading (Lauritzen, SIGGRAPH 2010), on per-tile light
// lists. Each frame the G-buffer's 8x8-pixel tiles are fitted to their surfaces (the box
// around each tile's surfaces: Lauritzen's per-tile depth bounds, tightened to the surfaces'
// extent across the tile too), the lights that may reach each tile are listed on the GPU by
// render/culling/ClusterLists.h (a cluster grid of one slice per tile), and one compute dispatch, a
// workgroup per tile, shades each pixel with its tile's list, testing each light against the
// pixel's surface first. Lists longer than one invocation may walk are finished over their
// tiles only. The difference from clustered is the missing depth slices (a tile whose
// surfaces span a large depth range keeps every light of that range) and the compute
// shading: the two sides of the 2D-against-3D question, on one list builder.
#pragma once

#include "render/culling/ClusterGrid.h"
#include "render/culling/ClusterLists.h"
#include "render/techniques/ListLighting.h"
#include "render/techniques/Technique.h"

namespace manylights {

inline constexpr int kTiledTileSize = 8;
inline constexpr ClusterGridShape kTiledGridShape{.tileSize = kTiledTileSize, .slices = 1, .surfaceBounds = true};

class TiledTechnique : public Technique {
public:
    explicit TiledTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;
    void frameIssued() override { lists_.frameIssued(); }
    bool oldestFrameFitted() override { return lists_.oldestFrameFitted(); }
    // Those of render/culling/ClusterLists.h, clusters being the tiles.
    std::vector<TechniqueCounter> counters() const override { return lists_.counters(grid_); }

private:
    ClusterGrid grid_;
    ClusterLists lists_;
    ListLighting lighting_;  // in compute: a workgroup per tile
};

}  // namespace manylights
