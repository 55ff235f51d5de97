#version 450 core
// Clustered, once per light batch: the lights' bits in the masks of the clusters they
// reach. One workgroup per (light, band of rows of tiles): its invocations share out the
// tiles of the band that the light's bounding sphere covers on screen (tile i to invocation
// i % CLUSTER_ASSIGN_LANES) and test, in each, the occupied slices within the sphere's depth
// span whose box the sphere (and a spot's cone) reaches.
//
// A workgroup per light rather than an invocation per light: llvmpipe runs 8 invocations in
// lock step, and 8 lights on them walked as many tiles as the largest of the 8 covers; the
// tiles of one light keep every lane busy but the last round's. Courtyard, 4096 lights,
// 1280x720: 23 -> 15 ms (docs/performance.md). A band has rowsPerBand rows, at most
// kTilesPerBand tiles (render/ClusterGrid.cpp), so loop iterations per invocation stay under
// kTilesPerBand / CLUSTER_ASSIGN_LANES · (CLUSTER_SLICES + 1), about 9,200, within the bound
// of render/LightBatches.h.
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"

layout(local_size_x = CLUSTER_ASSIGN_LANES) in;
layout(location = 0) uniform uint rowsPerBand;

// The tile rectangle (first.xy, last.xy inclusive) a sphere in view space covers on screen.
// A sphere wholly beyond the near plane projects inside the projection of its bounding
// box's corners; one reaching the eye plane may cover any tile. False when it is off screen.
bool sphereTileRect(vec3 centre, float radius, uvec2 grid, out uvec2 first, out uvec2 last)
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
    first = min(uvec2(pixelLo) / uint(CLUSTER_TILE_SIZE), grid - 1u);
    last = min(uvec2(pixelHi) / uint(CLUSTER_TILE_SIZE), grid - 1u);
    return true;
}

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
    // its radius in depth too (courtyard, as above: 15 -> 12 ms, fewer box tests). The lighting pass computes a surface's slice in another
    // program, whose rounding may differ: a hundredth of a slice either way, as
    // cluster_tiles.comp allows for.
    if (!light.unbounded) {
        float viewDepth = -light.centre.z;
        uint kLo = uint(clamp(floor(sliceCoordinate(viewDepth - light.radius, range) - 0.01), 0.0,
                              float(CLUSTER_SLICES - 1)));
        uint kHi = uint(clamp(floor(sliceCoordinate(viewDepth + light.radius, range) + 0.01), 0.0,
                              float(CLUSTER_SLICES - 1)));
        slices &= (0xffffffffu >> (31u - kHi)) & ~((1u << kLo) - 1u);
    }
    uint words = clusterMaskWords();
    uint summaryWords = clusterSummaryWords();
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
    uint band = gl_WorkGroupID.y;
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
    uvec2 first = uvec2(0u);
    uvec2 last = grid - 1u;
    if (!light.unbounded && (-light.centre.z + light.radius < frame.projection.z ||
                             !sphereTileRect(light.centre, light.radius, grid, first, last)))
        return;
    // This band's rows of the light's tile rectangle, walked as one run of tiles.
    first.y = max(first.y, band * rowsPerBand);
    last.y = min(last.y, band * rowsPerBand + rowsPerBand - 1u);
    if (first.y > last.y)
        return;
    uint columns = last.x - first.x + 1u;
    uint tiles = columns * (last.y - first.y + 1u);
    for (uint i = gl_LocalInvocationID.x; i < tiles; i += uint(CLUSTER_ASSIGN_LANES))
        addLightToTile(light, (first.y + i / columns) * grid.x + first.x + i % columns, bit / 32u,
                       1u << (bit % 32u));
}
