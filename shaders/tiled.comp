#version 450 core
// tiled (Lauritzen, SIGGRAPH 2010): one workgroup per 16x16 tile. It finds the tile's
// depth range among its surfaces, culls every light against the tile's frustum cut to that
// range into a list in shared memory, and shades its pixels with that list.
#define LIGHTING_IN_COMPUTE 1
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/culling.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;
layout(binding = 5) uniform sampler2D sceneDepth;
layout(binding = 2, rgba32f) uniform writeonly image2D litImage;
layout(std430, binding = 6) buffer TileStatistics {
    uint overflowedTiles;  // tiles whose lights did not fit TILE_CAPACITY
};

const uint THREADS = uint(TILE_SIZE * TILE_SIZE);
const uint NO_LIGHT = 0xFFFFFFFFu;

shared uint tileDepthMin;  // float bits: positive floats order like their bits
shared uint tileDepthMax;
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
        tileDepthMin = floatBitsToUint(3.0e38);
        tileDepthMax = 0u;
        tileLightCount = 0u;
    }
    barrier();

    Surface s;
    if (covered) {
        s = gbufferSurface(pixel);
        uint depthBits = floatBitsToUint(max(viewDepth(s.position), 0.0));
        atomicMin(tileDepthMin, depthBits);
        atomicMax(tileDepthMax, depthBits);
    }
    barrier();
    if (tileDepthMax == 0u)
        return;  // no surface in this tile

    // The tile's frustum: four planes through the eye (normals point inwards), cut to the
    // depth range of its surfaces, widened slightly so rounding cannot cut a surface off.
    float depthMin = uintBitsToFloat(tileDepthMin) * 0.999;
    float depthMax = uintBitsToFloat(tileDepthMax) * 1.001;
    vec2 pixelLo = vec2(gl_WorkGroupID.xy * uint(TILE_SIZE));
    vec2 pixelHi = min(pixelLo + float(TILE_SIZE), frame.viewport.xy);
    vec2 slopeLo = (pixelLo * frame.viewport.zw * 2.0 - 1.0) * frame.projection.xy;
    vec2 slopeHi = (pixelHi * frame.viewport.zw * 2.0 - 1.0) * frame.projection.xy;
    vec3 planes[4] = vec3[4](normalize(vec3(1.0, 0.0, slopeLo.x)), normalize(vec3(-1.0, 0.0, -slopeHi.x)),
                             normalize(vec3(0.0, 1.0, slopeLo.y)), normalize(vec3(0.0, -1.0, -slopeHi.y)));
    vec3 boxLo = vec3(min(slopeLo * depthMin, slopeLo * depthMax), -depthMax);
    vec3 boxHi = vec3(max(slopeHi * depthMin, slopeHi * depthMax), -depthMin);
    vec3 boxCentre = 0.5 * (boxLo + boxHi);
    float boxRadius = 0.5 * length(boxHi - boxLo);

    for (uint i = gl_LocalInvocationIndex; i < frame.counts.x; i += THREADS) {
        GpuLight light = lights[i];
        float radius = light.positionRadius.w;
        if (radius <= 0.0)
            continue;
        if (radius < UNBOUNDED_RADIUS) {
            vec3 centre = (frame.view * vec4(light.positionRadius.xyz, 1.0)).xyz;
            if (-centre.z - radius > depthMax || -centre.z + radius < depthMin)
                continue;
            if (dot(planes[0], centre) < -radius || dot(planes[1], centre) < -radius ||
                dot(planes[2], centre) < -radius || dot(planes[3], centre) < -radius)
                continue;
            vec3 axis = mat3(frame.view) * light.spotAxisCosCutoff.xyz;
            if (!coneTouchesSphere(centre, axis, light.spotAxisCosCutoff.w, boxCentre, boxRadius))
                continue;
        }
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
    vec3 color = shadeGlobal(s, V);
    if (overflowed) {
        // More lights reach the tile than its list holds: nothing is dropped, the tile's
        // pixels evaluate every light instead (slow, and reported in --stats).
        for (uint i = 0u; i < frame.counts.x; ++i)
            color += shadeLocal(i, s, V);
        recordLightEvaluationsAt(pixel, frame.counts.x);
    } else {
        for (uint i = 0u; i < count; ++i)
            color += shadeLocal(tileLights[i], s, V);
        recordLightEvaluationsAt(pixel, count);
    }
    imageStore(litImage, pixel, vec4(color, 1.0));
}
