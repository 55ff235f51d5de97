#include "render/TiledTechnique.h"
#include "render/Bindings.h"

#include <string>
#include <vector>

#include "render/GpuScene.h"
#include "render/LightBatches.h"
#include "render/PassProfiler.h"

namespace manylights {

namespace {
// Bindings of shaders/tiled.comp.
constexpr GLuint kLitImageUnit = bindings::LIT_IMAGE_UNIT;
constexpr GLuint kDepthUnit = bindings::SCENE_DEPTH_UNIT;

gl::Defines tiledDefines(const TechniqueOptions& options)
{
    gl::Defines defines = shaderDefines(options);
    defines.emplace_back("TILE_SIZE", std::to_string(kTiledTileSize));
    defines.emplace_back("LIGHTS_PER_BATCH", std::to_string(kLightsPerBatch));
    return defines;
}
}  // namespace

TiledTechnique::TiledTechnique(const TechniqueOptions& options)
    : Technique(options),
      program_("tiled lighting", {{GL_COMPUTE_SHADER, "tiled.comp"}}, tiledDefines(options)),
      lightWindows_(lightWindowsSupported())
{
}

void TiledTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    targets.gbuffer.fill(scene, profiler);
    auto pass = profiler.pass("lighting");
    scene.bind();
    targets.gbuffer.bindForReading();
    targets.depthStencil.bindUnit(kDepthUnit);
    // Make the lit image's clear to the background visible to the image stores' neighbours.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindImageTexture(kLitImageUnit, targets.lit.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    const std::vector<LightBatch> batches = lightBatches(static_cast<std::uint32_t>(scene.lightCount()));
    const bool oneWindow = lightWindows_ && fitsOneLightWindow(batches);
    if (oneWindow)
        scene.bindLightWindow(batches.front());
    const gl::Program& program =
        program_.variant(scene.lightingFeatures(), oneWindow ? LightSource::UniformWindow : LightSource::StorageBuffer);
    program.use();
    const auto groups = [](int pixels) { return static_cast<GLuint>((pixels + kTiledTileSize - 1) / kTiledTileSize); };
    for (const LightBatch& batch : batches) {
        // Each batch after the first adds to what the one before it stored.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        setLightBatch(program, batch);
        glDispatchCompute(groups(targets.width), groups(targets.height), 1);
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace manylights
