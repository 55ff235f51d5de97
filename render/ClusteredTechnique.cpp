#include "render/ClusteredTechnique.h"

#include "render/GpuScene.h"
#include "render/ScreenPasses.h"

namespace manylights {

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.gbufferLayout, kClusteredGridShape),
      lists_(kClusteredGridShape),
      lighting_("clustered lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
                clusterListDefines(clusterGridDefines(shaderDefines(options), kClusteredGridShape))),
      longLighting_("clustered long lists", {{GL_COMPUTE_SHADER, "clustered_long.comp"}},
                    clusterListDefines(clusterGridDefines(shaderDefines(options), kClusteredGridShape)))
{
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const
{
    return {{"clusters", static_cast<double>(grid_.clusterCount())},
            {"cluster_pairs", static_cast<double>(lists_.pairs())},
            {"longest_cluster_list", static_cast<double>(lists_.longestList())},
            {"cluster_list_visits", static_cast<double>(lists_.listVisits())},
            {"cluster_rebuilds", static_cast<double>(lists_.rebuilds())},
            {"gpu_memory_bytes", static_cast<double>(lists_.memoryBytes() + grid_.memoryBytes())}};
}

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    passes.run(ClusterGrid::fitPass(), [&] {
        grid_.resize(targets.width, targets.height, 0);
        grid_.fitToSurfaces();
    });
    const auto lightCount = static_cast<std::uint32_t>(scene.lightCount());
    lists_.build(passes, grid_, lightCount);
    // Lists name lights by index, so the lights are read by index.
    const LightSource source = scene.indexedLightSource();
    const LightBatch allLights{0, lightCount};
    const gl::Program& program = lighting_.variant(scene.lightingFeatures(), source);
    passes.run(lightBatchPass(allLights, Resource::LightGrid), [&] {
        scene.bindLightSource(source, allLights);
        grid_.bind();
        lists_.bind();
        drawCoveredPixels(program);
    });
    if (lists_.laterParts() == 0)
        return;
    const gl::Program& longProgram = longLighting_.variant(scene.lightingFeatures(), source);
    for (std::uint32_t part = 1; part <= lists_.laterParts(); ++part)
        passes.run({.name = "lighting",
                    .sampled = Resource::GBuffer,
                    .images = Resource::LitImage,
                    .storage = Resource::LightGrid,
                    .indirect = Resource::LightGrid,
                    .writes = Resource::LitImage},
                   [&] {
                       scene.bindLightSource(source, allLights);
                       grid_.bind();
                       lists_.bind();
                       longProgram.set(kClusterListPartLocation, part);
                       longProgram.use();
                       lists_.dispatchLongListTiles();
                   });
}

}  // namespace manylights
