#include "render/Technique.h"

#include "render/ClusteredTechnique.h"
#include "render/DeferredTechnique.h"
#include "render/ForwardTechnique.h"
#include "render/TiledQuadsTechnique.h"
#include "render/TiledTechnique.h"
#include "render/VolumeTechniques.h"

namespace manylights {

FrameTargets::FrameTargets(int width_, int height_)
    : width(width_),
      height(height_),
      depthStencil("depth stencil", kDepthStencilTarget.format, width_, height_),
      lit("lit colour", GL_RGBA32F, width_, height_),
      litFramebuffer("lit", {&lit}, &depthStencil),
      gbuffer(width_, height_, depthStencil),
      lightEvaluations("light evaluations", GL_R32UI, width_, height_),
      inRangeCounts("in-range lights", GL_R32UI, width_, height_)
{
}

gl::Defines shaderDefines(const TechniqueOptions& options)
{
    gl::Defines defines;
    if (options.countWork)
        defines.emplace_back("COUNT_WORK", "1");
    return defines;
}

const std::vector<std::string>& techniqueNames()
{
    static const std::vector<std::string> names = {"forward", "deferred", "volumes", "stencil",
                                                   "tiled-quads", "tiled", "clustered"};
    return names;
}

std::unique_ptr<Technique> makeTechnique(std::string_view name, const TechniqueOptions& options)
{
    if (name == "forward")
        return std::make_unique<ForwardTechnique>(options);
    if (name == "deferred")
        return std::make_unique<DeferredTechnique>(options);
    if (name == "volumes")
        return std::make_unique<VolumesTechnique>(options);
    if (name == "stencil")
        return std::make_unique<StencilTechnique>(options);
    if (name == "tiled-quads")
        return std::make_unique<TiledQuadsTechnique>(options);
    if (name == "tiled")
        return std::make_unique<TiledTechnique>(options);
    if (name == "clustered")
        return std::make_unique<ClusteredTechnique>(options);
    return nullptr;
}

}  // namespace manylights
