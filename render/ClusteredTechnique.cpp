#include "render/ClusteredTechnique.h"

#include "render/GpuScene.h"
#include "render/ScreenPasses.h"

namespace manylights {

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.gbufferLayout),
      lighting_("clustered lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
                clusterGridDefines(shaderDefines(options)))
{
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const
{
    return {{"clusters", static_cast<double>(grid_.clusterCount())},
            {"light_batches", static_cast<double>(batchCount_)}};
}

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    const std::vector<LightBatch> batches = lightBatches(static_cast<std::uint32_t>(scene.lightCount()),
                                                         ClusterGrid::lightsPerBatch(targets.width, targets.height));
    batchCount_ = static_cast<std::uint32_t>(batches.size());
    passes.run(ClusterGrid::fitPass(), [&] {
        grid_.resize(targets.width, targets.height, batches.front().size());
        grid_.fitToSurfaces();
    });
    const LightSource source = fitsOneLightWindow(batches) ? scene.walkedLightSource() : scene.indexedLightSource();
    const gl::Program& program = lighting_.variant(scene.lightingFeatures(), source);
    for (const LightBatch& batch : batches) {
        passes.run(ClusterGrid::assignPass("clusters"), [&] { grid_.assignLights(batch); });
        passes.run(lightBatchPass(batch, Resource::LightGrid), [&] {
            scene.bindLightSource(source, batch);
            grid_.bind();
            setLightBatch(program, batch);
            drawCoveredPixels(program);
        });
    }
}

}  // namespace manylights
