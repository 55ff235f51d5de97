// Renders frames of one scene at one size with any technique and any view, and reads the
// result back. The CLI, the tests and (later) the viewer all drive this one class.
#pragma once

#include <memory>
#include <vector>

#include "gl/Program.h"
#include "render/GpuScene.h"
#include "render/Image.h"
#include "render/PassProfiler.h"
#include "render/Technique.h"
#include "render/Views.h"

namespace manylights {

class Renderer {
public:
    // Throws manylights::Error when the size exceeds what the GL implementation supports.
    Renderer(const Scene& scene, const std::vector<Light>& lights, int width, int height);

    // Rebuilds every size-dependent resource (the passes and programs stay).
    void resize(int width, int height);

    // One frame: `view` Final runs the technique; any other view runs the geometry pass and
    // shows that G-buffer quantity (the same for every technique). Waits for the GPU.
    FrameSample renderFrame(Technique& technique, ViewMode view);

    // The last frame's colour as linear floats, rows top to bottom.
    Image readColour() const;
    // Which pixels of the last frame hold a surface.
    std::vector<bool> readCoverage() const;

    const GpuScene& gpuScene() const { return gpuScene_; }
    int width() const { return targets_->width; }
    int height() const { return targets_->height; }

private:
    GpuScene gpuScene_;
    std::unique_ptr<FrameTargets> targets_;
    gl::Program viewProgram_;
    PassProfiler profiler_;
};

}  // namespace manylights
