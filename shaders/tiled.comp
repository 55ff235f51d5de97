#version 450 core
// tiled (Lauritzen, SIGGRAPH 2010): one workgroup per 8x8 tile. It finds the tile's
// depth range among its surfaces, culls the lights of the batch against the tile's frustum
// cut to that range into a bit mask in shared memory (bit i: light lightBatch.x + i may reach
// the tile), and shades its pixels by walking the mask. A mask rather than a list: it needs
// no count, no capacity (a bit for every light of a batch: nothing can overflow) and no sort
// (a pixel walks its lights in index order, the order forward adds them in, so the image is
// the same on every run). One dispatch per light batch (lib/light_batch.glsl); the later
// ones add to the lit image.
//
// The culling tests only the lights its coarse tile lists (lib/coarse_tiles.glsl, set by
// tiled_coarse.comp from each light's screen rectangle), not every light of the batch: with
// thousands of small lights a tile's workgroup spent more on testing them all than on
// shading (courtyard, 4096 lights, 1280x720: ~100 of 300 ms, docs/performance.md).
//
// 8x8 tiles rather than Lauritzen's 16x16: the lists fit their pixels better, and with the
// coarse tiles the culling of four times the tiles costs less than the shading it saves
// (courtyard, 4096 lights: frame 231-232 -> 209-211 ms; LearnOpenGL's scene no slower).
//
// Loop iterations per invocation: the culling walk (mask words of the coarse tile's, a batch
// / 32 / 64 ≤ 4, each with its ≤ 32 bits and the frustum's four planes) and the shading walk
// (one per mask word and one per light of the batch): under the bound of
// render/LightBatches.h.
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/culling.glsl"
#include "lib/coarse_tiles.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;
// After the workgroup size, which it reads.
#include "lib/tile_depth_range.glsl"
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = LIT_IMAGE_UNIT, rgba32f) uniform image2D litImage;

const uint THREADS = uint(TILE_SIZE * TILE_SIZE);
const uint MASK_WORDS = uint(LIGHTS_PER_BATCH / 32);
const uint SUMMARY_WORDS = (MASK_WORDS + 31u) / 32u;

shared uint tileLightMask[MASK_WORDS];
shared uint tileMaskSummary[SUMMARY_WORDS];  // bit w % 32 of word w / 32: mask word w is not empty

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool covered = all(lessThan(pixel, ivec2(frame.viewport.xy))) && texelFetch(sceneDepth, pixel, 0).r < 1.0;
    // Only the summary is cleared: the shading walks the mask words it marks, each written
    // whole by the invocation that culled it.
    if (gl_LocalInvocationIndex == 0u)
        clearTileDepthRange();
    if (gl_LocalInvocationIndex < SUMMARY_WORDS)
        tileMaskSummary[gl_LocalInvocationIndex] = 0u;
    barrier();

    Surface s;
    if (covered) {
        s = gbufferSurface(pixel);
        addToTileDepthRange(viewDepth(s.position));
    }
    barrier();
    if (!tileHasSurface())
        return;

    // Each invocation culls the candidates of whole mask words, so it owns the words it
    // writes: no atomics but the summary's.
    TileFrustum frustum = workgroupTileFrustum();
    uvec2 coarseTile = gl_WorkGroupID.xy * gl_WorkGroupSize.xy / coarseTileSize;
    uint words = lightBatchMaskWords();
    uint coarseMasks = (coarseTile.y * coarseTileGrid().x + coarseTile.x) * words;
    for (uint w = gl_LocalInvocationIndex; w < words; w += THREADS) {
        uint candidates = coarseTileMasks[coarseMasks + w];
        uint reaching = 0u;
        while (candidates != 0u) {
            uint bit = uint(findLSB(candidates));
            candidates &= candidates - 1u;
            if (lightMayReachTile(batchLight(lightBatch.x + w * 32u + bit), frustum))
                reaching |= 1u << bit;
        }
        if (reaching != 0u) {
            tileLightMask[w] = reaching;
            atomicOr(tileMaskSummary[w / 32u], 1u << (w % 32u));
        }
    }
    barrier();
    if (!covered)
        return;

    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    uint summaryWords = lightBatchSummaryWords();
    uint evaluated = 0u;
    for (uint g = 0u; g < summaryWords; ++g) {
        uint nonEmpty = tileMaskSummary[g];
        while (nonEmpty != 0u) {
            uint word = g * 32u + uint(findLSB(nonEmpty));
            nonEmpty &= nonEmpty - 1u;
            uint bits = tileLightMask[word];
            while (bits != 0u) {
                uint bit = uint(findLSB(bits));
                bits &= bits - 1u;
                color += shadeLocal(lightBatch.x + word * 32u + bit, s, V);
                ++evaluated;
            }
        }
    }
    recordLightEvaluationsAt(pixel, evaluated);
    if (!isFirstLightBatch())
        color += imageLoad(litImage, pixel).rgb;
    imageStore(litImage, pixel, vec4(color, 1.0));
}
