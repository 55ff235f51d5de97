#version 450 core
// Clustered, once per light batch: the lights' bits in the masks of the clusters they
// reach. One invocation per (light, band of rows of tiles): it walks the tiles of its band
// that the light's bounding sphere covers on screen and, in each, the occupied slices whose
// box the sphere (and a spot's cone) reaches. Splitting a light's work by bands keeps every
// invocation's work small and alike: a light that covers the whole screen is spread over all
// bands instead of walking every cluster on one thread. A band has rowsPerBand rows, at most
// 1,024 tiles in all (render/ClusteredTechnique.cpp), so loop iterations per invocation stay
// under (1,024 + 2 · rowsPerBand) · (CLUSTER_SLICES + 2), about 10,300, within the bound of
// render/LightBatches.h.
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"

layout(local_size_x = 64) in;
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

// Whether a light's sphere and cone can reach the view-space box lo..hi.
bool lightTouchesBox(vec3 centre, float radius, vec3 axis, float cosCutoff, vec3 lo, vec3 hi)
{
    return sphereTouchesBox(centre, radius, lo, hi) &&
           coneTouchesSphere(centre, axis, cosCutoff, 0.5 * (lo + hi), 0.5 * length(hi - lo));
}

void main()
{
    uint bit = gl_GlobalInvocationID.x;
    uint band = gl_GlobalInvocationID.y;
    uint lightIndex = lightBatch.x + bit;
    if (lightIndex >= lightBatch.y)
        return;
    GpuLight light = lights[lightIndex];
    float radius = light.positionRadius.w;
    if (radius <= 0.0)
        return;
    bool unbounded = radius >= UNBOUNDED_RADIUS;
    vec3 centre = (frame.view * vec4(light.positionRadius.xyz, 1.0)).xyz;
    vec3 axis = mat3(frame.view) * light.spotAxisCosCutoff.xyz;
    float cosCutoff = light.spotAxisCosCutoff.w;
    uvec2 grid = clusterTileGrid();
    uvec2 first = uvec2(0u);
    uvec2 last = grid - 1u;
    if (!unbounded && (-centre.z + radius < frame.projection.z || !sphereTileRect(centre, radius, grid, first, last)))
        return;
    uint firstRow = max(first.y, band * rowsPerBand);
    uint lastRow = min(last.y, band * rowsPerBand + rowsPerBand - 1u);
    if (firstRow > lastRow)
        return;

    uint words = clusterMaskWords();
    uint summaryWords = clusterSummaryWords();
    uint word = bit / 32u;
    uint wordBit = 1u << (bit % 32u);
    uint summaryBit = 1u << (word % 32u);
    for (uint row = firstRow; row <= lastRow; ++row)
    for (uint x = first.x; x <= last.x; ++x) {
        uint tile = row * grid.x + x;
        uint slices = tileOccupiedSlices[tile];
        if (slices == 0u)
            continue;
        vec2 range = tileDepthRange[tile];
        if (!unbounded) {
            vec3 lo;
            vec3 hi;
            tileFrustumBox(tile, range.x, range.y, lo, hi);
            if (!lightTouchesBox(centre, radius, axis, cosCutoff, lo, hi))
                continue;
        }
        while (slices != 0u) {
            uint k = uint(findLSB(slices));
            slices &= slices - 1u;
            if (!unbounded) {
                vec3 lo;
                vec3 hi;
                clusterBox(tile, range, k, lo, hi);
                if (!lightTouchesBox(centre, radius, axis, cosCutoff, lo, hi))
                    continue;
            }
            uint cluster = tile * uint(CLUSTER_SLICES) + k;
            // The first bit set in a word marks the word in the summary.
            if (atomicOr(clusterLightMasks[cluster * words + word], wordBit) == 0u)
                atomicOr(clusterMaskSummaries[cluster * summaryWords + word / 32u], summaryBit);
        }
    }
}
