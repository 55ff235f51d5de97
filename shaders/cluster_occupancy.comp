#version 450 core
// Clustered, step 1: mark the clusters that hold at least one visible surface. Only those
// get lights (Olsson et al.'s cluster compaction, as a flag per cluster).
#include "lib/frame.glsl"
#include "lib/clusters.glsl"
#include "lib/gbuffer_position.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 5) uniform sampler2D sceneDepth;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy))) || texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return;
    float depth = viewDepth(gbufferPosition(pixel));
    clusterOccupied[clusterIndex(clusterOfPixel(vec2(pixel) + 0.5, depth))] = 1u;
}
