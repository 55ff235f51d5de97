#include "render/GBuffer.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"

namespace manylights {

namespace {
std::array<gl::Texture2D, kGBufferColourTargets.size()> makeTargets(int width, int height)
{
    std::array<gl::Texture2D, kGBufferColourTargets.size()> targets;
    for (std::size_t i = 0; i < targets.size(); ++i)
        targets[i] = gl::Texture2D(std::string("gbuffer ") + std::string(kGBufferColourTargets[i].name),
                                   kGBufferColourTargets[i].format, width, height);
    return targets;
}
}  // namespace

GBuffer::GBuffer(int width, int height, const gl::Texture2D& depthStencil)
    : targets_(makeTargets(width, height)),
      framebuffer_("gbuffer", {&targets_[0], &targets_[1], &targets_[2], &targets_[3], &targets_[4]}, &depthStencil),
      program_("geometry pass", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}})
{
}

void GBuffer::fill(const GpuScene& scene, PassProfiler& profiler) const
{
    auto pass = profiler.pass("geometry");
    fill(scene);
}

void GBuffer::fill(const GpuScene& scene) const
{
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < static_cast<int>(targets_.size()); ++i)
        framebuffer_.clearColour(i, zero);
    framebuffer_.clearDepthStencil(1.0f, 0);
    framebuffer_.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    scene.bind();
    scene.drawObjects(program_);
}

void GBuffer::bindForReading() const
{
    for (std::size_t i = 0; i < targets_.size(); ++i)
        targets_[i].bindUnit(static_cast<GLuint>(i));
}

}  // namespace manylights
