#include "render/ClusteredTechnique.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"
#include "render/ScreenPasses.h"

namespace manylights {

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : Technique(options),
      grid_(options.gbufferLayout),
      lighting_("clustered lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
                clusterGridDefines(shaderDefines(options))),
      lightWindows_(lightWindowsSupported())
{
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const
{
    return {{"clusters", static_cast<double>(grid_.clusterCount())},
            {"light_batches", static_cast<double>(batchCount_)}};
}

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    targets.gbuffer.fill(scene, profiler);
    const std::vector<LightBatch> batches = lightBatches(static_cast<std::uint32_t>(scene.lightCount()),
                                                         ClusterGrid::lightsPerBatch(targets.width, targets.height));
    batchCount_ = static_cast<std::uint32_t>(batches.size());
    {
        auto pass = profiler.pass("clusters");
        grid_.resize(targets.width, targets.height, batches.front().size());
        grid_.fitToSurfaces(scene, targets);
    }
    const bool oneWindow = lightWindows_ && fitsOneLightWindow(batches);
    if (oneWindow)
        scene.bindLightWindow(batches.front());
    const gl::Program& program = lighting_.variant(scene.lightingFeatures(),
                                                   oneWindow ? LightSource::UniformWindow : LightSource::StorageBuffer);
    for (const LightBatch& batch : batches) {
        {
            auto pass = profiler.pass("clusters");
            grid_.assignLights(scene, batch);
        }
        auto pass = profiler.pass("lighting");
        grid_.bind();
        shadeCoveredPixels(scene, targets, program, batch);
    }
}

}  // namespace manylights
