#include "render/TiledTechnique.h"
#include "render/Bindings.h"

#include <string>
#include <vector>

#include "render/FramePasses.h"
#include "render/GpuScene.h"
#include "render/LightBatches.h"
#include "render/LightTiles.h"

namespace manylights {

namespace {

constexpr int kCoarseTileSizeLocation = 42;  // lib/coarse_tiles.glsl's coarseTileSize
constexpr GLuint kCoarseMasksBinding = bindings::COARSE_TILE_MASKS_BUFFER_BINDING;

gl::Defines coarseTileDefines(gl::Defines defines)
{
    defines.emplace_back("COARSE_TILE_SIZE_LOCATION", std::to_string(kCoarseTileSizeLocation));
    return defines;
}

gl::Defines coarsePassDefines()
{
    gl::Defines defines = coarseTileDefines(lightTileDefines());
    addLightBatchDefines(defines);
    return defines;
}

gl::Defines tiledDefines(const TechniqueOptions& options)
{
    gl::Defines defines = coarseTileDefines(shaderDefines(options));
    defines.emplace_back("TILE_SIZE", std::to_string(kTiledTileSize));
    defines.emplace_back("LIGHTS_PER_BATCH", std::to_string(kLightsPerBatch));
    return defines;
}

}  // namespace

int coarseTileSizeFor(int width, int height)
{
    int size = kCoarseTileSize;
    const auto maskBytes = [&] {
        return static_cast<std::size_t>(tilesAlong(width, size)) * static_cast<std::size_t>(tilesAlong(height, size)) *
               maskWordsFor(kLightsPerBatch) * sizeof(std::uint32_t);
    };
    while (maskBytes() > kCoarseMaskBudgetBytes)
        size *= 2;
    return size;
}

TiledTechnique::TiledTechnique(const TechniqueOptions& options)
    : Technique(options),
      coarse_("tiled coarse tiles", {{GL_COMPUTE_SHADER, "tiled_coarse.comp"}}, coarsePassDefines()),
      program_("tiled lighting", {{GL_COMPUTE_SHADER, "tiled.comp"}}, tiledDefines(options))
{
}

void TiledTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    const std::vector<LightBatch> batches = lightBatches(static_cast<std::uint32_t>(scene.lightCount()));
    const LightSource source = fitsOneLightWindow(batches) ? scene.walkedLightSource() : scene.indexedLightSource();
    const gl::Program& program = program_.variant(scene.lightingFeatures(), source);
    const int coarseSize = coarseTileSizeFor(targets.width, targets.height);
    const int coarseX = tilesAlong(targets.width, coarseSize);
    const int coarseY = tilesAlong(targets.height, coarseSize);
    const auto groups = [](int pixels) { return static_cast<GLuint>(tilesAlong(pixels, kTiledTileSize)); };
    for (const LightBatch& batch : batches) {
        const std::size_t maskBytes = static_cast<std::size_t>(coarseX) * static_cast<std::size_t>(coarseY) *
                                      maskWordsFor(batch.size()) * sizeof(std::uint32_t);
        passes.run({.name = "coarse tiles", .storage = Resource::LightGrid, .writes = Resource::LightGrid}, [&] {
            if (!coarseMasks_ || coarseMasks_.size() < maskBytes)
                coarseMasks_ = gl::Buffer("tiled coarse tile masks", maskBytes, nullptr, 0);
            coarseMasks_.clearToZero(maskBytes);
            coarseMasks_.bindBase(GL_SHADER_STORAGE_BUFFER, kCoarseMasksBinding);
            coarse_.set(kCoarseTileSizeLocation, static_cast<unsigned>(coarseSize));
            dispatchLightTiles(coarse_, batch, coarseX, coarseY);
        });
        // One dispatch per batch: each batch after the first loads what the one before it stored.
        passes.run({.name = "lighting",
                    .sampled = Resource::GBuffer,
                    .images = Resource::LitImage,
                    .storage = Resource::LightGrid,
                    .writes = Resource::LitImage},
                   [&] {
                       scene.bindLightSource(source, batch);
                       coarseMasks_.bindBase(GL_SHADER_STORAGE_BUFFER, kCoarseMasksBinding);
                       setLightBatch(program, batch);
                       program.set(kCoarseTileSizeLocation, static_cast<unsigned>(coarseSize));
                       program.use();
                       glDispatchCompute(groups(targets.width), groups(targets.height), 1);
                   });
    }
}

}  // namespace manylights
