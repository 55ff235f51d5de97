// The environment's CPU side (scene/Environment.h, issue 42): the scene file's key, the
// equirectangular mapping as docs/scene-format.md states it, the built-in studio, and the
// irradiance's spherical harmonics against sums over the map's texels written here.
//
// Tolerances: the harmonics integrate each texel's rectangle exactly, in double, and are kept
// as floats, so where order 2 is exact (a uniform map, a sky and a ground) they agree with the
// formula to float rounding (1e-6 relative). For an asymmetric map, order 2 leaves out the
// clamped cosine's higher bands: |E − E_SH| / π ≤ (3/32) ∫ L dω / π, the largest gap between
// max(c, 0) and its order-2 expansion 3/32 + c/2 + 15c²/32 (at c = 0). That expansion itself,
// integrated over the texels here by the midpoint rule, is what the harmonics must give, to
// 1e-3 of ∫ L dω / π: the midpoint rule's error over 64-row texels (measured up to 3e-4 of it,
// its centre is not a texel's centroid in solid angle); a wrong l = 2 band is off by a tenth.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "SceneFileTestSupport.h"
#include "scene/Environment.h"

namespace manylights {
namespace {

glm::dvec3 texelDirection(const EnvironmentImage& map, int i, int j)
{
    return environmentDirection({(i + 0.5) / map.width, (j + 0.5) / map.height});
}

EnvironmentImage uniformMap(int height, glm::vec3 radiance)
{
    EnvironmentImage map{.width = 2 * height, .height = height, .radiance = {}};
    map.radiance.assign(static_cast<std::size_t>(map.width) * height, radiance);
    return map;
}

TEST(EnvironmentMapping, AxesLandWhereTheFormatSays)
{
    // −Z is the middle of the image, +X at u = 0.75, +Z at the left and right edges, +Y the top.
    EXPECT_NEAR(environmentUv({0, 0, -1}).x, 0.5, 1e-7);
    EXPECT_NEAR(environmentUv({0, 0, -1}).y, 0.5, 1e-7);
    EXPECT_NEAR(environmentUv({1, 0, 0}).x, 0.75, 1e-7);
    EXPECT_NEAR(environmentUv({-1, 0, 0}).x, 0.25, 1e-7);
    EXPECT_NEAR(std::abs(environmentUv({0, 0, 1}).x - 0.5), 0.5, 1e-7);
    EXPECT_NEAR(environmentUv({0, 1, 0}).y, 0.0, 1e-7);
    EXPECT_NEAR(environmentUv({0, -1, 0}).y, 1.0, 1e-7);
    for (const glm::dvec3 d : {glm::dvec3(0.3, 0.5, -0.8), glm::dvec3(-0.7, -0.2, 0.4), glm::dvec3(0.1, 0.9, 0.2)}) {
        const glm::dvec3 unit = glm::normalize(d);
        const glm::dvec3 back = environmentDirection(glm::dvec2(environmentUv(unit)));
        EXPECT_NEAR(glm::length(back - unit), 0.0, 1e-6);
    }
}

TEST(EnvironmentMapping, RotationTurnsTheContentCounterClockwiseSeenFromAbove)
{
    // Turned by 90°, what was at +X shows at −Z: −Z is sampled at +X.
    const glm::dvec3 sampled = environmentLookup({0, 0, -1}, 90.0);
    EXPECT_NEAR(glm::length(sampled - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(environmentLookup({0.3, 0.4, 0.5}, 0.0) - glm::dvec3(0.3, 0.4, 0.5)), 0.0, 1e-15);
}

TEST(EnvironmentMapping, TexelSolidAnglesCoverTheSphere)
{
    double total = 0.0;
    for (int j = 0; j < 16; ++j)
        total += 32 * environmentTexelSolidAngle(j, 16);
    EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-12);
}

TEST(EnvironmentIrradiance, UniformMapGivesItsRadiance)
{
    const IrradianceSh sh = irradianceSh(uniformMap(32, {0.5f, 1.0f, 2.0f}));
    for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0.6, 0, -0.8), glm::dvec3(0, -1, 0)}) {
        const glm::dvec3 e = irradianceOverPi(sh, n);
        EXPECT_NEAR(e.r, 0.5, 1e-6);
        EXPECT_NEAR(e.g, 1.0, 1e-6);
        EXPECT_NEAR(e.b, 2.0, 2e-6);
    }
}

