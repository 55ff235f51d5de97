// Full-screen passes over the pixels that hold a surface, shared by the techniques that shade
// from the G-buffer (deferred, clustered, the volumes' global terms, tiled-quads) and by the
// Renderer's views.
#pragma once

#include "gl/Program.h"
#include "render/frame/FramePasses.h"
#include "render/programs/LightBatches.h"

namespace manylights {

// Draws one triangle over the screen at depth 1 with `program` (shaders/fullscreen.vert): under
// kCoveredPixels (or kAddToCoveredPixels) the depth test GL_GREATER against the scene's depth
// passes only the pixels that hold a surface. Every full-screen pass over the G-buffer uses it.
void drawCoveredPixels(const gl::Program& program);

// The pass of a full-screen lighting program over one light batch: it reads the G-buffer and
// shades each covered pixel with the batch's lights; the first batch writes the lit image (its
// colour includes the light-independent terms), the others add to it. `storage`: what else
// the program reads (the cluster grid).
Pass lightBatchPass(const LightBatch& batch, Resource storage = Resource::None);

}  // namespace manylights
