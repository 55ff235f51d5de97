// tiled: compute-shader tiled deferred shading (Lauritzen, SIGGRAPH 2010). One workgroup
// per 8x8-pixel tile culls the lights of a batch against the tile's depth-bounded frustum
// into a bit mask in shared memory (a bit for every light of the batch, so nothing can
// overflow), then shades the tile's pixels by walking it. The lights it tests are those whose
// screen rectangle meets its coarse tile (a square of 8x8 tiles or more), which a pass per
// batch marks first: a per-light scatter, so that no workgroup tests every light of a large
// scene. A scene whose lights fit one light window (render/LightBatches.h) reads them from a
// uniform block, the others from the light texels or the storage buffer.
#pragma once

#include <cstdint>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

namespace manylights {

inline constexpr int kTiledTileSize = 8;
// The coarse tiles' side: 64 pixels, or more where their masks would exceed
// kCoarseMaskBudgetBytes (above 8192x8192 for batches of 8,192 lights).
inline constexpr int kCoarseTileSize = 64;
inline constexpr std::size_t kCoarseMaskBudgetBytes = std::size_t{16} << 20;

// The coarse tiles' side for an image of this size: kCoarseTileSize, doubled until the masks
// of a full batch fit the budget.
int coarseTileSizeFor(int width, int height);

class TiledTechnique : public Technique {
public:
    explicit TiledTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

private:
    gl::Program coarse_;
    LightingProgram program_;
    gl::Buffer coarseMasks_;
};

}  // namespace manylights
