#include "render/Technique.h"

#include "render/DeferredTechnique.h"
#include "render/ForwardTechnique.h"
#include "render/VolumeTechniques.h"

namespace manylights {

FrameTargets::FrameTargets(int width_, int height_)
    : width(width_),
      height(height_),
      depthStencil("depth stencil", kDepthStencilTarget.format, width_, height_),
      lit("lit colour", GL_RGBA32F, width_, height_),
      litFramebuffer("lit", {&lit}, &depthStencil),
      gbuffer(width_, height_, depthStencil)
{
}

const std::vector<std::string>& techniqueNames()
{
    static const std::vector<std::string> names = {"forward", "deferred", "volumes", "stencil"};
    return names;
}

std::unique_ptr<Technique> makeTechnique(std::string_view name)
{
    if (name == "forward")
        return std::make_unique<ForwardTechnique>();
    if (name == "deferred")
        return std::make_unique<DeferredTechnique>();
    if (name == "volumes")
        return std::make_unique<VolumesTechnique>();
    if (name == "stencil")
        return std::make_unique<StencilTechnique>();
    return nullptr;
}

}  // namespace manylights
