// Full-screen passes over the pixels that hold a surface, shared by the techniques that shade
// from the G-buffer (deferred, clustered, the volumes' global terms, tiled-quads) and by the
// Renderer's views.
#pragma once

#include "gl/Program.h"
#include "render/FrameTargets.h"
#include "render/LightBatches.h"

namespace manylights {

class GpuScene;

// Draws one triangle over the screen at depth 1 with the depth test GL_GREATER against the
// scene's depth, so only pixels holding a surface run `program` (shaders/fullscreen.vert).
// Used by every full-screen pass over the G-buffer.
void drawCoveredPixels(const gl::Program& program);

// A full-screen lighting pass over one light batch: `program` reads the G-buffer and shades
// each covered pixel with the batch's lights; the first batch writes the lit image (its
// colour includes the light-independent terms), the others add to it (deferred and clustered
// end with it).
void shadeCoveredPixels(const GpuScene& scene, FrameTargets& targets, const gl::Program& program,
                        const LightBatch& batch);

// Sets up adding to the lit image over covered pixels only: additive blending, and the
// depth test GL_GREATER against the scene's depth for geometry at depth 1, no depth writes.
void beginAddingToCoveredPixels();

}  // namespace manylights
