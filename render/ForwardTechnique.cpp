// forward: the reference. Every fragment of every object loops over every light.
#include "render/ForwardTechnique.h"

#include "render/GpuScene.h"
#include "render/LightBatches.h"
#include "render/PassProfiler.h"

namespace manylights {

ForwardTechnique::ForwardTechnique(const TechniqueOptions& options)
    : Technique(options),
      program_("forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}},
               shaderDefines(options))
{
}

void ForwardTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    auto pass = profiler.pass("forward");
    targets.litFramebuffer.clearDepthStencil(1.0f, 0);
    targets.litFramebuffer.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    scene.bind();
    // One draw of the objects per light batch. The later ones add their batch's light to the
    // fragments the first one left visible: the same program draws the same triangles, so
    // the depth test GL_EQUAL passes exactly those (GL's invariance rule).
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount()))) {
        if (!batch.isFirst()) {
            glDepthFunc(GL_EQUAL);
            glDepthMask(GL_FALSE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
        }
        scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
            const gl::Program& program = program_.variant(scene.lightingFeatures(), LightSource::StorageBuffer, maps);
            setLightBatch(program, batch);
            return program;
        });
    }
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

}  // namespace manylights
