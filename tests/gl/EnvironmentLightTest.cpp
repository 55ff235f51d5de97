// The environment's prefiltered radiance (render/environment/EnvironmentLight.h, issue 42)
// against a CPU reference of the integral it approximates, on a small smooth map: for each
// level l (roughness r = l / 5, α = r²) and texel direction N, with V = N,
//   P(N) = ∫ L(ω) D(h) max(N·ω, 0) dω / ∫ D(h) max(N·ω, 0) dω,   h = normalize(N + ω),
// summed here over every texel of the map (each constant over its rectangle, its exact solid
// angle). That is the mean of L(l)·(N·l) / mean of (N·l) over GGX-distributed l, which the
// compute pass estimates with 64 to 256 filtered importance samples.
//
// Tolerance: 2% of the reference + 1e-3. The estimate reads the map's mipmaps (2x2 box averages
// that ignore each texel's solid angle) with bilinear filtering where the reference takes each
// texel exactly, from a few samples each standing for a patch of the lobe: filtered importance
// sampling blurs, lowering peaks and raising valleys. The largest difference measured over the
// checked texels was 85% of the tolerance (level 2, a dim texel 2.3% off; the others 1.1-1.7%
// of their value); the chain's float storage adds nothing to speak of. A level
// prefiltered for the wrong roughness (the next level's, or α taken as r) is off by more than
// the tolerance somewhere on this map, which LevelOfTheWrongRoughnessFallsOutside checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "GlContextTest.h"
#include "render/environment/EnvironmentLight.h"
#include "scene/Environment.h"

namespace manylights {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRelativeTolerance = 0.02;
constexpr double kAbsoluteTolerance = 1e-3;

// A smooth map of 64x32 texels: a sky gradient and two broad bright lobes off the axes.
EnvironmentImage smoothMap()
{
    EnvironmentImage map{.width = 64, .height = 32, .radiance = {}};
    map.radiance.resize(64 * 32);
    const glm::dvec3 wide = glm::normalize(glm::dvec3(0.6, 0.5, -0.6));
    const glm::dvec3 narrow = glm::normalize(glm::dvec3(-0.7, 0.1, 0.7));
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 d = environmentDirection({(i + 0.5) / map.width, (j + 0.5) / map.height});
            const double base = 0.4 + 0.3 * d.y;
            const double a = 3.0 * std::exp(-(1.0 - glm::dot(d, wide)) * 6.0);
            const double b = 2.0 * std::exp(-(1.0 - glm::dot(d, narrow)) * 20.0);
            map.at(i, j) = glm::vec3(glm::dvec3(base + a, base + 0.5 * a + b, base + b));
        }
    return map;
}

// The reference P(N) for roughness r (α = r²).
glm::dvec3 prefilteredReference(const EnvironmentImage& map, const glm::dvec3& n, double roughness)
{
    const double alpha = roughness * roughness;
    const double a2 = alpha * alpha;
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (int j = 0; j < map.height; ++j) {
        const double solidAngle = environmentTexelSolidAngle(j, map.height);
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 l = environmentDirection({(i + 0.5) / map.width, (j + 0.5) / map.height});
            const double nl = glm::dot(n, l);
            if (nl <= 0.0)
                continue;
            const double nh = glm::dot(n, glm::normalize(n + l));
            const double t = nh * nh * (a2 - 1.0) + 1.0;
            const double w = a2 / (kPi * t * t) * nl * solidAngle;
            sum += glm::dvec3(map.at(i, j)) * w;
            weight += w;
        }
    }
    return sum / weight;
}

class EnvironmentLightTest : public GlContextTest {
protected:
    // Each level of the chain prefiltered from `map`, as RGBA floats, rows from v = 0.
    static std::vector<std::vector<float>> prefilteredLevels(const EnvironmentImage& map)
    {
        const gl::MipmappedTexture2D radiance("test radiance", EnvironmentLight::kRadianceFormat,
                                              EnvironmentLight::kRadianceWidth, EnvironmentLight::kRadianceWidth / 2,
                                              EnvironmentLight::kRadianceLevels);
        const gl::Program program = EnvironmentLight::prefilterProgram(EnvironmentLight::kRadianceFormat);
        EnvironmentLight::prefilter(map, radiance, program);
        std::vector<std::vector<float>> levels;
        for (int level = 0; level < radiance.levels(); ++level) {
            std::vector<float> texels(static_cast<std::size_t>(radiance.levelWidth(level)) *
                                      radiance.levelHeight(level) * 4);
            radiance.readLevel(level, GL_RGBA, GL_FLOAT, texels.size() * sizeof(float), texels.data());
            levels.push_back(std::move(texels));
        }
        return levels;
    }

