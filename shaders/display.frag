#version 450 core
// The display pass (render/DisplayPass.h): each output pixel averages its SUPERSAMPLE x
// SUPERSAMPLE block of the lit image in linear light (a box filter; 1 x 1 without
// supersampling), then applies the display transform of lib/display.glsl. With the default
// settings the transform is the identity and the pixel passes unchanged. Loop iterations:
// at most kMaxSupersample² = 64. A full-screen fragment pass rather than a compute one:
// llvmpipe runs it about three times as fast (docs/performance.md).
#include "lib/display.glsl"

layout(binding = 0) uniform sampler2D litImage;
layout(location = 0) uniform float exposureScale;  // 2^EV
layout(location = 1) uniform int supersample;
layout(location = 0) out vec4 displayed;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    ivec2 first = pixel * supersample;
    for (int dy = 0; dy < supersample; ++dy)
        for (int dx = 0; dx < supersample; ++dx)
            sum += texelFetch(litImage, first + ivec2(dx, dy), 0).rgb;
    vec3 linear = sum / float(supersample * supersample);
    vec3 colour = displayTransform(linear, exposureScale);
    // Alpha: the luma FXAA finds edges by (shaders/fxaa.frag), of the displayed values.
    displayed = vec4(colour, dot(clamp(colour, 0.0, 1.0), vec3(0.299, 0.587, 0.114)));
}
