// The screen tiles a light's bounding sphere covers, for the passes that set each light's bit
// in per-tile masks (cluster_assign.comp, tiled_coarse.comp): one workgroup of
// LIGHT_TILE_LANES invocations per (light, band of rows of tiles), its invocations sharing
// out the light's tiles in the band (tile i of the run to invocation i % LIGHT_TILE_LANES).
//
// A workgroup per light rather than an invocation per light: llvmpipe runs 8 invocations in
// lock step, and 8 lights on them walked as many tiles as the largest of the 8 covers; the
// tiles of one light keep every lane busy but the last round's (courtyard, 4096 lights,
// 1280x720, the cluster assignment: 23 -> 15 ms, docs/performance.md). Bands bound the walk:
// a band has rowsPerBand rows, at most kTilesPerBand tiles (render/LightTiles.h), so each
// invocation visits at most kTilesPerBand / LIGHT_TILE_LANES = 1,024 tiles, whatever the
// image size. Needs lib/frame.glsl first.
layout(local_size_x = LIGHT_TILE_LANES) in;
layout(location = LIGHT_TILE_ROWS_PER_BAND_LOCATION) uniform uint rowsPerBand;

// The rectangle of tiles (first.xy, last.xy inclusive, in a grid of `grid` tiles of
// `tileSize` pixels) that a sphere in view space covers on screen. A sphere wholly beyond the
// near plane projects inside the projection of its bounding box's corners; one reaching the
// eye plane may cover any tile. False when it is off screen.
bool sphereTileRect(vec3 centre, float radius, uint tileSize, uvec2 grid, out uvec2 first, out uvec2 last)
{
    first = uvec2(0u);
    last = grid - 1u;
    if (-centre.z - radius <= frame.projection.z)
        return true;
    vec2 ndcLo = vec2(1e30);
    vec2 ndcHi = vec2(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
        vec3 p = centre + radius * vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0,
                                        (corner & 4) != 0 ? 1.0 : -1.0);
        vec2 ndc = p.xy / (-p.z * frame.projection.xy);
        ndcLo = min(ndcLo, ndc);
        ndcHi = max(ndcHi, ndc);
    }
    if (any(greaterThan(ndcLo, vec2(1.0))) || any(lessThan(ndcHi, vec2(-1.0))))
        return false;
    vec2 pixelLo = (clamp(ndcLo, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
    vec2 pixelHi = (clamp(ndcHi, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
    first = min(uvec2(pixelLo) / tileSize, grid - 1u);
    last = min(uvec2(pixelHi) / tileSize, grid - 1u);
    return true;
}

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
