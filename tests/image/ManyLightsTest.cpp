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

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

// A 2 cm square facing the camera 10 m away (a few pixels at 1280x720), lit by point lights
// 5 cm in front of it with range 20 cm: nothing else in the scene, so the techniques that
// evaluate every light at every covered pixel stay fast. `lights` is the JSON of the lights
// (a light set, so that the file stays small however many lights it makes).
std::string onOneSpot(const std::string& lights)
{
    return R"({"camera": {"eye": [0, 0, 10], "look_at": [0, 0, 0], "fov_y": 45, "near": 1, "far": 20},)"
           R"("objects": [{"mesh": {"primitive": "plane", "size": [0.02, 0.02]},)"
           R"( "transform": {"rotate": [90, 0, 0]}, "material": {"diffuse": [0.8, 0.6, 0.4]}}],)" +
           lights + "}\n";
}

class ManyLightsOnOneSpot : public ::testing::TestWithParam<std::string> {};

TEST_P(ManyLightsOnOneSpot, SumsEveryLight)
{
    // Twice the driver's loop limit, and 16 light batches, all at one position with one range
    // (a set whose box is a point), in random hues.
    constexpr int kLights = 131072;
    static_assert(kLights > 65535 && kLights > 8 * static_cast<int>(kLightsPerBatch));
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    const std::string position = "[0.001, -0.002, 0.05]";
    writeFile(dir / "one.json",
              onOneSpot(R"("lights": [{"type": "point", "pos": )" + position + R"(, "intensity": [1, 1, 1], "range": 0.2}])"));
    writeFile(dir / "many.json", onOneSpot(R"("light_sets": [{"count": )" + std::to_string(kLights) +
                                           R"(, "seed": 5, "type": "point", "min": )" + position + R"(, "max": )" +
                                           position + R"(, "range": [0.2, 0.2], "intensity": [0.0005, 0.002]}])"));
    const std::vector<std::string> args = {"--size", "1280x720", "--gbuffer", "seed", "--technique", technique};
    const Image one = renderPfm((dir / "one.json").string(), dir / "one.pfm", args);
    const Image many = renderPfm((dir / "many.json").string(), dir / "many.pfm", args);
    ASSERT_EQ(one.rgb.size(), many.rgb.size());
    // Each light adds its intensity times what a unit light adds there, so the image is the
    // one-light image times the lights' summed intensity, per channel.
    const std::vector<Light> lights = expandLights(loadSceneFile(dir / "many.json"));
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
    constexpr double kRounding = kLights * 0x1p-24;
    static_assert(kRounding < 8e-3);
    int lit = 0;
    int failures = 0;
    for (std::size_t i = 0; i < one.rgb.size(); ++i) {
        const double expected = static_cast<double>(one.rgb[i]) * total[i % 3];
        lit += expected > 0.0;
        if (!(std::abs(many.rgb[i] - expected) <= 8e-3 * expected) && ++failures <= 5)
            ADD_FAILURE() << technique << ": value " << i << ": " << many.rgb[i] << ", expected " << expected;
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GE(lit, 3) << "the square should cover a pixel";
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, ManyLightsOnOneSpot, ::testing::ValuesIn(techniqueNames()),
                         test::techniqueTestName);

nlohmann::json countWork(const std::filesystem::path& dir, const std::string& scene,
                         const std::vector<std::string>& options)
{
    const std::filesystem::path stats = dir / "stats.json";
    std::vector<std::string> args = {"render", scene, "-o", (dir / "out.png").string(), "--count-work", "--stats",
                                     stats.string()};
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
        const nlohmann::json stats = countWork(dir, MANYLIGHTS_SOURCE_DIR "/tests/scenes/" + scene,
                                               {"--size", "1280x720", "--technique", technique});
        const auto inRange = stats["in_range_pairs"].get<std::uint64_t>();
        EXPECT_GT(inRange, 300000u) << scene;
        EXPECT_GE(stats["light_evaluations"].get<std::uint64_t>(), inRange) << technique << " on " << scene;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, WorkAtUserSizes, ::testing::ValuesIn(techniqueNames()),
                         test::techniqueTestName);

}  // namespace
}  // namespace manylights
