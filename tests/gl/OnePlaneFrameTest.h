// The fixture of the GL tests that run passes (render/frame/FramePasses.h): a headless context, a
// scene of one plane on the GPU, 32x32 frame targets and a profiler.
#pragma once

#include "GlContextTest.h"
#include "render/frame/FramePasses.h"
#include "render/scene/GpuScene.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {

class OnePlaneFrameTest : public GlContextTest {
protected:
    const Scene scene_ =
        parseScene(R"({"objects": [{"mesh": {"primitive": "plane", "size": [4, 4]}}]})", "<one plane>", ".");
    GpuScene gpuScene_{scene_, expandLights(scene_), resolveDriverChoices({.profile = DriverProfile::Auto})};
    FrameTargets targets_{32, 32};
    PassProfiler profiler_;
};

}  // namespace manylights
