#include "render/techniques/ClusteredTechnique.h"

namespace manylights {

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.shaders.gbufferLayout, kClusteredGridShape),
      lists_(kClusteredGridShape, options.culling),
      lighting_("clustered lighting", options, kClusteredGridShape, options.lightingStage)
{
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const { return lists_.counters(grid_); }

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    buildListsOverSurfaces(scene, targets, passes, grid_, lists_);
    lighting_.run(scene, grid_, lists_, passes);
}

}  // namespace manylights
