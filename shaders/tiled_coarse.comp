#version 450 core
// tiled, once per light batch before tiled.comp: each light's bit in the masks of the coarse
// tiles (lib/coarse_tiles.glsl) that its bounding sphere's screen rectangle meets. No depth
// test here: the surfaces' depths are known per tile only in tiled.comp, which tests the
// lights a coarse tile lists against each of its tiles' depth-bounded frustums. One workgroup
// per (light, band of rows of coarse tiles), sharing out the light's tiles
// (lib/light_tiles.glsl): at most 1,024 loop iterations per invocation.
#include "lib/bindings.glsl"
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/light_batch.glsl"
#include "lib/coarse_tiles.glsl"
#include "lib/culling.glsl"
#include "lib/light_tiles.glsl"

void main()
{
    uint bit = gl_WorkGroupID.x;
    uint lightIndex = lightBatch.x + bit;
    if (lightIndex >= lightBatch.y)
        return;
    vec4 positionRadius = lights[lightIndex].positionRadius;
    float radius = positionRadius.w;
    if (radius <= 0.0)
        return;
    vec3 centre = (frame.view * vec4(positionRadius.xyz, 1.0)).xyz;
    uvec2 grid = coarseTileGrid();
    LightTileRun run;
    if (!lightTileRun(centre, radius, radius >= UNBOUNDED_RADIUS, coarseTileSize, grid, run))
        return;
    uint word = bit / 32u;
    uint wordBit = 1u << (bit % 32u);
    uint words = lightBatchMaskWords();
    for (uint i = gl_LocalInvocationID.x; i < run.tiles; i += uint(LIGHT_TILE_LANES))
        atomicOr(coarseTileMasks[tileOfRun(run, i, grid.x) * words + word], wordBit);
}
