#version 450 core
// One level of the environment's prefiltered radiance (render/environment/EnvironmentLight.h):
// the map convolved with the GGX lobe of `roughness` about each texel's direction, with N = V = R
// (the split-sum approximation's assumption, Karis 2013), weighted by N·L as Karis's, in two
// parts (render/environment/PrefilterSource.h). The map's remainder below a threshold is
// importance-sampled with filtered importance sampling (Křivánek and Colbert 2008): each of
// `sampleCount` samples reads the remainder's mipmap whose texels cover the solid angle the
// sample stands for, so that a few samples see the whole lobe without the noise of point
// samples. The light taken off the brightest texels (a sun) is summed texel by texel, exactly:
// Σ power · D(h) (N·l) / W(α), W the lobe's integral. tests/gl/EnvironmentLightTest.cpp checks
// the levels against the integral summed over the map's texels on the CPU.
#include "lib/bindings.glsl"
#include "lib/environment.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = ENVIRONMENT_SOURCE_UNIT) uniform sampler2D environmentSource;
layout(binding = ENVIRONMENT_LEVEL_IMAGE_UNIT, ENVIRONMENT_FORMAT) uniform writeonly image2D environmentLevel;
layout(location = 0) uniform float roughness;
// The level's samples per texel, at most MAX_PREFILTER_SAMPLES (EnvironmentLight::prefilterSamples).
layout(location = 1) uniform uint sampleCount;
// How many bright texels there are, at most MAX_BRIGHT_TEXELS, and 1 / W(α) (ggxLobeIntegral).
layout(location = 2) uniform uint brightTexelCount;
layout(location = 3) uniform float inverseLobeIntegral;

// std430 layout of render/environment/PrefilterSource.h: BrightTexel, pairs of direction (xyz)
// and power (rgb: radiance above the threshold times the texel's solid angle).
layout(std430, binding = ENVIRONMENT_BRIGHT_TEXELS_BUFFER_BINDING) readonly buffer BrightTexels {
    vec4 brightTexels[];
};

// The i-th of `count` points of the Hammersley set on the unit square.
vec2 hammersley(uint i, uint count)
{
    return vec2(float(i) / float(count), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

void main()
{
    ivec2 size = imageSize(environmentLevel);
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= size.x || texel.y >= size.y)
        return;
    vec2 uv = (vec2(texel) + 0.5) / vec2(size);
    vec2 sourceSize = vec2(textureSize(environmentSource, 0));
    vec3 N = environmentDirection(uv);
    vec3 up = abs(N.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 T = normalize(cross(up, N));
    vec3 B = cross(N, T);
    float alpha = roughness * roughness;
    float a2 = alpha * alpha;
    // A texel's angular height, π / H: the solid angle of the map's texels at its equator.
    float texelAngle = kEnvironmentPi / sourceSize.y;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint count = min(sampleCount, uint(MAX_PREFILTER_SAMPLES));  // llvmpipe's loops must be bounded
    for (uint i = 0u; i < count; ++i) {
        vec2 xi = hammersley(i, count);
        // H from the GGX distribution D(H)·(N·H), the half vector's density.
        float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (a2 - 1.0) * xi.y));
        float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
        float phi = 2.0 * kEnvironmentPi * xi.x;
        vec3 H = T * (sinTheta * cos(phi)) + B * (sinTheta * sin(phi)) + N * cosTheta;
        vec3 L = 2.0 * cosTheta * H - N;
        float NdotL = dot(N, L);
        // L's density is D(H)·(N·H) / (4 V·H) = D / 4 with V = N; a sample stands for
        // 1 / (count · density) of the sphere, and reads the mipmap whose texels span as much.
        // Křivánek and Colbert add 1 to that level (a bilinear footprint); without it the
        // levels are within 2% of the integral (tests/gl/EnvironmentLightTest.cpp), with it
        // up to 8% blurrier where the map has broad peaks.
        float t = cosTheta * cosTheta * (a2 - 1.0) + 1.0;
        float D = a2 / (kEnvironmentPi * t * t);
        float sampleAngle = 4.0 / (float(count) * D);
        float lod = max(0.5 * log2(sampleAngle / (texelAngle * texelAngle)), 0.0);
        vec3 radiance = textureLod(environmentSource, environmentUv(L), lod).rgb;
        sum += NdotL > 0.0 ? radiance * NdotL : vec3(0.0);
        weight += max(NdotL, 0.0);
    }
    // The bright texels, each at its centre as the CPU's brute-force sum takes it. With V = N,
    // (N·h)² = (1 + N·l) / 2.
    vec3 bright = vec3(0.0);
    uint brightCount = min(brightTexelCount, uint(MAX_BRIGHT_TEXELS));  // llvmpipe's loops must be bounded
    for (uint k = 0u; k < brightCount; ++k) {
        vec3 l = brightTexels[2u * k].xyz;
        float NdotL = dot(N, l);
        float t = (0.5 + 0.5 * NdotL) * (a2 - 1.0) + 1.0;
        float D = a2 / (kEnvironmentPi * t * t);
        bright += NdotL > 0.0 ? brightTexels[2u * k + 1u].rgb * (D * NdotL) : vec3(0.0);
    }
    imageStore(environmentLevel, texel, vec4(sum / weight + bright * inverseLobeIntegral, 1.0));
}
