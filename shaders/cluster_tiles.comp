#version 450 core
// A cluster grid fitted to the surfaces, once per frame (clustered, tiled): one invocation per
// tile finds the nearest and farthest surface seen through the tile (its slices divide that
// range), then marks the slices that hold a pixel's surface. Only those get lights. With
// CLUSTER_SURFACE_BOUNDS it also keeps, per occupied cluster, the view-space box around its
// surfaces (lib/clusters.glsl), which the light lists test lights against
// (lib/cluster_culling.glsl).
// A thread per tile walking its pixels, rather than a workgroup per tile meeting at
// barriers: llvmpipe runs barriers by switching between the workgroup's invocations, which
// cost more than the walk. The first walk keeps each pixel's view-space position for the
// second (reading the G-buffer again cost 4 ms of 21 at 1280x720).
// Loop iterations: two walks of CLUSTER_TILE_SIZE² pixels, the second with CLUSTER_SLICES per
// pixel (unless the compiler unrolls them), and two of the slices: 2 · (256 + 17) + 256 · 32 +
// 2 · 32 at most.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/gbuffer_position.glsl"

layout(local_size_x = 64) in;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;

// The view-space position of the surface at `pixel` (xyz) and its view depth as the lighting
// pass computes it (w), or w = 0 where there is none. Surfaces lie beyond the near plane; the
// floor keeps the slice logs finite whatever the rounding.
vec4 surfaceAt(ivec2 pixel)
{
    if (texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return vec4(0.0);
    vec3 world = gbufferPosition(pixel);
    return vec4((frame.view * vec4(world, 1.0)).xyz, max(viewDepth(world), frame.projection.z * 0.5));
}

void main()
{
    uvec2 grid = clusterTileGrid();
    uint tile = gl_GlobalInvocationID.x;
    if (tile >= grid.x * grid.y)
        return;
    uvec2 tileLo;
    uvec2 tileHi;
    clusterTilePixels(tile, tileLo, tileHi);
    ivec2 first = ivec2(tileLo);
    ivec2 end = ivec2(tileHi);
    float nearest = 3.0e38;
    float farthest = 0.0;
    vec4 surfaces[CLUSTER_TILE_SIZE * CLUSTER_TILE_SIZE];
    for (int y = first.y; y < end.y; ++y)
        for (int x = first.x; x < end.x; ++x) {
            vec4 surface = surfaceAt(ivec2(x, y));
            surfaces[(y - first.y) * CLUSTER_TILE_SIZE + x - first.x] = surface;
            if (surface.w != 0.0) {
                nearest = min(nearest, surface.w);
                farthest = max(farthest, surface.w);
            }
        }
    if (farthest == 0.0) {
        tileDepthRange[tile] = vec4(0.0);
        tileOccupiedSlices[tile] = 0u;
        return;
    }
    // Widened so that rounding cannot put a surface outside; the ratio stays above 1, so the
    // slice logs are defined even for a tile facing the camera square on.
    vec4 slicing = tileSlicing(vec2(nearest * 0.999, farthest * 1.001));
    uint occupied = 0u;
#ifdef CLUSTER_SURFACE_BOUNDS
    vec3 lo[CLUSTER_SLICES];
    vec3 hi[CLUSTER_SLICES];
    for (int k = 0; k < CLUSTER_SLICES; ++k) {
        lo[k] = vec3(3.0e38);
        hi[k] = vec3(-3.0e38);
    }
#endif
    for (int y = first.y; y < end.y; ++y)
        for (int x = first.x; x < end.x; ++x) {
            vec4 surface = surfaces[(y - first.y) * CLUSTER_TILE_SIZE + x - first.x];
            if (surface.w != 0.0) {
                // The lighting pass computes the slice again in another program, whose
                // rounding may differ: a surface within a hundredth of a slice of a boundary
                // counts on both sides (it is in both slices' boxes).
                float coordinate = sliceCoordinate(surface.w, slicing);
                uint below = uint(clamp(floor(coordinate - 0.01), 0.0, float(CLUSTER_SLICES - 1)));
                uint above = uint(clamp(floor(coordinate + 0.01), 0.0, float(CLUSTER_SLICES - 1)));
                occupied |= (1u << below) | (1u << above);
#ifdef CLUSTER_SURFACE_BOUNDS
                // Every slice's box, each kept or grown by a select, rather than the two
                // boxes indexed by the slices: an index that differs from lane to lane makes
                // llvmpipe reach the arrays lane by lane, where the loop, unrolled, keeps them
                // in registers (courtyard, 1280x720: clustered's pass 15-16 -> 13 ms,
                // docs/techniques.md).
                for (int k = 0; k < CLUSTER_SLICES; ++k) {
                    bool inSlice = uint(k) == below || uint(k) == above;
                    lo[k] = inSlice ? min(lo[k], surface.xyz) : lo[k];
                    hi[k] = inSlice ? max(hi[k], surface.xyz) : hi[k];
                }
#endif
            }
        }
    tileDepthRange[tile] = slicing;
    tileOccupiedSlices[tile] = occupied;
#ifdef CLUSTER_SURFACE_BOUNDS
    // Grown by a little more than a view-space coordinate's rounding, so that a surface the
    // lighting pass finds in reach (in world space) is inside its cluster's box too.
    uint clusterBase = tile * uint(CLUSTER_SLICES);
    for (int k = 0; k < CLUSTER_SLICES; ++k) {
        if ((occupied & (1u << uint(k))) == 0u)
            continue;
        vec3 margin = vec3(1e-5) + 1e-5 * max(abs(lo[k]), abs(hi[k]));
        clusterBounds[2u * (clusterBase + uint(k))] = vec4(lo[k] - margin, 0.0);
        clusterBounds[2u * (clusterBase + uint(k)) + 1u] = vec4(hi[k] + margin, 0.0);
    }
#endif
}
