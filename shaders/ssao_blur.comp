#version 450 core
// Averages the raw occlusion over the 4x4 block the noise tile repeats in (render/effects/Ssao.cpp),
// so the per-pixel rotation's pattern disappears. Only pixels holding a surface take part.
#include "lib/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = RAW_OCCLUSION_UNIT) uniform sampler2D rawOcclusion;
layout(binding = OCCLUSION_IMAGE_UNIT, r32f) uniform writeonly image2D blurredOcclusion;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(blurredOcclusion);
    if (any(greaterThanEqual(pixel, size)))
        return;
    float sum = 0.0;
    float count = 0.0;
    for (int dy = -2; dy < 2; ++dy)
        for (int dx = -2; dx < 2; ++dx) {
            ivec2 neighbour = pixel + ivec2(dx, dy);
            if (any(lessThan(neighbour, ivec2(0))) || any(greaterThanEqual(neighbour, size)) ||
                texelFetch(sceneDepth, neighbour, 0).r == 1.0)
                continue;
            sum += texelFetch(rawOcclusion, neighbour, 0).r;
            count += 1.0;
        }
    imageStore(blurredOcclusion, pixel, vec4(count > 0.0 ? sum / count : 1.0));
}
