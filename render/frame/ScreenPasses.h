// Full-screen passes over the pixels that hold a surface, shared by the techniques that shade
// from the G-buffer (deferred, clustered, the volumes' global terms, tiled-quads) and by the
// Renderer's views.
#pragma once

#include "gl/Program.h"
#include "render/driver/DriverProfile.h"
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

// The record of a lighting pass in the compute stage, from its record as a full-screen
// fragment pass (`fragment`, such as lightBatchPass gives): the same name, and what it samples
// and reads as storage; the lit image loaded and stored as an image instead of blended into
// (shaders/lib/lighting_stage.glsl), and no target.
Pass computeLightingPass(const Pass& fragment);

// The one seam of the lighting stage (--lighting-stage, issue 46): runs the lighting pass
// `fragment` with `program`, built for `stage` (a fragment shader over the covered pixels, or a
// compute shader of `groupsX` x `groupsY` workgroups over the image, whose record
// computeLightingPass makes). `bind` binds what the program reads beside the scene, before the
// draw or the dispatch.
template <typename Bind>
void runLightingPass(FramePasses& passes, LightingStage stage, const Pass& fragment, const gl::Program& program,
                     GLuint groupsX, GLuint groupsY, Bind&& bind)
{
    if (stage == LightingStage::Fragment) {
        passes.run(fragment, [&] {
            bind();
            drawCoveredPixels(program);
        });
        return;
    }
    passes.run(computeLightingPass(fragment), [&] {
        bind();
        program.use();
        glDispatchCompute(groupsX, groupsY, 1);
    });
}

}  // namespace manylights
