#include "render/frame/GBuffer.h"
#include "render/programs/Bindings.h"

#include "render/frame/FramePasses.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {
std::vector<gl::Texture2D> makeTargets(int width, int height, GBufferLayout layout)
{
    std::vector<gl::Texture2D> targets;
    for (const GBufferTarget& target : gbufferColourTargets(layout))
        targets.emplace_back(std::string("gbuffer ") + std::string(target.name), target.format, width, height);
    return targets;
}

std::vector<const gl::Texture2D*> addressesOf(const std::vector<gl::Texture2D>& textures)
{
    std::vector<const gl::Texture2D*> addresses;
    for (const gl::Texture2D& texture : textures)
        addresses.push_back(&texture);
    return addresses;
}
}  // namespace

GBuffer::GBuffer(int width, int height, const gl::Texture2D& depthStencil, GBufferLayout layout)
    : layout_(layout),
      targets_(makeTargets(width, height, layout)),
      framebuffer_("gbuffer", addressesOf(targets_), &depthStencil),
      programs_("geometry pass", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                TechniqueVariant{.gbufferLayout = layout})
{
}

void GBuffer::fill(FramePasses& passes)
{
    if (current_)
        return;
    passes.run({.name = "geometry", .target = Resource::GBuffer}, [&] { clearAndDraw(passes.scene()); });
    current_ = true;
}

void GBuffer::fill(const GpuScene& scene) const
{
    framebuffer_.bind();
    const gl::Texture2D& target = targets_.front();  // every target has the frame's size
    applyPipelineState({}, target.width(), target.height());
    scene.bind();
    clearAndDraw(scene);
    // The draws may leave their items' culling and winding (render/scene/DrawList.h): GL's defaults
    // again for the code outside the passes that follows.
    applyPipelineState({}, target.width(), target.height());
}

void GBuffer::clearAndDraw(const GpuScene& scene) const
{
    for (int i = 0; i < static_cast<int>(targets_.size()); ++i)
        framebuffer_.clearColourToZero(i);
    framebuffer_.clearDepthStencil(1.0f, 0);
    // The pass evaluates no light: the variants differ only in the material's maps.
    scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
        return programs_.variant(LightingFeatures{}, LightSource::StorageBuffer, maps);
    });
}

void GBuffer::bindForReading() const
{
    const std::span<const GBufferTarget> layoutTargets = gbufferColourTargets(layout_);
    for (std::size_t i = 0; i < targets_.size(); ++i)
        targets_[i].bindUnit(static_cast<GLuint>(layoutTargets[i].unit));
}

}  // namespace manylights
