#version 450 core
// in_range_pairs (docs/cli.md): for every pixel holding a surface, how many lights reach it
// (A·S > 0). The least work any technique can do; a technique's culling efficiency is this
// over its light evaluations.
//
// Exact per pixel, culled per tile: one workgroup per 16x16 tile marks, in a bit mask of
// the light batch, the lights that may reach the tile's frustum cut to its surfaces' depth
// range (the conservative test of lib/culling.glsl), and each pixel counts the marked lights
// that reach it with the lighting function's own test. BRUTE_FORCE marks every light, for
// the test that checks the culling against counting every pair. One dispatch per light
// batch, adding to the counts. Loop iterations: ≤ 2 to clear the mask, ≤ 33 to cull, and
// ≤ 2 · 257 + one batch to count: under the bound of render/programs/LightBatches.h.
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/lighting.glsl"
#include "lib/light_batch.glsl"
#include "lib/gbuffer.glsl"
#include "lib/culling.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
// After the workgroup size, which it reads.
#include "lib/tile_depth_range.glsl"
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = IN_RANGE_COUNTS_IMAGE_UNIT, r32ui) uniform uimage2D inRangeCounts;

const uint THREADS = 256u;

shared uint candidates[LIGHTS_PER_BATCH / 32];

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(pixel, imageSize(inRangeCounts)));
    bool covered = inside && texelFetch(sceneDepth, pixel, 0).r < 1.0;
    uint words = lightBatchMaskWords();
    for (uint w = gl_LocalInvocationIndex; w < words; w += THREADS)
        candidates[w] = 0u;
    if (gl_LocalInvocationIndex == 0u)
        clearTileDepthRange();
    barrier();
    vec3 position = vec3(0.0);
    if (covered) {
        position = gbufferPosition(pixel);
        addToTileDepthRange(viewDepth(position));
    }
    barrier();
    if (tileHasSurface()) {
        TileFrustum frustum = workgroupTileFrustum();
        for (uint i = lightBatch.x + gl_LocalInvocationIndex; i < lightBatch.y; i += THREADS) {
#ifndef BRUTE_FORCE
            if (!lightMayReachTile(lights[i], frustum))
                continue;
#endif
            uint bit = i - lightBatch.x;
            atomicOr(candidates[bit / 32u], 1u << (bit % 32u));
        }
    }
    barrier();
    if (!inside)
        return;
    uint count = 0u;
    if (covered) {
        for (uint w = 0u; w < words; ++w) {
            uint bits = candidates[w];
            while (bits != 0u) {
                uint bit = uint(findLSB(bits));
                bits &= bits - 1u;
                if (lightReach(lights[lightBatch.x + w * 32u + bit], position).w > 0.0)
                    ++count;
            }
        }
    }
    if (!isFirstLightBatch())
        count += imageLoad(inRangeCounts, pixel).r;
    imageStore(inRangeCounts, pixel, uvec4(count));
}
