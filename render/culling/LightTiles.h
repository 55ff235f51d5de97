// The passes that give lights to tiles a workgroup per light: the transparency grid's masks
// (render/culling/ClusterGrid.h) and the wide lights' pairs of the light lists (render/culling/ClusterLists.h).
// Their shaders include shaders/lib/light_tiles.glsl: one workgroup of kLightTileLanes
// invocations per (light, band of tile rows), the invocations sharing out the light's tiles.
#pragma once

#include <cstddef>

#include "gl/Program.h"
#include "render/programs/LightBatches.h"

namespace manylights {

// llvmpipe's lock-step width (8 with 256-bit vectors): the invocations that share one
// light's tiles. On a GPU a fraction of a warp, in passes that are small there.
inline constexpr int kLightTileLanes = 8;
// A band of tile rows has at most this many tiles, so an invocation visits at most 1,024.
inline constexpr int kTilesPerBand = 1024 * kLightTileLanes;

// The tiles of `tileSize` pixels across `pixels`, the last one cut at the image's edge.
constexpr int tilesAlong(int pixels, int tileSize) { return (pixels + tileSize - 1) / tileSize; }
// The 32-bit words of a bit mask over `lights` lights (shaders/lib/light_batch.glsl's
// lightBatchMaskWords for a batch of that many); of its summary, maskWordsFor(words).
constexpr std::size_t maskWordsFor(std::size_t lights) { return (lights + 31) / 32; }

// Runs `program` (compiled with CullingVariant::lightTiles: LIGHT_TILE_LANES; its rows per band
// are at shaders/lib/locations.glsl's LIGHT_TILE_ROWS_PER_BAND_LOCATION) for every light of `batch` over a grid of
// gridWidth x gridHeight tiles: a workgroup per light and band of rows.
void dispatchLightTiles(const gl::Program& program, const LightBatch& batch, int gridWidth, int gridHeight);

}  // namespace manylights
