#include "render/techniques/TiledTechnique.h"

#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

LightingProgram tiledLighting(const TechniqueOptions& options, bool listTexels, bool globalList)
{
    gl::Defines defines =
        clusterListDefines(clusterGridDefines(shaderDefines(options), kTiledGridShape), listTexels, globalList);
    defines.emplace_back("EVERY_TILE", "1");
    return LightingProgram("tiled lighting", {{GL_COMPUTE_SHADER, "list_lighting.comp"}}, std::move(defines));
}

}  // namespace

TiledTechnique::TiledTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.gbufferLayout, kTiledGridShape),
      lists_(kTiledGridShape, shaderDefines(options)),
      lighting_{{tiledLighting(options, false, false), tiledLighting(options, false, true)},
                {tiledLighting(options, true, false), tiledLighting(options, true, true)}}
{
}

void TiledTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    buildListsOverSurfaces(scene, targets, passes, grid_, lists_);
    const gl::Program& program = lighting_[lists_.readsTexels() ? 1 : 0][lists_.hasGlobalList() ? 1 : 0].variant(
        scene.lightingFeatures(), scene.indexedLightSource());
    passes.run({.name = "lighting",
                // The lists may be read as texels: fetches wait on the list passes' writes too.
                .sampled = Resource::GBuffer | Resource::LightGrid,
                .images = Resource::LitImage,
                .storage = Resource::LightGrid,
                .writes = Resource::LitImage},
               [&] {
                   grid_.bind();
                   lists_.bind();
                   program.set(kClusterListPartLocation, 0u);
                   program.use();
                   glDispatchCompute(static_cast<GLuint>(grid_.gridWidth()), static_cast<GLuint>(grid_.gridHeight()),
                                     1);
               });
    lists_.lightLongLists(scene, grid_, passes);
}

}  // namespace manylights