TEST(EnvironmentIrradiance, SkyAndGroundAreExact)
{
    // Lt above the horizon, Lb below: E(n) / π = Lt (1 + n_y) / 2 + Lb (1 − n_y) / 2.
    const double top = 1.5;
    const double bottom = 0.25;
    EnvironmentImage map = uniformMap(32, glm::vec3(static_cast<float>(top)));
    for (int j = 16; j < 32; ++j)
        for (int i = 0; i < 64; ++i)
            map.at(i, j) = glm::vec3(static_cast<float>(bottom));
    const IrradianceSh sh = irradianceSh(map);
    for (const glm::dvec3 d : {glm::dvec3(0, 1, 0), glm::dvec3(0.6, 0.3, -0.5), glm::dvec3(-0.2, -0.9, 0.1)}) {
        const glm::dvec3 n = glm::normalize(d);
        const double want = top * (1 + n.y) / 2 + bottom * (1 - n.y) / 2;
        EXPECT_NEAR(irradianceOverPi(sh, n).r, want, 1e-6 * want);
    }
}

TEST(EnvironmentIrradiance, AsymmetricPatchWithinTheOrderTwoBound)
{
    // One small bright patch off every axis on a dim map.
    EnvironmentImage map = uniformMap(64, glm::vec3(0.05f));
    const glm::dvec3 centre = glm::normalize(glm::dvec3(0.5, 0.6, -0.62));
    double power = 0.0;  // ∫ L dω
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            if (glm::dot(texelDirection(map, i, j), centre) > std::cos(8.0 * std::numbers::pi / 180.0))
                map.at(i, j) = glm::vec3(20.0f);
            power += map.at(i, j).r * environmentTexelSolidAngle(j, map.height);
        }
    const IrradianceSh sh = irradianceSh(map);
    const double bound = 3.0 / 32.0 * power / std::numbers::pi;  // of E / π
    double largest = 0.0;
    for (const glm::dvec3 d : {centre, glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(-0.5, 0.2, 0.7),
                               glm::dvec3(0.1, -1, 0.2), glm::dvec3(0.8, -0.1, 0.6)}) {
        const glm::dvec3 n = glm::normalize(d);
        double exact = 0.0;   // E / π by the midpoint rule over the texels
        double order2 = 0.0;  // the same with the clamped cosine's order-2 expansion
        for (int j = 0; j < map.height; ++j)
            for (int i = 0; i < map.width; ++i) {
                const double c = glm::dot(n, texelDirection(map, i, j));
                const double weight = map.at(i, j).r * environmentTexelSolidAngle(j, map.height) / std::numbers::pi;
                exact += weight * std::max(c, 0.0);
                order2 += weight * (3.0 / 32.0 + c / 2.0 + 15.0 / 32.0 * c * c);
            }
        const double got = irradianceOverPi(sh, n).r;
        EXPECT_NEAR(got, order2, 1e-3 * power / std::numbers::pi)
            << "n = (" << n.x << ", " << n.y << ", " << n.z << ")";
        EXPECT_LE(std::abs(got - exact), bound);
        largest = std::max(largest, std::abs(got - exact) / bound);
    }
    // The bound is not vacuous here: some normal comes within a third of it.
    EXPECT_GT(largest, 0.3);
}

TEST(StudioEnvironment, HasSkyFloorAndBrightPatches)
{
    const EnvironmentImage studio = studioEnvironment(64);
    ASSERT_EQ(studio.width, 128);
    ASSERT_EQ(studio.height, 64);
    float brightest = 0.0f;
    for (const glm::vec3& texel : studio.radiance) {
        ASSERT_TRUE(std::isfinite(texel.r) && texel.r >= 0.0f && texel.g >= 0.0f && texel.b >= 0.0f);
        brightest = std::max(brightest, texel.r);
    }
    const glm::vec3 zenith = studio.at(64, 0);
    const glm::vec3 nadir = studio.at(64, 63);
    EXPECT_GT(zenith.r, 3.0f * nadir.r);
    EXPECT_GT(brightest, 5.0f * zenith.r);
}

TEST(EnvironmentKey, IsReadWithItsDefaults)
{
    const Scene builtin = test::parse(R"json({"environment": {"map": "builtin:studio"}})json");
    ASSERT_TRUE(builtin.environment);
    EXPECT_EQ(builtin.environment->map, "builtin:studio");
    EXPECT_EQ(builtin.environment->look, EnvironmentLook{});
    EXPECT_FALSE(test::parse("{}").environment);

    // A file is resolved relative to the scene file; its contents are read by the render layer.
    const auto dir = std::filesystem::temp_directory_path() / "manylights-environment-key";
    std::filesystem::create_directories(dir / "maps");
    std::ofstream(dir / "maps" / "Sky.HDR") << "";
    const Scene file = parseScene(
        R"json({"environment": {"map": "maps/Sky.HDR", "intensity": 2.5, "rotation": -30, "background": true}})json",
        "scene.json", dir);
    ASSERT_TRUE(file.environment);
    EXPECT_EQ(file.environment->map, (dir / "maps" / "Sky.HDR").string());
    EXPECT_EQ(file.environment->look,
              (EnvironmentLook{.intensity = 2.5f, .rotationDegrees = -30.0f, .background = true}));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace manylights
