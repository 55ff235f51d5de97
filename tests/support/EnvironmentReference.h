// The environment's prefiltered radiance by brute force (docs/lighting.md, "The environment"),
// the reference tests/gl/EnvironmentLightTest.cpp checks the levels against and
// tests/image/EnvironmentLightTest.cpp the rendered spheres: for roughness r (α = r²) and a
// unit direction N, with V = N,
//   P(N) = ∫ L(ω) D(h) max(N·ω, 0) dω / ∫ D(h) max(N·ω, 0) dω,   h = normalize(N + ω),
// summed over every texel of the map, each constant over its rectangle, at its centre, with its
// exact solid angle. And the map with a real sun that issue 48 found blotches and a star with.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Environment.h"

namespace manylights::test {

// The map's texels as the sum takes them: direction, radiance, solid angle. In plain doubles,
// not glm's vectors: the same arithmetic in the same order, but an unoptimised build (`make
// sanitize`'s Debug) calls a function for each of glm's operators, which made the sum over a
// 128x64 map for every texel of the levels take a minute there.
class EnvironmentTexelSum {
public:
    explicit EnvironmentTexelSum(const EnvironmentImage& map)
    {
        for (int j = 0; j < map.height; ++j) {
            const double solidAngle = environmentTexelSolidAngle(j, map.height);
            for (int i = 0; i < map.width; ++i) {
                const glm::dvec3 d = environmentDirection({(i + 0.5) / map.width, (j + 0.5) / map.height});
                const glm::vec3 radiance = map.at(i, j);
                texels_.push_back({d.x, d.y, d.z, solidAngle, radiance.r, radiance.g, radiance.b});
            }
        }
    }

    // P(n) for `roughness`. With V = N, (N·h)² = (1 + N·ω) / 2, and D's constant factor cancels.
    glm::dvec3 prefiltered(const glm::dvec3& n, double roughness) const
    {
        const double alpha = roughness * roughness;
        const double a2 = alpha * alpha;
        double r = 0.0, g = 0.0, b = 0.0, weight = 0.0;
        for (const Texel& t : texels_) {
            const double nl = n.x * t.x + n.y * t.y + n.z * t.z;
            if (nl <= 0.0)
                continue;
            const double d = (0.5 + 0.5 * nl) * (a2 - 1.0) + 1.0;
            const double w = nl * t.solidAngle / (d * d);
            r += t.r * w;
            g += t.g * w;
            b += t.b * w;
            weight += w;
        }
        return glm::dvec3(r, g, b) / weight;
    }

private:
    struct Texel {
        double x, y, z;  // the direction of its centre
        double solidAngle;
        double r, g, b;  // its radiance
    };
    std::vector<Texel> texels_;
};

// Issue 48's map: a sky of about 1 (bluer and brighter towards the zenith) over a ground of about
// 0.4, and a sun 0.6° across of radiance 20,000 at kSunDirection, 55° up. Each texel holds the
// mean over its solid angle (the sun's share by 16x16 points spread evenly in u and cos θ), so a
// sun narrower than a texel is a texel of its power, as in a file of that size. `height` rows;
// the sun elsewhere with `sun` (unit).
inline const glm::dvec3 kSunDirection = glm::normalize(glm::dvec3(0.35, 0.82, 0.45));
inline constexpr double kSunRadiance = 20000.0;
inline constexpr double kSunDiameterDegrees = 0.6;

inline glm::dvec3 sunMapSky(const glm::dvec3& d)
{
    if (d.y < 0.0)
        return {0.45, 0.4, 0.35};
    return glm::dvec3(0.75, 0.85, 1.0) + glm::dvec3(0.15, 0.2, 0.35) * d.y;
}

inline EnvironmentImage sunMap(int height, const glm::dvec3& sun = kSunDirection)
{
    constexpr int kPoints = 16;
    const double sunCos = std::cos(kSunDiameterDegrees / 2.0 * std::numbers::pi / 180.0);
    // Texels whose centre is further than this from the sun cannot hold any of it (a texel's
    // half-diagonal is under 2 · π / height).
    const double nearCos = std::cos(4.0 * std::numbers::pi / height);
    EnvironmentImage map{.width = 2 * height, .height = height, .radiance = {}};
    map.radiance.resize(static_cast<std::size_t>(map.width) * height);
    for (int j = 0; j < height; ++j) {
        const double cosTop = std::cos(std::numbers::pi * j / height);
        const double cosBottom = std::cos(std::numbers::pi * (j + 1) / height);
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 centre = environmentDirection({(i + 0.5) / map.width, (j + 0.5) / height});
            glm::dvec3 radiance = sunMapSky(centre);
            if (glm::dot(centre, sun) > nearCos) {
                int inside = 0;
                for (int a = 0; a < kPoints; ++a)
                    for (int b = 0; b < kPoints; ++b) {
                        const double cosTheta = cosTop + (cosBottom - cosTop) * (b + 0.5) / kPoints;
                        const double v = std::acos(std::clamp(cosTheta, -1.0, 1.0)) / std::numbers::pi;
                        const glm::dvec3 d = environmentDirection({(i + (a + 0.5) / kPoints) / map.width, v});
                        inside += glm::dot(d, sun) > sunCos ? 1 : 0;
                    }
                radiance += glm::dvec3(kSunRadiance * inside / (kPoints * kPoints));
            }
            map.at(i, j) = glm::vec3(radiance);
        }
    }
    return map;
}

}  // namespace manylights::test
