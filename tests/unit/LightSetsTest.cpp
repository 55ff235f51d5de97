// Generated lights (docs/scene-format.md `light_sets`): deterministic, prefix-stable, within bounds, and
// the --lights split over sets exact and proportional.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "scene/LightSets.h"

namespace manylights {
namespace {

LightSet pointSet(int count, std::uint32_t seed)
{
    LightSet set;
    set.count = count;
    set.seed = seed;
    set.type = LightType::Point;
    set.boxMin = {-20.0f, 0.2f, -20.0f};
    set.boxMax = {20.0f, 2.0f, 20.0f};
    set.range = {1.5f, 3.0f};
    set.intensity = {0.3f, 1.0f};
    return set;
}

LightSet spotSet(int count, std::uint32_t seed)
{
    LightSet set = pointSet(count, seed);
    set.type = LightType::Spot;
    set.cutoffDegrees = {20.0f, 45.0f};
    set.exponent = {0.0f, 8.0f};
    return set;
}

Scene sceneWith(std::vector<LightSet> sets)
{
    Scene scene;
    scene.lightSets = std::move(sets);
    return scene;
}

void expectSameLight(const Light& a, const Light& b)
{
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.intensity, b.intensity);
    EXPECT_EQ(a.falloff, b.falloff);
    EXPECT_EQ(a.range, b.range);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_EQ(a.cutoffDegrees, b.cutoffDegrees);
    EXPECT_EQ(a.exponent, b.exponent);
}

TEST(LightSets, SameSeedSameLights)
{
    const std::vector<Light> a = expandLights(sceneWith({pointSet(200, 7), spotSet(50, 9)}));
    const std::vector<Light> b = expandLights(sceneWith({pointSet(200, 7), spotSet(50, 9)}));
    ASSERT_EQ(a.size(), 250u);
    ASSERT_EQ(b.size(), 250u);
    for (std::size_t i = 0; i < a.size(); ++i)
        expectSameLight(a[i], b[i]);
}

TEST(LightSets, DifferentSeedDifferentLights)
{
    const std::vector<Light> a = expandLights(sceneWith({pointSet(20, 7)}));
    const std::vector<Light> b = expandLights(sceneWith({pointSet(20, 8)}));
    int samePositions = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        samePositions += a[i].position == b[i].position ? 1 : 0;
    EXPECT_EQ(samePositions, 0);
}

TEST(LightSets, FirstLightsStableWhenCountGrows)
{
    for (const LightSet& base : {pointSet(0, 3), spotSet(0, 3)}) {
        LightSet small = base;
        small.count = 10;
        LightSet large = base;
        large.count = 1000;
        const std::vector<Light> a = expandLights(sceneWith({small}));
        const std::vector<Light> b = expandLights(sceneWith({large}));
        ASSERT_EQ(a.size(), 10u);
        ASSERT_EQ(b.size(), 1000u);
        for (std::size_t i = 0; i < a.size(); ++i)
            expectSameLight(a[i], b[i]);
    }
}

// The draw order and the conversion to [0, 1) are part of the format (a scene must render the
// same lights on every standard library), so they are checked against std::mt19937 directly.
TEST(LightSets, DrawOrderAndConversionAreFixed)
{
    std::mt19937 rng(7);
    auto unit = [&] { return static_cast<float>(static_cast<std::uint32_t>(rng()) >> 8) * 0x1p-24f; };
    const LightSet set = pointSet(2, 7);
    const std::vector<Light> lights = expandLights(sceneWith({set}));
    ASSERT_EQ(lights.size(), 2u);
    for (const Light& light : lights) {
        const float x = -20.0f + 40.0f * unit();
        const float y = 0.2f + (2.0f - 0.2f) * unit();
        const float z = -20.0f + 40.0f * unit();
        const float range = 1.5f + 1.5f * unit();
        const float hue = unit();
        const float scale = 0.3f + 0.7f * unit();
        EXPECT_FLOAT_EQ(light.position.x, x);
        EXPECT_FLOAT_EQ(light.position.y, y);
        EXPECT_FLOAT_EQ(light.position.z, z);
        EXPECT_FLOAT_EQ(light.range, range);
        // The brightest channel of a fully saturated colour is 1, so it carries the scale.
        EXPECT_FLOAT_EQ(std::max({light.intensity.r, light.intensity.g, light.intensity.b}), scale);
        // Hue in sixths: 0 red, 1/3 green, 2/3 blue; a channel that is exactly zero names the sector.
        const int sector = std::min(static_cast<int>(hue * 6.0f), 5);
        const int zeroChannel[] = {2, 2, 0, 0, 1, 1};
        EXPECT_EQ(light.intensity[zeroChannel[sector]], 0.0f) << "hue " << hue;
    }
}

TEST(LightSets, PointLightsWithinTheirBounds)
{
    const LightSet set = pointSet(2000, 11);
    const std::vector<Light> lights = expandLights(sceneWith({set}));
    ASSERT_EQ(lights.size(), 2000u);
    std::set<int> hueSectors;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        EXPECT_EQ(light.type, LightType::Point);
        EXPECT_EQ(light.falloff, Falloff::Range);
        EXPECT_EQ(light.name, "set0[" + std::to_string(i) + "]");
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(light.position[axis], set.boxMin[axis]);
            EXPECT_LE(light.position[axis], set.boxMax[axis]);
        }
        EXPECT_GE(light.range, 1.5f);
        EXPECT_LE(light.range, 3.0f);
        const float brightest = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
        const float darkest = std::min({light.intensity.r, light.intensity.g, light.intensity.b});
        EXPECT_GE(brightest, 0.3f);
        EXPECT_LE(brightest, 1.0f);
        EXPECT_EQ(darkest, 0.0f);  // fully saturated
        const glm::vec3 c = light.intensity / brightest;
        hueSectors.insert((c.r == 1.0f ? 1 : 0) | (c.g == 1.0f ? 2 : 0) | (c.b == 1.0f ? 4 : 0));
    }
    // Red, green and blue each lead somewhere among 2000 random hues.
    EXPECT_TRUE(hueSectors.count(1) && hueSectors.count(2) && hueSectors.count(4));
}

