#include "render/techniques/DeferredTechnique.h"

#include "render/frame/ScreenPasses.h"
#include "render/scene/GpuScene.h"

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
    const LightSource source = scene.walkedLightSource();
    const gl::Program& program = lighting_.variant(scene.lightingFeatures(), source);
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount()), lightsPerBatch(source)))
        passes.run(lightBatchPass(batch), [&] {
            scene.bindLightSource(source, batch);
            setLightBatch(program, batch);
            drawCoveredPixels(program);
        });
}

}  // namespace manylights
