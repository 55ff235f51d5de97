#include "render/techniques/DeferredTechnique.h"

#include "render/frame/ScreenPasses.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {
LightingProgram deferredLighting(const TechniqueOptions& options)
{
    if (options.lightingStage == LightingStage::Compute)
        return LightingProgram("deferred compute lighting", {{GL_COMPUTE_SHADER, "deferred.comp"}}, options.shaders);
    return LightingProgram("deferred lighting",
                           {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred.frag"}},
                           options.shaders);
}

// deferred.comp's workgroup.
constexpr int kComputeTile = 8;
}  // namespace

DeferredTechnique::DeferredTechnique(const TechniqueOptions& options)
    : Technique(options), lighting_(deferredLighting(options))
{
}

void DeferredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    const LightSource source = scene.walkedLightSource();
    const gl::Program& program = lighting_.variant(scene.lightingFeatures(), source);
    const auto groups = [](int pixels) { return static_cast<GLuint>((pixels + kComputeTile - 1) / kComputeTile); };
    // In the compute stage each batch reads what the one before stored (deferred.comp).
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount()), lightsPerBatch(source)))
        runLightingPass(passes, options().lightingStage, lightBatchPass(batch), program, groups(targets.width),
                        groups(targets.height), [&] {
                            scene.bindLightSource(source, batch);
                            setLightBatch(program, batch);
                        });
}

}  // namespace manylights