TEST(LightSets, SpotLightsPointDownwardWithinTheirIntervals)
{
    LightSet set = spotSet(2000, 5);
    set.cutoffDegrees = {25.0f, 35.0f};
    set.exponent = {2.0f, 4.0f};
    const std::vector<Light> lights = expandLights(sceneWith({set}));
    ASSERT_EQ(lights.size(), 2000u);
    float maxTilt = 0.0f;
    for (const Light& light : lights) {
        EXPECT_EQ(light.type, LightType::Spot);
        EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-5f);
        const float tilt = glm::degrees(std::acos(std::clamp(-light.direction.y, -1.0f, 1.0f)));
        EXPECT_LE(tilt, 30.0f + 1e-3f);
        maxTilt = std::max(maxTilt, tilt);
        EXPECT_GE(light.cutoffDegrees, 25.0f);
        EXPECT_LE(light.cutoffDegrees, 35.0f);
        EXPECT_GE(light.exponent, 2.0f);
        EXPECT_LE(light.exponent, 4.0f);
    }
    EXPECT_GT(maxTilt, 25.0f);  // the tilt really is random, not always straight down
}

TEST(LightSets, ExplicitLightsComeFirst)
{
    Scene scene = sceneWith({pointSet(3, 1), spotSet(2, 2)});
    Light lamp;
    lamp.name = "lamp";
    lamp.falloff = Falloff::Classic;
    scene.lights.push_back(lamp);
    const std::vector<Light> lights = expandLights(scene);
    ASSERT_EQ(lights.size(), 6u);
    EXPECT_EQ(lights[0].name, "lamp");
    EXPECT_EQ(lights[0].falloff, Falloff::Classic);
    EXPECT_EQ(lights[1].name, "set0[0]");
    EXPECT_EQ(lights[3].name, "set0[2]");
    EXPECT_EQ(lights[4].name, "set1[0]");
    EXPECT_EQ(lights[4].type, LightType::Spot);
    EXPECT_EQ(lights[5].name, "set1[1]");
}

