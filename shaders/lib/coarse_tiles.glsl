// tiled's coarse tiles (render/TiledTechnique.h): squares of coarseTileSize pixels, a whole
// number of tiled's tiles, each with a bit mask over the current light batch: bit i is set
// when the screen rectangle of light lightBatch.x + i's bounding sphere meets the coarse
// tile (tiled_coarse.comp sets them). tiled.comp then tests only those lights against each
// of its tiles instead of every light of the batch. Needs lib/frame.glsl and
// lib/light_batch.glsl first.
layout(std430, binding = COARSE_TILE_MASKS_BUFFER_BINDING) buffer CoarseTileMasks {
    uint coarseTileMasks[];  // coarse tile t, word w: [t * lightBatchMaskWords() + w]
};
layout(location = COARSE_TILE_SIZE_LOCATION) uniform uint coarseTileSize;  // pixels

uvec2 coarseTileGrid()
{
    return (uvec2(frame.viewport.xy) + coarseTileSize - 1u) / coarseTileSize;
}

