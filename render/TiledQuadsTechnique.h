// tiled-quads: the screen cut into 32-pixel tiles, the lights culled against each tile on
// the CPU (render/TileCulling.h), and each tile drawn as one quad whose fragment shader
// loops over that tile's lights only.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/Technique.h"
#include "render/TileCulling.h"

namespace manylights {

// The shader variants: tiles are bucketed by their light count, and a tile with n lights is
// drawn by the variant with the smallest bound ≥ n (the last has no bound). Its loop then
// has a constant trip limit, which shader compilers can unroll and schedule for: the
// classic way this technique kept per-tile loops cheap on hardware with weak dynamic loops.
inline constexpr std::array<std::uint32_t, 8> kTileLightBounds = {8, 16, 32, 64, 128, 256, 512, 1024};

class TiledQuadsTechnique : public Technique {
public:
    explicit TiledQuadsTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled-quads"; }
    void render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler) override;

    // The last frame's culling result, for tests and statistics.
    const TileLightLists& lastLists() const { return culler_.lists(); }

private:
    static constexpr std::size_t kVariants = kTileLightBounds.size() + 1;

    // Culls, buckets the tiles by variant and uploads what the quads read.
    void cullAndUpload(const GpuScene& scene, const FrameTargets& targets);
    void drawTiles(const GpuScene& scene, const FrameTargets& targets) const;

    gl::Program global_;
    std::array<gl::Program, kVariants> variants_;
    TileCuller culler_;
    // The tiles to draw (those with lights), grouped by variant: variant v draws
    // drawOrder_[variantFirst_[v] .. variantFirst_[v + 1]).
    std::vector<std::uint32_t> drawOrder_;
    std::array<std::uint32_t, kVariants + 1> variantFirst_{};
    gl::Buffer tileRanges_;
    gl::Buffer tileOrder_;
    gl::Buffer lightIndices_;
};

}  // namespace manylights
