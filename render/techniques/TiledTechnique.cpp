#include "render/techniques/TiledTechnique.h"

#include "render/scene/GpuScene.h"

namespace manylights {

TiledTechnique::TiledTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.shaders.gbufferLayout, kTiledGridShape),
      lists_(kTiledGridShape, options.culling),
      lighting_("tiled lighting", options, kTiledGridShape, LightingStage::Compute)
{
}

void TiledTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    buildListsOverSurfaces(scene, targets, passes, grid_, lists_);
    lighting_.run(scene, grid_, lists_, passes);
}

}  // namespace manylights
