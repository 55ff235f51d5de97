// The environment's prefiltered radiance (render/environment/EnvironmentLight.h, issues 42 and
// 48) against the brute-force integral it approximates (tests/support/EnvironmentReference.h):
// for each level k (roughness r = (k + 1) / 5, α = r²) and texel direction N, with V = N,
//   P(N) = ∫ L(ω) D(h) max(N·ω, 0) dω / ∫ D(h) max(N·ω, 0) dω,   h = normalize(N + ω),
// summed here over every texel of the map (each constant over its rectangle, its exact solid
// angle). The compute pass sums the map's brightest texels exactly and estimates the rest with
// 64 to 256 filtered importance samples.
//
// Tolerances:
// - A small smooth map: 2% of the reference + 1e-3. The estimate reads the remainder's mipmaps
//   (2x2 box averages that ignore each texel's solid angle) with bilinear filtering where the
//   reference takes each texel exactly, from a few samples each standing for a patch of the
//   lobe: filtered importance sampling blurs, lowering peaks and raising valleys. The largest
//   difference measured over the checked texels was 85% of the tolerance before the bright
//   texels were split off (level 2, a dim texel 2.3% off). A level prefiltered for the wrong
//   roughness (the next level's, or α taken as r) is off by more than the tolerance somewhere
//   on this map, which LevelOfTheWrongRoughnessFallsOutside checks.
// - Issue 48's sun map (a 0.6° sun of 20,000 over a sky of about 1, at 256x128 so that the sun
//   is a part of one texel as in a 1024x512 file, and the brute force stays cheap): 3% of the
//   reference at every texel of every level, the poles included, the bound; measured up
//   to 37% of it (1.1%, roughness 0.2). Filtered importance sampling alone, before the brightest
//   texels were split off, was off by up to 147% there (roughness 0.2) and 43% at roughness 1.
//   The same with a noon sun 1.5° from the zenith, in the pole's narrow texels, where the star
//   was (every texel of the poles' rows, every fourth of the others); it fails without the split.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include <stb/stb_image_write.h>

#include "GlContextTest.h"
#include "render/environment/EnvironmentFiles.h"
#include "render/environment/EnvironmentLight.h"
#include "render/environment/PrefilterSource.h"
#include "scene/Environment.h"
#include "tests/support/EnvironmentReference.h"

namespace manylights {
namespace {

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

class EnvironmentLightTest : public GlContextTest {
public:
    // Each level of the chain prefiltered from `map`, as RGBA floats, rows from v = 0.
    static std::vector<std::vector<float>> prefilteredLevels(const EnvironmentImage& map)
    {
        const gl::LayeredTexture radiance("test radiance", EnvironmentLight::kRadianceFormat,
                                          EnvironmentLight::kRadianceWidth, EnvironmentLight::kRadianceWidth / 2,
                                          EnvironmentLight::kRadianceMips, EnvironmentLight::kRadianceLevels);
        const gl::Program program = EnvironmentLight::prefilterProgram(EnvironmentLight::kRadianceFormat);
        EnvironmentLight::prefilter(map, radiance, program);
        std::vector<std::vector<float>> levels;
        for (int level = 0; level < radiance.layers(); ++level) {
            const int mip = EnvironmentLight::radianceMip(level);
            std::vector<float> texels(static_cast<std::size_t>(radiance.levelWidth(mip)) * radiance.levelHeight(mip) *
                                      4);
            radiance.readLayer(mip, level, GL_RGBA, GL_FLOAT, texels.size() * sizeof(float), texels.data());
            levels.push_back(std::move(texels));
        }
        return levels;
    }

    // The width of layer `level` of the prefiltered radiance.
    static int levelWidth(int level)
    {
        return EnvironmentLight::kRadianceWidth >> EnvironmentLight::radianceMip(level);
    }