    // The largest |got − reference| / (tolerance) over every `step`-th texel of `level`, with
    // the reference made for `roughness`; above 1 means outside the tolerance.
    static double worstOfLevel(const EnvironmentImage& map, const std::vector<float>& texels, int level,
                               double roughness, int step)
    {
        const int width = EnvironmentLight::kRadianceWidth >> level;
        const int height = width / 2;
        double worst = 0.0;
        for (int j = step / 2; j < height; j += step)
            for (int i = step / 2; i < width; i += step) {
                const glm::dvec3 n = environmentDirection({(i + 0.5) / width, (j + 0.5) / height});
                const glm::dvec3 want = prefilteredReference(map, n, roughness);
                for (int c = 0; c < 3; ++c) {
                    const double got = texels[(static_cast<std::size_t>(j) * width + i) * 4 + c];
                    const double allowed = kRelativeTolerance * want[c] + kAbsoluteTolerance;
                    worst = std::max(worst, std::abs(got - want[c]) / allowed);
                }
            }
        return worst;
    }
};

TEST_F(EnvironmentLightTest, PrefilteredLevelsMatchTheCpuIntegral)
{
    const EnvironmentImage map = smoothMap();
    const std::vector<std::vector<float>> levels = prefilteredLevels(map);
    ASSERT_EQ(levels.size(), static_cast<std::size_t>(EnvironmentLight::kRadianceLevels));
    for (int level = 1; level < EnvironmentLight::kRadianceLevels; ++level) {
        // Every texel of the small levels, a spread of the large ones (the reference is a sum over
        // the whole map per texel).
        const int step = std::max(1, (EnvironmentLight::kRadianceWidth >> level) / 32);
        const double worst =
            worstOfLevel(map, levels[static_cast<std::size_t>(level)], level, environmentLevelRoughness(level), step);
        EXPECT_LE(worst, 1.0) << "level " << level;
    }
}

TEST_F(EnvironmentLightTest, LevelOfTheWrongRoughnessFallsOutside)
{
    const EnvironmentImage map = smoothMap();
    const std::vector<std::vector<float>> levels = prefilteredLevels(map);
    for (int level = 1; level + 1 < EnvironmentLight::kRadianceLevels; ++level) {
        const int step = std::max(1, (EnvironmentLight::kRadianceWidth >> level) / 32);
        const std::vector<float>& texels = levels[static_cast<std::size_t>(level)];
        EXPECT_GT(worstOfLevel(map, texels, level, environmentLevelRoughness(level + 1), step), 1.0) << level;
        // Roughness taken as α: the lobe of r² instead of r.
        const double r = environmentLevelRoughness(level);
        EXPECT_GT(worstOfLevel(map, texels, level, std::sqrt(r), step), 1.0) << level;
    }
}

TEST_F(EnvironmentLightTest, FirstLevelIsTheMapItself)
{
    // A map as wide as the chain: level 0 is its texels (read at their centres; 2^-10 would
    // allow half-float storage, which llvmpipe truncates).
    EnvironmentImage map = studioEnvironment(EnvironmentLight::kRadianceWidth / 2);
    const std::vector<std::vector<float>> levels = prefilteredLevels(map);
    for (std::size_t t = 0; t < map.radiance.size(); ++t)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(levels[0][t * 4 + c], map.radiance[t][c], map.radiance[t][c] * 0x1p-10) << "texel " << t;
}

TEST_F(EnvironmentLightTest, NoEnvironmentBindsZeros)
{
    const EnvironmentLight none;
    EXPECT_FALSE(none.present());
    EXPECT_FALSE(none.showsBackground());
    float texel[4] = {1, 1, 1, 1};
    none.radiance().readLevel(0, GL_RGBA, GL_FLOAT, sizeof texel, texel);
    EXPECT_EQ(texel[0] + texel[1] + texel[2], 0.0f);
}

}  // namespace
}  // namespace manylights