// A set's "casts_shadows" reaches each light it generates, at any --lights total.
TEST(LightSets, GeneratedLightsInheritTheSetsCastsShadows)
{
    LightSet unshadowed = spotSet(3, 2);
    unshadowed.castsShadows = false;
    Scene scene = sceneWith({pointSet(2, 1), unshadowed});
    for (const std::optional<int> total : {std::optional<int>(), std::optional<int>(50)}) {
        const std::vector<Light> lights = expandLights(scene, total);
        const std::size_t firstSetCount = total ? 20u : 2u;
        ASSERT_EQ(lights.size(), total ? 50u : 5u);
        for (std::size_t i = 0; i < lights.size(); ++i)
            EXPECT_EQ(lights[i].castsShadows, i < firstSetCount) << lights[i].name;
    }
}

TEST(LightSets, TotalOverridesCountsInProportion)
{
    const Scene scene = sceneWith({pointSet(100, 1), spotSet(300, 2)});
    const std::vector<Light> lights = expandLights(scene, 1000);
    ASSERT_EQ(lights.size(), 1000u);
    EXPECT_EQ(lights[249].name, "set0[249]");
    EXPECT_EQ(lights[250].name, "set1[0]");
    // The override grows a set without changing the lights it already had.
    const std::vector<Light> original = expandLights(scene);
    for (std::size_t i = 0; i < 100; ++i)
        expectSameLight(original[i], lights[i]);
    for (std::size_t i = 0; i < 300; ++i)
        expectSameLight(original[100 + i], lights[250 + i]);
    EXPECT_TRUE(expandLights(scene, 0).empty());
}

// range_reference_count: the drawn range times sqrt(reference / count), count being the
// set's count after --lights; every other draw is untouched.
TEST(LightSets, ReferenceCountScalesRangesBySquareRoot)
{
    LightSet plain = pointSet(1024, 21);
    LightSet scaled = plain;
    scaled.rangeReferenceCount = 1024;
    struct Case {
        int count;
        float factor;  // sqrt(1024 / count)
    };
    // Powers of four give exact factors; 1000 an irrational one, computed as the loader does.
    const Case cases[] = {{1024, 1.0f},
                          {4096, 0.5f},
                          {256, 2.0f},
                          {65536, 0.125f},
                          {1000, static_cast<float>(std::sqrt(1024.0 / 1000.0))}};
    for (const Case& c : cases) {
        const std::vector<Light> expected = expandLights(sceneWith({plain}), c.count);
        const std::vector<Light> actual = expandLights(sceneWith({scaled}), c.count);
        ASSERT_EQ(actual.size(), static_cast<std::size_t>(c.count));
        for (std::size_t i = 0; i < actual.size(); ++i) {
            EXPECT_EQ(actual[i].range, expected[i].range * c.factor) << "count " << c.count << " light " << i;
            EXPECT_EQ(actual[i].position, expected[i].position);
            EXPECT_EQ(actual[i].intensity, expected[i].intensity);
        }
    }
    // Without --lights the set's own count is the count: 1024 here, so the ranges are as drawn.
    const std::vector<Light> own = expandLights(sceneWith({scaled}));
    const std::vector<Light> ownPlain = expandLights(sceneWith({plain}));
    for (std::size_t i = 0; i < own.size(); ++i)
        EXPECT_EQ(own[i].range, ownPlain[i].range);
    EXPECT_EQ(rangeScaleFor(1024, 4096), 0.5);
    EXPECT_EQ(rangeScaleFor(3, 12), 0.5);
}

