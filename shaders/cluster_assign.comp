#version 450 core
// The transparency grid, once per light batch: the lights' bits in the masks of the clusters
// they reach. One workgroup per (light, band of rows of tiles), its invocations sharing out the
// tiles the light's bounding sphere covers on screen (lib/light_tiles.glsl), each testing, in
// its tiles, the occupied slices within the sphere's depth span whose box the sphere (and a
// spot's cone) reaches. Loop iterations per invocation: at most 1,024 tiles (the bands of
// lib/light_tiles.glsl) times CLUSTER_SLICES + 1, about 9,200, within the bound of
// render/programs/LightBatches.h.
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"
#include "lib/cluster_culling.glsl"
#include "lib/light_tiles.glsl"

// Sets the light's bit (`word`, `wordBit` of the batch's masks) in every occupied cluster
// of `tile` that the light may reach.
void addLightToTile(ViewLight light, uint tile, uint word, uint wordBit)
{
    uint slices = lightSlicesOfTile(light, tile);
    uint words = lightBatchMaskWords();
    while (slices != 0u) {
        uint k = uint(findLSB(slices));
        slices &= slices - 1u;
        setClusterMaskBit(tile * uint(CLUSTER_SLICES) + k, words, word, wordBit, true);
    }
}

void main()
{
    uint bit = gl_WorkGroupID.x;
    uint lightIndex = lightBatch.x + bit;
    if (lightIndex >= lightBatch.y)
        return;
    ViewLight light = viewLight(lights[lightIndex]);
    if (light.radius <= 0.0)
        return;
    uvec2 grid = clusterTileGrid();
    LightTileRun run;
    if (!lightTileRun(light.centre, light.radius, light.unbounded, uint(CLUSTER_TILE_SIZE), grid, run))
        return;
    for (uint i = gl_LocalInvocationID.x; i < run.tiles; i += uint(LIGHT_TILE_LANES))
        addLightToTile(light, tileOfRun(run, i, grid.x), bit / 32u, 1u << (bit % 32u));
}
