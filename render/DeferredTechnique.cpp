#include "render/DeferredTechnique.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"

namespace manylights {

void drawCoveredPixels(const gl::Program& program)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

void shadeCoveredPixels(const GpuScene& scene, FrameTargets& targets, const gl::Program& program,
                        const LightBatch& batch)
{
    targets.litFramebuffer.bind();
    if (batch.isFirst())
        glDisable(GL_BLEND);
    else
        beginAddingToCoveredPixels();
    scene.bind();
    targets.gbuffer.bindForReading();
    setLightBatch(program, batch);
    drawCoveredPixels(program);
    glDisable(GL_BLEND);
}

void beginAddingToCoveredPixels()
{
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
}

DeferredTechnique::DeferredTechnique(const TechniqueOptions& options)
    : lightWindows_(lightWindowsSupported()),
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
