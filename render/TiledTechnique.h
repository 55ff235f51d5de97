// tiled: compute-shader tiled deferred shading (Lauritzen, SIGGRAPH 2010). One workgroup
// per 16x16-pixel tile culls the lights of a batch against the tile's depth-bounded frustum
// into a bit mask in shared memory (a bit for every light of the batch, so nothing can
// overflow), then shades the tile's pixels by walking it. A scene whose lights fit one light
// window (render/LightBatches.h) reads them from a uniform block, the others from the
// storage buffer.
#pragma once

#include <cstdint>

#include "gl/Program.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

namespace manylights {

inline constexpr int kTiledTileSize = 16;

class TiledTechnique : public Technique {
public:
    explicit TiledTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

private:
    LightingProgram program_;
};

}  // namespace manylights
