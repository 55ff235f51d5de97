// No light dropped at any count or size (issue 11). Mesa's llvmpipe silently ends a shader's
// loops after 65,535 iterations in all (tests/gl/GlTest.cpp, LoopLimit), so a technique
// that looped over more lights in one invocation lost the rest without an error; every
// technique now takes lights in batches (render/LightBatches.h). These tests put more lights
// on one spot than that limit, and check every technique's work against the pairs in range
// at a size people render at.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/LightBatches.h"
#include "render/Technique.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;

const std::string kScenes = MANYLIGHTS_SOURCE_DIR "/tests/scenes/";

class ManyLightsOnOneSpot : public ::testing::TestWithParam<std::string> {};

// tests/scenes/lights_on_one_spot.json: a 2 cm square facing the camera 10 m away (a few
// pixels at 1280x720) under 131,072 point lights at one position 5 cm in front of it, with
// one range (a light set whose box is a point) and random hues. Nothing else is in the
// scene, so the techniques that evaluate every light at every covered pixel stay fast.
// one_light_on_one_spot.json: the same with one white light of intensity 1.
TEST_P(ManyLightsOnOneSpot, SumsEveryLight)
{
    // Twice the driver's loop limit, and 16 light batches.
    constexpr int kLights = 131072;
    static_assert(kLights > 65535 && kLights > 8 * static_cast<int>(kLightsPerBatch));
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    const std::vector<std::string> args = {"--size", "1280x720", "--gbuffer", "seed", "--technique", technique};
    const Image one = renderPfm(kScenes + "one_light_on_one_spot.json", dir / "one.pfm", args);
    const Image many = renderPfm(kScenes + "lights_on_one_spot.json", dir / "many.pfm", args);
    ASSERT_EQ(one.rgb.size(), many.rgb.size());
    // Each light adds its intensity times what a unit light adds there, so the image is the
    // one-light image times the lights' summed intensity, per channel.
    const std::vector<Light> lights = expandLights(loadSceneFile(kScenes + "lights_on_one_spot.json"));
    ASSERT_EQ(lights.size(), static_cast<std::size_t>(kLights));
    double total[3] = {0.0, 0.0, 0.0};
    for (const Light& light : lights)
        for (int c = 0; c < 3; ++c)
            total[c] += light.intensity[c];
    // Summing n positive float32 terms one after another errs by at most (n - 1) · 2^-24 of
    // the sum (each addition rounds once): 7.8e-3 for the volume techniques, which blend
    // every light into the image separately, and less for those that sum batches of 8,192
    // in the shader. So 8e-3 relative is float rounding, while a technique that stops at
    // 65,535 lights is off by half.
    constexpr double kTolerance = 8e-3;
    static_assert(kLights * 0x1p-24 < kTolerance);
    Image expected = one;
    int lit = 0;
    for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
        expected.rgb[i] = static_cast<float>(static_cast<double>(one.rgb[i]) * total[i % 3]);
        lit += expected.rgb[i] > 0.0f;
    }
    test::expectImagesNear(expected, many, {.relative = kTolerance}, technique);
    EXPECT_GE(lit, 3) << "the square should cover a pixel";
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, ManyLightsOnOneSpot, ::testing::ValuesIn(techniqueNames()),
                         test::techniqueTestName);

nlohmann::json countWork(const std::filesystem::path& dir, const std::string& scene,
                         const std::vector<std::string>& options)
{
    const std::filesystem::path stats = dir / "stats.json";
    std::vector<std::string> args = {"render",       scene,     "-o",          (dir / "out.png").string(),
                                     "--count-work", "--stats", stats.string()};
    args.insert(args.end(), options.begin(), options.end());
    test::runCliOrFail(args);
    std::ifstream in(stats);
    return nlohmann::json::parse(in);
}

class WorkAtUserSizes : public ::testing::TestWithParam<std::string> {};

// No technique evaluates fewer pairs than are in range, which would mean dropped light, on
// scenes with spots, a wide spot, an unbounded light and a light over most of the view.
TEST_P(WorkAtUserSizes, EvaluationsCoverThePairsInRange)
{
    const auto dir = scratchDirectory();
    const std::string& technique = GetParam();
    for (const std::string scene : {"big_light.json", "spots_and_points.json"}) {
        const nlohmann::json stats = countWork(dir, kScenes + scene, {"--size", "1280x720", "--technique", technique});
        const auto inRange = stats["in_range_pairs"].get<std::uint64_t>();
        EXPECT_GT(inRange, 300000u) << scene;
        EXPECT_GE(stats["light_evaluations"].get<std::uint64_t>(), inRange) << technique << " on " << scene;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, WorkAtUserSizes, ::testing::ValuesIn(techniqueNames()),
                         test::techniqueTestName);

}  // namespace
}  // namespace manylights
