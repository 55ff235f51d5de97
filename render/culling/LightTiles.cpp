#include "render/culling/LightTiles.h"

#include "core/Error.h"
#include "render/programs/Locations.h"

namespace manylights {

void dispatchLightTiles(const gl::Program& program, const LightBatch& batch, int gridWidth, int gridHeight)
{
    // A band of whole rows stays within kTilesPerBand tiles, the shaders' loop bound: a row
    // never has more (32768 pixels are 2,048 tiles of 16).
    ML_ASSERT(gridWidth >= 1 && gridWidth <= kTilesPerBand);
    const auto rowsPerBand = static_cast<std::uint32_t>(kTilesPerBand / gridWidth);
    const auto bands = (static_cast<std::uint32_t>(gridHeight) + rowsPerBand - 1) / rowsPerBand;
    setLightBatch(program, batch);
    program.set(locations::LIGHT_TILE_ROWS_PER_BAND_LOCATION, rowsPerBand);
    program.use();
    glDispatchCompute(batch.size(), bands, 1);
}

}  // namespace manylights
