#version 450 core
// Clustered, once per light batch: the lights' bits in the masks of the clusters they
// reach. One workgroup per (light, band of rows of tiles), its invocations sharing out the
// tiles the light's bounding sphere covers on screen (lib/light_tiles.glsl), each testing, in
// its tiles, the occupied slices within the sphere's depth span whose box the sphere (and a
// spot's cone) reaches. Loop iterations per invocation: at most 1,024 tiles (the bands of
// lib/light_tiles.glsl) times CLUSTER_SLICES + 1, about 9,200, within the bound of
// render/LightBatches.h.
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"
#include "lib/light_tiles.glsl"

// A light of the batch as the culling sees it, in view space.
struct ViewLight {
    vec3 centre;
    float radius;
    bool unbounded;  // reaches every surface: no test can reject it
    vec3 axis;       // a spot's unit axis
    float cosCutoff;  // a spot's cos(cutoff); -2 for point lights
};

// Whether the light's sphere and cone can reach the view-space box lo..hi.
bool lightTouchesBox(ViewLight light, vec3 lo, vec3 hi)
{
    return light.unbounded ||
           (sphereTouchesBox(light.centre, light.radius, lo, hi) &&
            coneTouchesSphere(light.centre, light.axis, light.cosCutoff, 0.5 * (lo + hi), 0.5 * length(hi - lo)));
}

// The box around slice k of a tile whose pixels are pixelLo..pixelHi and whose slices span
// `range`: the first slice reaches back to the range's start and the last on to its end.
void sliceBox(vec2 pixelLo, vec2 pixelHi, vec2 range, uint k, out vec3 lo, out vec3 hi)
{
    float logRatio = sliceLogRatio(range);
    float zNear = k == 0u ? range.x : range.x * exp(logRatio * float(k));
    float zFar = k + 1u == uint(CLUSTER_SLICES) ? range.y : min(range.x * exp(logRatio * float(k + 1u)), range.y);
    frustumSectionBox(pixelLo, pixelHi, zNear, max(zFar, zNear), lo, hi);
}

// Sets the light's bit (`word`, `wordBit` of the batch's masks) in every occupied cluster
// of `tile` that the light may reach.
void addLightToTile(ViewLight light, uint tile, uint word, uint wordBit)
{
    uint slices = tileOccupiedSlices[tile];
    if (slices == 0u)
        return;
    vec2 range = tileDepthRange[tile];
    uvec2 pixelLo;
    uvec2 pixelHi;
    clusterTilePixels(tile, pixelLo, pixelHi);
    vec3 lo;
    vec3 hi;
    // The whole tile first: most lights that reach its rectangle miss its surfaces' depths.
    frustumSectionBox(vec2(pixelLo), vec2(pixelHi), range.x, range.y, lo, hi);
    if (!lightTouchesBox(light, lo, hi))
        return;
    // Only the slices within the sphere's depth span: a surface the light reaches lies within
    // its radius in depth too (courtyard, 4096 lights: 15 -> 12 ms, fewer box tests). The
    // lighting pass computes a surface's slice in another program, whose rounding may
    // differ: a hundredth of a slice either way, as cluster_tiles.comp allows for.
    if (!light.unbounded) {
        float viewDepth = -light.centre.z;
        uint kLo = uint(clamp(floor(sliceCoordinate(viewDepth - light.radius, range) - 0.01), 0.0,
                              float(CLUSTER_SLICES - 1)));
        uint kHi = uint(clamp(floor(sliceCoordinate(viewDepth + light.radius, range) + 0.01), 0.0,
                              float(CLUSTER_SLICES - 1)));
        slices &= (0xffffffffu >> (31u - kHi)) & ~((1u << kLo) - 1u);
    }
    uint words = lightBatchMaskWords();
    uint summaryWords = lightBatchSummaryWords();
    while (slices != 0u) {
        uint k = uint(findLSB(slices));
        slices &= slices - 1u;
        sliceBox(vec2(pixelLo), vec2(pixelHi), range, k, lo, hi);
        if (!lightTouchesBox(light, lo, hi))
            continue;
        uint cluster = tile * uint(CLUSTER_SLICES) + k;
        // The first bit set in a word marks the word in the summary.
        if (atomicOr(clusterLightMasks[cluster * words + word], wordBit) == 0u)
            atomicOr(clusterMaskSummaries[cluster * summaryWords + word / 32u], 1u << (word % 32u));
    }
}

void main()
{
    uint bit = gl_WorkGroupID.x;
    uint lightIndex = lightBatch.x + bit;
    if (lightIndex >= lightBatch.y)
        return;
    GpuLight gpuLight = lights[lightIndex];
    ViewLight light;
    light.radius = gpuLight.positionRadius.w;
    if (light.radius <= 0.0)
        return;
    light.unbounded = light.radius >= UNBOUNDED_RADIUS;
    light.centre = (frame.view * vec4(gpuLight.positionRadius.xyz, 1.0)).xyz;
    light.axis = mat3(frame.view) * gpuLight.spotAxisCosCutoff.xyz;
    light.cosCutoff = gpuLight.spotAxisCosCutoff.w;
    uvec2 grid = clusterTileGrid();
    LightTileRun run;
    if (!lightTileRun(light.centre, light.radius, light.unbounded, uint(CLUSTER_TILE_SIZE), grid, run))
        return;
    for (uint i = gl_LocalInvocationID.x; i < run.tiles; i += uint(LIGHT_TILE_LANES))
        addLightToTile(light, tileOfRun(run, i, grid.x), bit / 32u, 1u << (bit % 32u));
}
