#include "render/ScreenPasses.h"

#include "render/GpuScene.h"

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

}  // namespace manylights
