#include "render/DeferredTechnique.h"

#include "render/GpuScene.h"
#include "render/ScreenPasses.h"

namespace manylights {

DeferredTechnique::DeferredTechnique(const TechniqueOptions& options)
    : Technique(options),
      lighting_("deferred lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred.frag"}},
                shaderDefines(options))
{
}

void DeferredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    const bool windows = scene.readsLightWindows();
    const gl::Program& program =
        lighting_.variant(scene.lightingFeatures(), windows ? LightSource::UniformWindow : scene.indexedLightSource());
    const std::uint32_t perBatch = windows ? kLightsPerWindow : kLightsPerBatch;
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount()), perBatch))
        passes.run(lightBatchPass(batch), [&] {
            if (windows)
                scene.bindLightWindow(batch);
            setLightBatch(program, batch);
            drawCoveredPixels(program);
        });
}

}  // namespace manylights
