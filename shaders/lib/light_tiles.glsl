// The screen tiles a light's bounding sphere covers, for the passes that give a light to
// tiles a workgroup per light (cluster_assign.comp, cluster_pairs.comp's wide lights): one workgroup of
// LIGHT_TILE_LANES invocations per (light, band of rows of tiles), its invocations sharing
// out the light's tiles in the band (tile i of the run to invocation i % LIGHT_TILE_LANES).
//
// A workgroup per light rather than an invocation per light: llvmpipe runs 8 invocations in
// lock step, and 8 lights on them walked as many tiles as the largest of the 8 covers; the
// tiles of one light keep every lane busy but the last round's (courtyard, 4096 lights,
// 1280x720, the cluster assignment: 23 -> 15 ms, docs/performance.md). Bands bound the walk:
// a band has rowsPerBand rows, at most kTilesPerBand tiles (render/culling/LightTiles.h), so each
// invocation visits at most kTilesPerBand / LIGHT_TILE_LANES = 1,024 tiles, whatever the
// image size. Needs lib/frame.glsl and lib/culling.glsl (sphereTileRect) first.
#include "lib/locations.glsl"
layout(local_size_x = LIGHT_TILE_LANES) in;
layout(location = LIGHT_TILE_ROWS_PER_BAND_LOCATION) uniform uint rowsPerBand;

// The tiles of this workgroup's band that a light covers, row by row as one run.
struct LightTileRun {
    uvec2 first;   // the run's first tile (x, y)
    uint columns;  // tiles per row
    uint tiles;    // in all
};

// The run of this workgroup's band (gl_WorkGroupID.y) that a light covers: its sphere (view-
// space centre, radius) on screen, or every tile when it is unbounded. False when there is
// none: the sphere lies wholly before the near plane, off screen, or outside the band.
bool lightTileRun(vec3 centre, float radius, bool unbounded, uint tileSize, uvec2 grid, out LightTileRun run)
{
    uvec2 first = uvec2(0u);
    uvec2 last = grid - 1u;
    if (!unbounded &&
        (-centre.z + radius < frame.projection.z || !sphereTileRect(centre, radius, tileSize, grid, first, last)))
        return false;
    uint band = gl_WorkGroupID.y;
    first.y = max(first.y, band * rowsPerBand);
    last.y = min(last.y, band * rowsPerBand + rowsPerBand - 1u);
    if (first.y > last.y)
        return false;
    run.first = first;
    run.columns = last.x - first.x + 1u;
    run.tiles = run.columns * (last.y - first.y + 1u);
    return true;
}

// The number (row by row in a grid `gridWidth` tiles across) of the run's tile i.
uint tileOfRun(LightTileRun run, uint i, uint gridWidth)
{
    return (run.first.y + i / run.columns) * gridWidth + run.first.x + i % run.columns;
}
