#version 450 core
// The log-average luminance of the lit image's surfaces (Reinhard et al. 2002, eq. 1: exp of
// the mean of log(δ + L)), for the viewer's auto-exposure (render/effects/DisplayPass.h). Background
// pixels do not count: an empty sky would otherwise drag the exposure up until every surface
// burns out. 0.18 (exposure 0) when no sample holds a surface. One workgroup samples
// a grid of SAMPLES_X x SAMPLES_Y points spread over the image (every pixel would cost a
// full-screen pass; a grid of 2,304 points tracks the average as well for exposure), each
// thread summing its share, then halving the sums in shared memory. Loop iterations: grid
// points / 256 = 9, then 8 halvings.
#include "lib/bindings.glsl"
layout(local_size_x = 256) in;
layout(binding = DISPLAY_SOURCE_UNIT) uniform sampler2D litImage;
layout(binding = LUMINANCE_DEPTH_UNIT) uniform sampler2D surfaceDepth;
layout(std430, binding = LUMINANCE_RESULT_BUFFER_BINDING) writeonly buffer Result {
    float logAverageLuminance;
};

const uint SAMPLES_X = 64u;
const uint SAMPLES_Y = 36u;
const float DELTA = 1e-4;  // keeps black pixels from sending the log to −∞

shared float sums[256];
shared float counts[256];

void main()
{
    ivec2 size = textureSize(litImage, 0);
    float sum = 0.0;
    float count = 0.0;
    for (uint i = gl_LocalInvocationIndex; i < SAMPLES_X * SAMPLES_Y; i += 256u) {
        vec2 where = (vec2(i % SAMPLES_X, i / SAMPLES_X) + 0.5) / vec2(SAMPLES_X, SAMPLES_Y);
        ivec2 pixel = ivec2(where * vec2(size));
        if (texelFetch(surfaceDepth, pixel, 0).r == 1.0)
            continue;
        vec3 colour = texelFetch(litImage, pixel, 0).rgb;
        float luminance = dot(max(colour, vec3(0.0)), vec3(0.2126, 0.7152, 0.0722));  // Rec. 709
        sum += log(DELTA + luminance);
        count += 1.0;
    }
    sums[gl_LocalInvocationIndex] = sum;
    counts[gl_LocalInvocationIndex] = count;
    barrier();
    for (uint half_ = 128u; half_ > 0u; half_ >>= 1u) {
        if (gl_LocalInvocationIndex < half_) {
            sums[gl_LocalInvocationIndex] += sums[gl_LocalInvocationIndex + half_];
            counts[gl_LocalInvocationIndex] += counts[gl_LocalInvocationIndex + half_];
        }
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u)
        logAverageLuminance = counts[0] > 0.0 ? exp(sums[0] / counts[0]) : 0.18;
}
