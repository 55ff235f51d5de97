#version 450 core
// Clustered, step 0: the nearest and farthest visible surface of the frame, the depth range
// the slices then divide.
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
    // Positive floats order like their bits.
    uint depthBits = floatBitsToUint(max(viewDepth(gbufferPosition(pixel)), 0.0));
    atomicMin(sceneDepthBits[0], depthBits);
    atomicMax(sceneDepthBits[1], depthBits);
}