    // The largest |got − reference| / (tolerance) over every `step`-th texel of `level` (every
    // texel of the first and last rows, the poles', whatever the step), with the reference made
    // for `roughness`; above 1 means outside the tolerance.
    static double worstOfLevel(const test::EnvironmentTexelSum& reference, const std::vector<float>& texels, int level,
                               double roughness, int step, double relative = kRelativeTolerance,
                               double absolute = kAbsoluteTolerance)
    {
        const int width = levelWidth(level);
        const int height = width / 2;
        double worst = 0.0;
        for (int j = 0; j < height; ++j) {
            const bool pole = j == 0 || j == height - 1;
            if (!pole && j % step != step / 2)
                continue;
            for (int i = pole ? 0 : step / 2; i < width; i += pole ? 1 : step) {
                const glm::dvec3 n = environmentDirection({(i + 0.5) / width, (j + 0.5) / height});
                const glm::dvec3 want = reference.prefiltered(n, roughness);
                for (int c = 0; c < 3; ++c) {
                    const double got = texels[(static_cast<std::size_t>(j) * width + i) * 4 + c];
                    worst = std::max(worst, std::abs(got - want[c]) / (relative * want[c] + absolute));
                }
            }
        }
        return worst;
    }
};

TEST_F(EnvironmentLightTest, PrefilteredLevelsMatchTheCpuIntegral)
{
    const EnvironmentImage map = smoothMap();
    const test::EnvironmentTexelSum reference(map);
    const std::vector<std::vector<float>> levels = prefilteredLevels(map);
    ASSERT_EQ(levels.size(), static_cast<std::size_t>(EnvironmentLight::kRadianceLevels));
    for (int level = 0; level < EnvironmentLight::kRadianceLevels; ++level) {
        // Every texel of the small levels, a spread of the large ones.
        const int step = std::max(1, levelWidth(level) / 32);
        const double worst = worstOfLevel(reference, levels[static_cast<std::size_t>(level)], level,
                                          environmentLevelRoughness(level), step);
        EXPECT_LE(worst, 1.0) << "level " << level;
    }
}

TEST_F(EnvironmentLightTest, LevelOfTheWrongRoughnessFallsOutside)
{
    const EnvironmentImage map = smoothMap();
    const test::EnvironmentTexelSum reference(map);
    const std::vector<std::vector<float>> levels = prefilteredLevels(map);
    for (int level = 0; level + 1 < EnvironmentLight::kRadianceLevels; ++level) {
        const int step = std::max(1, levelWidth(level) / 32);
        const std::vector<float>& texels = levels[static_cast<std::size_t>(level)];
        EXPECT_GT(worstOfLevel(reference, texels, level, environmentLevelRoughness(level + 1), step), 1.0) << level;
        // Roughness taken as α: the lobe of r² instead of r.
        const double r = environmentLevelRoughness(level);
        EXPECT_GT(worstOfLevel(reference, texels, level, std::sqrt(r), step), 1.0) << level;
    }
}

// Every level of `map` within 3% of the reference at every `step`-th texel and every texel of
// the poles' rows.
void expectLevelsWithinThreePercent(const EnvironmentImage& map, int step)
{
    const test::EnvironmentTexelSum reference(map);
    const std::vector<std::vector<float>> levels = EnvironmentLightTest::prefilteredLevels(map);
    for (int level = 0; level < EnvironmentLight::kRadianceLevels; ++level) {
        const double worst =
            EnvironmentLightTest::worstOfLevel(reference, levels[static_cast<std::size_t>(level)], level,
                                               environmentLevelRoughness(level), step, 0.03, 0.0);
        EXPECT_LE(worst, 1.0) << "level " << level;
    }
}

TEST_F(EnvironmentLightTest, SunMapLevelsWithinThreePercentAtEveryTexel)
{
    const EnvironmentImage map = test::sunMap(128);
    // The map is as issue 48's: the sun's texel holds radiance in the thousands.
    float brightest = 0.0f;
    for (const glm::vec3& texel : map.radiance)
        brightest = std::max(brightest, texel.r);
    EXPECT_GT(brightest, 1000.0f);
    expectLevelsWithinThreePercent(map, 1);
}

TEST_F(EnvironmentLightTest, SunNearTheZenithWithinThreePercentAtThePoles)
{
    // A noon sun, 1.5° from the pole, in the narrow texels of the first row but one: every texel
    // of the rows at the poles, and every fourth of the others.
    expectLevelsWithinThreePercent(test::sunMap(128, environmentDirection({0.3, 1.5 / 180.0})), 4);
}

TEST_F(EnvironmentLightTest, SplitKeepsThePowerAndBoundsTheBrightTexels)
{
    const EnvironmentImage map = test::sunMap(128);
    const auto power = [](const EnvironmentImage& image) {
        glm::dvec3 sum(0.0);
        for (int j = 0; j < image.height; ++j)
            for (int i = 0; i < image.width; ++i)
                sum += glm::dvec3(image.at(i, j)) * environmentTexelSolidAngle(j, image.height);
        return sum;
    };
    const glm::dvec3 total = power(map);
    for (const std::size_t maxBright : {std::size_t{512}, std::size_t{3}}) {
        const PrefilterSource split = splitForPrefiltering(map, 64, maxBright);
        EXPECT_EQ(split.remainder.width, 64);
        EXPECT_LE(split.bright.size(), maxBright);
        EXPECT_GE(split.bright.size(), 1u);
        glm::dvec3 sum = power(split.remainder);
        for (const BrightTexel& texel : split.bright)
            sum += glm::dvec3(glm::vec3(texel.power));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sum[c], total[c], 1e-5 * total[c]) << maxBright;
        for (const glm::vec3& texel : split.remainder.radiance)
            EXPECT_LE(environmentLuminance(texel), split.threshold * (1.0f + 1e-6f));
    }
}

TEST_F(EnvironmentLightTest, LobeIntegralIsTheSumOverTheSphere)
{
    // W(α) against the midpoint rule over c = N·ω in [0, 1] with 2·10^6 steps.
    for (const double roughness : {0.2, 0.4, 0.6, 0.8, 0.95, 0.999, 1.0}) {
        const double a2 = std::pow(roughness, 4.0);
        constexpr int kSteps = 2000000;
        double sum = 0.0;
        for (int s = 0; s < kSteps; ++s) {
            const double c = (s + 0.5) / kSteps;
            const double t = (0.5 + 0.5 * c) * (a2 - 1.0) + 1.0;
            sum += a2 / (std::numbers::pi * t * t) * c * 2.0 * std::numbers::pi / kSteps;
        }
        EXPECT_NEAR(ggxLobeIntegral(roughness), sum, 1e-6 * sum) << roughness;
    }
}

TEST_F(EnvironmentLightTest, LevelZeroIsTheMapAtItsOwnResolution)
{
    // The built-in studio (512x256) as its own texels, not resampled to the chain's size.
    const EnvironmentLight light(Environment{.map = std::string(kStudioEnvironment), .look = {}});
    const EnvironmentImage map = studioEnvironment(kStudioEnvironmentHeight);
    ASSERT_EQ(light.map().width(), map.width);
    ASSERT_EQ(light.map().height(), map.height);
    EXPECT_EQ(light.radiance().width(), EnvironmentLight::kRadianceWidth);
    EXPECT_TRUE(light.warnings().empty());
    std::vector<float> texels(map.radiance.size() * 4);
    light.map().readLevel(0, GL_RGBA, GL_FLOAT, texels.size() * sizeof(float), texels.data());
    for (std::size_t t = 0; t < map.radiance.size(); ++t)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(texels[t * 4 + c], map.radiance[t][c]) << "texel " << t;
}

TEST_F(EnvironmentLightTest, MapWiderThanTheCapIsShownBoxFilteredWithOneWarning)
{
    // The cap made small for the test (kMaxMapWidth is 8192): a 128x64 map under a cap of 64.
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "manylights-environment-cap.hdr";
    const EnvironmentImage map = test::sunMap(64);
    ASSERT_TRUE(stbi_write_hdr(path.string().c_str(), map.width, map.height, 3, &map.radiance[0].r));
    const EnvironmentLight light(Environment{.map = path.string(), .look = {}}, 64);
    std::filesystem::remove(path);
    EXPECT_EQ(light.map().width(), 64);
    EXPECT_EQ(light.map().height(), 32);
    ASSERT_EQ(light.warnings().size(), 1u);
    EXPECT_EQ(light.warnings()[0], path.string() + ": environment map is 128x64, shown and reflected at 64x32, the "
                                                   "largest level 0 kept");
    // Without the cap: none.
    EXPECT_TRUE(EnvironmentLight(Environment{.map = std::string(kStudioEnvironment), .look = {}}).warnings().empty());
}

TEST_F(EnvironmentLightTest, NoEnvironmentBindsZeros)
{
    const EnvironmentLight none;
    EXPECT_FALSE(none.present());
    EXPECT_FALSE(none.showsBackground());
    float texel[4] = {1, 1, 1, 1};
    none.radiance().readLayer(0, 0, GL_RGBA, GL_FLOAT, sizeof texel, texel);
    EXPECT_EQ(texel[0] + texel[1] + texel[2], 0.0f);
    none.map().readLevel(0, GL_RGBA, GL_FLOAT, sizeof texel, texel);
    EXPECT_EQ(texel[0] + texel[1] + texel[2], 0.0f);
}

}  // namespace
}  // namespace manylights
