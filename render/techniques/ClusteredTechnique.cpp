#include "render/techniques/ClusteredTechnique.h"

#include "render/frame/ScreenPasses.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

LightingProgram clusteredLighting(const TechniqueOptions& options, bool listTexels, bool globalList)
{
    return LightingProgram(
        "clustered lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
        clusterListDefines(clusterGridDefines(shaderDefines(options), kClusteredGridShape), listTexels, globalList));
}

}  // namespace

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.gbufferLayout, kClusteredGridShape),
      lists_(kClusteredGridShape, shaderDefines(options), options.culling),
      lighting_{{clusteredLighting(options, false, false), clusteredLighting(options, false, true)},
                {clusteredLighting(options, true, false), clusteredLighting(options, true, true)}}
{
    if (options.lightingStage == LightingStage::Compute)
        computeLighting_.emplace("clustered compute lighting", shaderDefines(options), kClusteredGridShape);
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const { return lists_.counters(grid_); }

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    buildListsOverSurfaces(scene, targets, passes, grid_, lists_);
    if (computeLighting_) {
        computeLighting_->run(scene, grid_, lists_, passes);
        lists_.lightLongLists(scene, grid_, passes);
        return;
    }
    const auto lightCount = static_cast<std::uint32_t>(scene.lightCount());
    // Lists name lights by index, so the lights are read by index.
    const LightSource source = scene.indexedLightSource();
    const LightBatch allLights{0, lightCount};
    const gl::Program& program = lighting_[lists_.readsTexels() ? 1 : 0][lists_.hasGlobalList() ? 1 : 0].variant(
        scene.lightingFeatures(), source);
    Pass lighting = lightBatchPass(allLights, Resource::LightGrid);
    // The lists may be read as texels (GL_TEXTURE_FETCH_BARRIER_BIT after the list passes'
    // storage writes, not only GL_SHADER_STORAGE_BARRIER_BIT).
    lighting.sampled = lighting.sampled | Resource::LightGrid;
    passes.run(lighting, [&] {
        scene.bindLightSource(source, allLights);
        grid_.bind();
        lists_.bind();
        drawCoveredPixels(program);
    });
    lists_.lightLongLists(scene, grid_, passes);
}

}  // namespace manylights
