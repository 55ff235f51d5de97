#include "render/TiledTechnique.h"
#include "render/Bindings.h"

#include <string>
#include <vector>

#include "render/FramePasses.h"
#include "render/GpuScene.h"
#include "render/LightBatches.h"

namespace manylights {

namespace {
gl::Defines tiledDefines(const TechniqueOptions& options)
{
    gl::Defines defines = shaderDefines(options);
    defines.emplace_back("TILE_SIZE", std::to_string(kTiledTileSize));
    defines.emplace_back("LIGHTS_PER_BATCH", std::to_string(kLightsPerBatch));
    return defines;
}
}  // namespace

TiledTechnique::TiledTechnique(const TechniqueOptions& options)
    : Technique(options), program_("tiled lighting", {{GL_COMPUTE_SHADER, "tiled.comp"}}, tiledDefines(options))
{
}

void TiledTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    const std::vector<LightBatch> batches = lightBatches(static_cast<std::uint32_t>(scene.lightCount()));
    const LightSource source = fitsOneLightWindow(batches) ? scene.walkedLightSource() : scene.indexedLightSource();
    const gl::Program& program = program_.variant(scene.lightingFeatures(), source);
    const auto groups = [](int pixels) { return static_cast<GLuint>((pixels + kTiledTileSize - 1) / kTiledTileSize); };
    // One dispatch per batch: each batch after the first loads what the one before it stored.
    for (const LightBatch& batch : batches)
        passes.run({.name = "lighting",
                    .sampled = Resource::GBuffer,
                    .images = Resource::LitImage,
                    .writes = Resource::LitImage},
                   [&] {
                       scene.bindLightSource(source, batch);
                       setLightBatch(program, batch);
                       program.use();
                       glDispatchCompute(groups(targets.width), groups(targets.height), 1);
                   });
}

}  // namespace manylights
