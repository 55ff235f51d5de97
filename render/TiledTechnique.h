// tiled: compute-shader tiled deferred shading (Lauritzen, SIGGRAPH 2010). One workgroup
// per 16x16-pixel tile culls all lights against the tile's depth-bounded frustum into a
// shared-memory list, then shades the tile's pixels with it. A list holds TILE_CAPACITY
// lights; a tile reached by more evaluates every light instead (correct, slow) and is
// counted in the statistics, so no light is ever dropped.
#pragma once

#include <cstdint>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

namespace manylights {

inline constexpr int kTiledTileSize = 16;
inline constexpr int kTiledTileCapacity = 1024;

class TiledTechnique : public Technique {
public:
    explicit TiledTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled"; }
    void render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler) override;
    std::vector<TechniqueCounter> counters() const override;

private:
    LightingProgram program_;
    gl::Buffer statistics_;
    std::uint32_t lastOverflowedTiles_ = 0;
};

}  // namespace manylights
