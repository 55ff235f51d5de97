#version 450 core
// Clustered, once per frame: one invocation per tile finds the nearest and farthest surface
// seen through the tile (its slices divide that range), then marks the slices that hold a
// pixel's surface. Only those get lights. A thread per tile walking its pixels, rather than
// a workgroup per tile meeting at barriers: llvmpipe runs barriers by switching between
// the workgroup's invocations, which cost more than the walk. The first walk keeps each
// pixel's depth for the second (reading the G-buffer again cost 4 ms of 21 at 1280x720).
// Loop iterations: two walks of CLUSTER_TILE_SIZE² pixels, 2 · (256 + 17) for 16-pixel tiles.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/light_batch.glsl"
#include "lib/clusters.glsl"
#include "lib/gbuffer_position.glsl"

layout(local_size_x = 64) in;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;

// The view depth of the surface at `pixel`, or 0 where there is none. Surfaces lie beyond
// the near plane; the floor keeps the slice logs finite whatever the rounding.
float surfaceDepth(ivec2 pixel)
{
    if (texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return 0.0;
    return max(viewDepth(gbufferPosition(pixel)), frame.projection.z * 0.5);
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
    float depths[CLUSTER_TILE_SIZE * CLUSTER_TILE_SIZE];
    for (int y = first.y; y < end.y; ++y)
        for (int x = first.x; x < end.x; ++x) {
            float depth = surfaceDepth(ivec2(x, y));
            depths[(y - first.y) * CLUSTER_TILE_SIZE + x - first.x] = depth;
            if (depth > 0.0) {
                nearest = min(nearest, depth);
                farthest = max(farthest, depth);
            }
        }
    if (farthest == 0.0) {
        tileDepthRange[tile] = vec2(0.0);
        tileOccupiedSlices[tile] = 0u;
        return;
    }
    // Widened so that rounding cannot put a surface outside; the ratio stays above 1, so the
    // slice logs are defined even for a tile facing the camera square on.
    vec2 range = vec2(nearest * 0.999, farthest * 1.001);
    uint occupied = 0u;
    for (int y = first.y; y < end.y; ++y)
        for (int x = first.x; x < end.x; ++x) {
            float depth = depths[(y - first.y) * CLUSTER_TILE_SIZE + x - first.x];
            if (depth > 0.0) {
                // The lighting pass computes the slice again in another program, whose
                // rounding may differ: a surface within a hundredth of a slice of a boundary
                // marks both sides.
                float coordinate = sliceCoordinate(depth, range);
                uint below = uint(clamp(floor(coordinate - 0.01), 0.0, float(CLUSTER_SLICES - 1)));
                uint above = uint(clamp(floor(coordinate + 0.01), 0.0, float(CLUSTER_SLICES - 1)));
                occupied |= (1u << below) | (1u << above);
            }
        }
    tileDepthRange[tile] = range;
    tileOccupiedSlices[tile] = occupied;
}
