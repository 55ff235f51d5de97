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

// A full-screen lighting pass: `program` reads the G-buffer and writes each covered pixel's
// colour into the lit image (deferred and clustered end with it).
void shadeCoveredPixels(const GpuScene& scene, FrameTargets& targets, const gl::Program& program);

// Sets up adding to the lit image over covered pixels only: additive blending, and the
// depth test GL_GREATER against the scene's depth for geometry at depth 1, no depth writes.
void beginAddingToCoveredPixels();

}  // namespace manylights
