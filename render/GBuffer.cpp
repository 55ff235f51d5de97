#include "render/GBuffer.h"
#include "render/Bindings.h"

#include "render/FramePasses.h"
#include "render/GpuScene.h"

namespace manylights {

namespace {
std::array<gl::Texture2D, kSeedGBufferTargets.size()> makeTargets(int width, int height, GBufferLayout layout)
{
    const auto& layoutTargets = gbufferColourTargets(layout);
    std::array<gl::Texture2D, kSeedGBufferTargets.size()> targets;
    for (std::size_t i = 0; i < targets.size(); ++i)
        targets[i] = gl::Texture2D(std::string("gbuffer ") + std::string(layoutTargets[i].name),
                                   layoutTargets[i].format, width, height);
    return targets;
}
}  // namespace

std::string_view gbufferLayoutName(GBufferLayout layout) { return layout == GBufferLayout::Seed ? "seed" : "compact"; }

std::optional<GBufferLayout> parseGBufferLayout(std::string_view name)
{
    if (name == "seed")
        return GBufferLayout::Seed;
    if (name == "compact")
        return GBufferLayout::Compact;
    return std::nullopt;
}

gl::Defines gbufferDefines(GBufferLayout layout, gl::Defines defines)
{
    if (layout == GBufferLayout::Compact)
        defines.emplace_back("GBUFFER_COMPACT", "1");
    return defines;
}

GBuffer::GBuffer(int width, int height, const gl::Texture2D& depthStencil, GBufferLayout layout)
    : layout_(layout),
      targets_(makeTargets(width, height, layout)),
      framebuffer_("gbuffer", {&targets_[0], &targets_[1], &targets_[2], &targets_[3], &targets_[4]}, &depthStencil),
      programs_("geometry pass", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                gbufferDefines(layout))
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
    applyPipelineState({});
    scene.bind();
    clearAndDraw(scene);
}

void GBuffer::clearAndDraw(const GpuScene& scene) const
{
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < static_cast<int>(targets_.size()); ++i)
        framebuffer_.clearColour(i, zero);
    framebuffer_.clearDepthStencil(1.0f, 0);
    // The pass evaluates no light: the variants differ only in the material's maps.
    scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
        return programs_.variant(LightingFeatures{}, LightSource::StorageBuffer, maps);
    });
}

void GBuffer::bindForReading() const
{
    // Units GBUFFER_POSITION_UNIT (0) to GBUFFER_EMISSIVE_UNIT (4), in target order.
    static_assert(bindings::GBUFFER_POSITION_UNIT == 0 && bindings::GBUFFER_EMISSIVE_UNIT == 4);
    for (std::size_t i = 0; i < targets_.size(); ++i)
        targets_[i].bindUnit(static_cast<GLuint>(bindings::GBUFFER_POSITION_UNIT + static_cast<int>(i)));
}

}  // namespace manylights
