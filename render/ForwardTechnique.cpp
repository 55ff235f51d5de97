// forward: the reference. Every fragment of every object loops over every light.
#include "render/ForwardTechnique.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"

namespace manylights {

ForwardTechnique::ForwardTechnique(const TechniqueOptions& options)
    : program_("forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}},
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
    scene.drawObjects(program_);
}

}  // namespace manylights
