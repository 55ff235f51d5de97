#pragma once

#include "gl/Program.h"
#include "gl/VertexArray.h"
#include "render/Technique.h"

namespace manylights {

// deferred: the geometry pass fills the G-buffer, then one full-screen pass shades every
// covered pixel with every light.
class DeferredTechnique : public Technique {
public:
    explicit DeferredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "deferred"; }
    void render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler) override;

private:
    gl::Program lighting_;
};

// Draws one triangle over the screen at depth 1 with the depth test GL_GREATER against the
// scene's depth, so only pixels holding a surface run `program` (shaders/fullscreen.vert).
// Used by every full-screen pass over the G-buffer.
void drawCoveredPixels(const gl::Program& program);

}  // namespace manylights
