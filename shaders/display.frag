#version 450 core
// The display pass (render/effects/DisplayPass.h): each output pixel averages its SUPERSAMPLE x
// SUPERSAMPLE block of the lit image in linear light (a box filter; one fetch without
// supersampling), then applies the display transform of lib/display.glsl. SUPERSAMPLE is a
// compile-time constant: llvmpipe runs a fetch inside a loop of uniform length several times
// slower than a lone one (7 of 11 ms at 1280x720). Loop iterations: at most
// kMaxSupersample² = 64. A full-screen fragment pass rather than a compute one: llvmpipe runs
// it faster (docs/performance.md).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#include "lib/display.glsl"

layout(binding = DISPLAY_SOURCE_UNIT) uniform sampler2D litImage;
layout(location = DISPLAY_EXPOSURE_SCALE_LOCATION) uniform float exposureScale;  // 2^EV
layout(location = 0) out vec4 displayed;
#ifdef COPY_OUTPUT
// With FXAA: the same picture into FXAA's output, whose non-edge pixels it keeps.
layout(location = 1) out vec4 displayedCopy;
#endif

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#if SUPERSAMPLE == 1
    vec3 linear = texelFetch(litImage, pixel, 0).rgb;
#else
    vec3 sum = vec3(0.0);
    ivec2 first = pixel * SUPERSAMPLE;
    for (int dy = 0; dy < SUPERSAMPLE; ++dy)
        for (int dx = 0; dx < SUPERSAMPLE; ++dx)
            sum += texelFetch(litImage, first + ivec2(dx, dy), 0).rgb;
    vec3 linear = sum / float(SUPERSAMPLE * SUPERSAMPLE);
#endif
    vec3 colour = displayTransform(linear, exposureScale);
    // Alpha: the luma FXAA finds edges by (shaders/fxaa.frag), of the displayed values.
    displayed = vec4(colour, dot(clamp(colour, 0.0, 1.0), vec3(0.299, 0.587, 0.114)));
#ifdef COPY_OUTPUT
    displayedCopy = displayed;
#endif
}