// Each set scales by its own count after the split, and a set without the key is untouched.
TEST(LightSets, ReferenceCountUsesEachSetsShareOfLights)
{
    LightSet first = pointSet(100, 1);
    first.rangeReferenceCount = 100;
    const LightSet second = spotSet(300, 2);
    // 1600 lights split 400 / 1200: the first set's ranges halve, the second's stay.
    const std::vector<Light> lights = expandLights(sceneWith({first, second}), 1600);
    const std::vector<Light> plain = expandLights(sceneWith({pointSet(100, 1), second}), 1600);
    ASSERT_EQ(lights.size(), 1600u);
    for (std::size_t i = 0; i < 400; ++i)
        EXPECT_EQ(lights[i].range, plain[i].range * 0.5f);
    for (std::size_t i = 400; i < 1600; ++i)
        EXPECT_EQ(lights[i].range, plain[i].range);
}

TEST(DistributeLightCount, HandWorkedExamples)
{
    auto counts = [](std::vector<int> setCounts, int total) {
        std::vector<LightSet> sets;
        for (int c : setCounts)
            sets.push_back(pointSet(c, 0));
        return distributeLightCount(sets, total);
    };
    EXPECT_EQ(counts({1024}, 5), std::vector<int>({5}));
    EXPECT_EQ(counts({1024, 0}, 100), std::vector<int>({100, 0}));
    // Quotas 10/3 each: floors 3, 3, 3 and one left over, which the earliest set takes.
    EXPECT_EQ(counts({1, 1, 1}, 10), std::vector<int>({4, 3, 3}));
    // Quotas 3.33 and 6.67: the larger remainder (the second set) gets the extra light.
    EXPECT_EQ(counts({1, 2}, 10), std::vector<int>({3, 7}));
    // Quotas 10/7 = 1.43, 20/7 = 2.86, 40/7 = 5.71: floors 1, 2, 5 leave two lights, which go
    // to the two largest remainders (6/7 and 5/7).
    EXPECT_EQ(counts({1, 2, 4}, 10), std::vector<int>({1, 3, 6}));
    // No proportions: an even split, the first sets taking the remainder.
    EXPECT_EQ(counts({0, 0, 0}, 8), std::vector<int>({3, 3, 2}));
    EXPECT_EQ(counts({0, 0}, 0), std::vector<int>({0, 0}));
    EXPECT_EQ(counts({5, 7}, 0), std::vector<int>({0, 0}));
    EXPECT_TRUE(counts({}, 10).empty());
}

TEST(DistributeLightCount, SumIsExactAndSplitIsProportional)
{
    std::mt19937 rng(1234);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<LightSet> sets;
        const int setCount = 1 + static_cast<int>(rng() % 7);
        std::int64_t sum = 0;
        for (int i = 0; i < setCount; ++i) {
            sets.push_back(pointSet(static_cast<int>(rng() % 5000), 0));
            sum += sets.back().count;
        }
        const int total = static_cast<int>(rng() % 2'000'000);
        const std::vector<int> counts = distributeLightCount(sets, total);
        ASSERT_EQ(counts.size(), sets.size());
        EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), std::int64_t{0}), total);
        for (std::size_t i = 0; i < sets.size(); ++i) {
            const double quota = sum == 0 ? static_cast<double>(total) / setCount
                                          : static_cast<double>(total) * sets[i].count / static_cast<double>(sum);
            EXPECT_LT(std::abs(counts[i] - quota), 1.0) << "set " << i << " of trial " << trial;
        }
    }
}

TEST(DistributeLightCount, LargeTotalsDoNotOverflow)
{
    const std::vector<LightSet> sets{pointSet(16'777'216, 0), pointSet(1, 0)};
    const std::vector<int> counts = distributeLightCount(sets, 2'000'000'000);
    ASSERT_EQ(counts.size(), 2u);
    EXPECT_EQ(static_cast<std::int64_t>(counts[0]) + counts[1], 2'000'000'000);
    EXPECT_EQ(counts[1], 119);  // 2e9 / 16777217 = 119.2
}

}  // namespace
}  // namespace manylights
