// What the prefiltering of an environment reads (issue 48; docs/lighting.md, "The environment"):
// the map split into a bounded remainder, which filtered importance sampling estimates well, and
// its brightest texels, which the compute pass sums exactly for every texel of every level.
//
// Filtered importance sampling reads a handful of mipmap texels per lobe. For a map whose light
// varies smoothly that is within a percent or two of the integral, but a sun (0.6° of radiance
// 20,000 over a sky of 1) is a few texels that outshine the whole sky: each sample that sees it
// adds a blob, so the levels came out blotchy, and where the sample pattern turns quickly (about
// the poles) the blobs made a star. Taking the light above a threshold off those texels and
// summing it texel by texel leaves the sampling a map whose range it handles, and the sum is the
// brute-force integral over those texels, exactly.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Environment.h"

namespace manylights {

// std430 layout of shaders/environment_prefilter.comp: BrightTexels.
struct BrightTexel {
    glm::vec4 direction;  // xyz: the unit direction of the texel's centre (map frame)
    glm::vec4 power;      // rgb: the radiance taken off the texel times its solid angle
};

struct PrefilterSource {
    // The map at most `maxWidth` wide, each texel's luminance at most `threshold`.
    EnvironmentImage remainder;
    // What was taken off the texels above the threshold, at most `maxBright` of them.
    std::vector<BrightTexel> bright;
    float threshold = 0.0f;
};

// The luminance the split compares (Rec. 709 weights, as the display's).
float environmentLuminance(const glm::vec3& radiance);

// `map` box-filtered to at most `maxWidth` wide (the same map when it is not wider): each texel
// the solid-angle-weighted mean of the texels whose centres fall in it, so a texel's radiance
// times its solid angle keeps the power it stands for. `maxWidth` even and ≥ 2.
EnvironmentImage downsampledEnvironment(const EnvironmentImage& map, int maxWidth);

// `map` at most `maxWidth` wide, split at the threshold `kBrightFactor` times its mean luminance
// or, when more than `maxBright` texels are above that, the luminance of the brightest texel not
// taken. A texel above the threshold keeps its colour scaled to the threshold's luminance, and
// the rest, times its solid angle, goes to `bright`. The remainder's and the bright texels' power
// add up to the map's.
inline constexpr double kBrightFactor = 2.0;
PrefilterSource splitForPrefiltering(const EnvironmentImage& map, int maxWidth, std::size_t maxBright);

// W(α) = ∫ D(h) max(N·ω, 0) dω over the sphere, with h = normalize(N + ω) and D GGX's
// distribution of α = roughness²: what the prefiltered integral divides by, with V = N.
double ggxLobeIntegral(double roughness);

}  // namespace manylights
