#version 450 core
// tiled (Lauritzen, SIGGRAPH 2010): one workgroup per 16x16 tile. It finds the tile's
// depth range among its surfaces, culls every light against the tile's frustum cut to that
// range into a list in shared memory, and shades its pixels with that list. One dispatch per
// light batch (lib/light_batch.glsl); the later ones add to the lit image. Loop iterations
// per invocation: the culling loop (a batch / 256 ≤ 32, with the frustum's four planes), the
// sort (≤ 55 stages of ≤ 4) and the shading loop (≤ one batch): under the bound of
// render/LightBatches.h.
#define LIGHTING_IN_COMPUTE 1
#include "lib/lighting.glsl"
#include "lib/light_batch.glsl"
#include "lib/gbuffer.glsl"
#include "lib/culling.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;
// After the workgroup size, which it reads.
#include "lib/tile_depth_range.glsl"
layout(binding = 5) uniform sampler2D sceneDepth;
layout(binding = 2, rgba32f) uniform image2D litImage;
layout(std430, binding = 6) buffer TileStatistics {
    uint overflowedTiles;  // tiles whose lights did not fit TILE_CAPACITY
};

const uint THREADS = uint(TILE_SIZE * TILE_SIZE);
const uint NO_LIGHT = 0xFFFFFFFFu;

shared uint tileLightCount;
shared uint tileLights[TILE_CAPACITY];

// Sorts the shared list by light index (bitonic; the unused tail holds NO_LIGHT), so that
// every pixel adds its lights in the order forward does, whatever order the threads
// appended them in: the image is then the same on every run.
void sortTileLights(uint count)
{
    uint size = 1u;
    while (size < count)
        size <<= 1u;
    for (uint i = count + gl_LocalInvocationIndex; i < size; i += THREADS)
        tileLights[i] = NO_LIGHT;
    barrier();
    for (uint block = 2u; block <= size; block <<= 1u) {
        for (uint stride = block >> 1u; stride > 0u; stride >>= 1u) {
            for (uint i = gl_LocalInvocationIndex; i < size; i += THREADS) {
                uint partner = i ^ stride;
                if (partner > i) {
                    bool ascending = (i & block) == 0u;
                    uint a = tileLights[i];
                    uint b = tileLights[partner];
                    if ((a > b) == ascending) {
                        tileLights[i] = b;
                        tileLights[partner] = a;
                    }
                }
            }
            barrier();
        }
    }
}

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool covered = all(lessThan(pixel, ivec2(frame.viewport.xy))) && texelFetch(sceneDepth, pixel, 0).r < 1.0;
    if (gl_LocalInvocationIndex == 0u) {
        clearTileDepthRange();
        tileLightCount = 0u;
    }
    barrier();

    Surface s;
    if (covered) {
        s = gbufferSurface(pixel);
        addToTileDepthRange(viewDepth(s.position));
    }
    barrier();
    if (!tileHasSurface())
        return;

    TileFrustum frustum = workgroupTileFrustum();
    for (uint i = lightBatch.x + gl_LocalInvocationIndex; i < lightBatch.y; i += THREADS) {
        if (!lightMayReachTile(lights[i], frustum))
            continue;
        uint slot = atomicAdd(tileLightCount, 1u);
        if (slot < uint(TILE_CAPACITY))
            tileLights[slot] = i;
    }
    barrier();

    uint count = tileLightCount;
    bool overflowed = count > uint(TILE_CAPACITY);
    if (overflowed && gl_LocalInvocationIndex == 0u)
        atomicAdd(overflowedTiles, 1u);
    if (!overflowed)
        sortTileLights(count);
    if (!covered)
        return;

    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    if (overflowed) {
        // More lights reach the tile than its list holds: nothing is dropped, the tile's
        // pixels evaluate every light of the batch instead (slow, and reported in --stats).
        for (uint i = lightBatch.x; i < lightBatch.y; ++i)
            color += shadeLocal(i, s, V);
        recordLightEvaluationsAt(pixel, lightBatch.y - lightBatch.x);
    } else {
        for (uint i = 0u; i < count; ++i)
            color += shadeLocal(tileLights[i], s, V);
        recordLightEvaluationsAt(pixel, count);
    }
    if (!isFirstLightBatch())
        color += imageLoad(litImage, pixel).rgb;
    imageStore(litImage, pixel, vec4(color, 1.0));
}
