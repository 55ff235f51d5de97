#include "render/DeferredTechnique.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"
#include "render/ScreenPasses.h"

namespace manylights {

DeferredTechnique::DeferredTechnique(const TechniqueOptions& options)
    : Technique(options),
      lightWindows_(lightWindowsSupported()),
      lighting_("deferred lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred.frag"}},
                shaderDefines(options))
{
}

void DeferredTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    targets.gbuffer.fill(scene, profiler);
    auto pass = profiler.pass("lighting");
    const gl::Program& program = lighting_.variant(
        scene.lightingFeatures(), lightWindows_ ? LightSource::UniformWindow : LightSource::StorageBuffer);
    const std::uint32_t perBatch = lightWindows_ ? kLightsPerWindow : kLightsPerBatch;
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount()), perBatch)) {
        if (lightWindows_)
            scene.bindLightWindow(batch);
        shadeCoveredPixels(scene, targets, program, batch);
    }
}

}  // namespace manylights
