#version 450 core
// in_range_pairs (SPEC.md §3): for every pixel holding a surface, how many lights reach it
// (A·S > 0). The least work any technique can do; a technique's culling efficiency is this
// over its light evaluations.
#define LIGHTING_IN_COMPUTE 1
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 5) uniform sampler2D sceneDepth;
layout(binding = 1, r32ui) uniform writeonly uimage2D inRangeCounts;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(inRangeCounts))))
        return;
    uint count = 0u;
    if (texelFetch(sceneDepth, pixel, 0).r < 1.0) {
        vec3 position = gbufferPosition(pixel);
        for (uint i = 0u; i < frame.counts.x; ++i)
            if (lightReach(lights[i], position).w > 0.0)
                ++count;
    }
    imageStore(inRangeCounts, pixel, uvec4(count));
}
