#include "render/LightTiles.h"

#include <algorithm>
#include <string>

namespace manylights {

gl::Defines lightTileDefines()
{
    return {{"LIGHT_TILE_LANES", std::to_string(kLightTileLanes)},
            {"LIGHT_TILE_ROWS_PER_BAND_LOCATION", std::to_string(kRowsPerBandLocation)}};
}

void dispatchLightTiles(const gl::Program& program, const LightBatch& batch, int gridWidth, int gridHeight)
{
    const auto rowsPerBand = static_cast<std::uint32_t>(std::max(1, kTilesPerBand / gridWidth));
    const auto bands = (static_cast<std::uint32_t>(gridHeight) + rowsPerBand - 1) / rowsPerBand;
    setLightBatch(program, batch);
    program.set(kRowsPerBandLocation, rowsPerBand);
    program.use();
    glDispatchCompute(batch.size(), bands, 1);
}

}  // namespace manylights
