// The global list of tiled and clustered (render/culling/ClusterLists.h): lights whose screen
// rectangle covers at least kGlobalLightGridFraction of the grid get no pairs and are walked by
// every pixel before its cluster's list. The scenes are made here: a floor and a ball under a
// few lights whose ranges cover the whole scene and many whose ranges cover a few tiles.
//
// Tolerance against forward: test::kAgreementTolerance (TechniqueAgreementTest.cpp), with the
// seed G-buffer, whose inputs are exact. The one difference left is the order of the sum: a
// pixel adds its global lights, then its cluster's, each in the lights' order, where forward
// adds them all in the lights' order. Each addition of non-negative terms rounds by at most
// 2^-24 of the sum, so two orders of n terms differ by at most 2 (n - 1) 2^-24 relative: below
// the tolerance's 1e-5 for n <= 84. No pixel of these scenes has 84 lights in range but those of
// the scene whose lights are all global or all listed, which forward's order (index order)
// sums the same way. A light dropped or added twice is a whole light's difference.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/culling/ClusterLists.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;

// A floor and a ball, lit by `wide` lights whose ranges (40-50 m) reach every surface of the
// 12 m floor, and `narrow` lights of 0.3-0.6 m scattered over it.
std::string writeScene(const std::filesystem::path& dir, int wide, int narrow)
{
    const auto lightSet = [](int count, int seed, double minRange, double maxRange, double intensity) {
        return nlohmann::json{{"count", count},
                              {"seed", seed},
                              {"type", "point"},
                              {"min", {-6, 0.2, -6}},
                              {"max", {6, 2.5, 6}},
                              {"range", {minRange, maxRange}},
                              {"intensity", {intensity / 4, intensity}}};
    };
    nlohmann::json scene = {
        {"camera", {{"eye", {0, 5, 8}}, {"look_at", {0, 0, 0}}, {"fov_y", 50}, {"near", 0.1}, {"far", 50}}},
        {"light_sets", nlohmann::json::array()},
        {"materials", {{"m", {{"diffuse", {0.7, 0.7, 0.7}}, {"specular", {0.3, 0.3, 0.3}}, {"shininess", 16}}}}},
        {"objects",
         {{{"mesh", {{"primitive", "plane"}, {"size", {12, 12}}}}, {"material", "m"}},
          {{"mesh", {{"primitive", "sphere"}, {"radius", 1}}},
           {"material", "m"},
           {"transform", {{"translate", {0, 1, 0}}}}}}}};
    if (wide > 0)
        scene["light_sets"].push_back(lightSet(wide, 3, 40, 50, 0.02));
    if (narrow > 0)
        scene["light_sets"].push_back(lightSet(narrow, 5, 0.3, 0.6, 0.5));
    const auto path = dir / ("lights-" + std::to_string(wide) + "-" + std::to_string(narrow) + ".json");
    test::writeFile(path, scene.dump());
    return path.string();
}

nlohmann::json readStats(const std::filesystem::path& path)
{
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

class GlobalLights : public ::testing::TestWithParam<std::string> {};

// A few global lights among many narrow ones: the image is forward's, every pair in range is
// evaluated once (each listed light, global or not, is tested against the pixel's surface
// before it is shaded), and the image is the same bytes on every run although the candidates
// reach the global list in whatever order the GPU ran them.
TEST_P(GlobalLights, WideAmongNarrowMatchForwardAndEvaluateThePairsInRange)
{
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    constexpr int kWide = 6;
    const std::string scene = writeScene(dir, kWide, 3000);
    const std::vector<std::string> size = {"--size", "320x180", "--gbuffer", "seed"};
    auto args = size;
    args.insert(args.end(), {"--technique", "forward"});
    const Image forward = renderPfm(scene, dir / "forward.pfm", args);
    args = size;
    args.insert(args.end(), {"--technique", technique, "--stats", (dir / "stats.json").string()});
    const Image image = renderPfm(scene, dir / "image.pfm", args);
    test::expectImagesNear(forward, image, test::kAgreementTolerance, technique);
    args.insert(args.end(), {"--frames", "2"});
    EXPECT_EQ(renderPfm(scene, dir / "again.pfm", args).rgb, image.rgb) << "run to run";

    args = size;
    args.insert(args.end(), {"--technique", technique, "--count-work", "--stats", (dir / "work.json").string()});
    renderPfm(scene, dir / "work.pfm", args);
    const nlohmann::json work = readStats(dir / "work.json");
    const auto inRange = work["in_range_pairs"].get<std::uint64_t>();
    EXPECT_GT(inRange, 320u * 180u * kWide / 2) << "the wide lights should reach most pixels";
    EXPECT_EQ(work["light_evaluations"].get<std::uint64_t>(), inRange);
    EXPECT_EQ(work["global_lights"].get<int>(), kWide);
    EXPECT_GT(work["cluster_pairs"].get<double>(), 1000.0) << "the narrow lights keep their pairs";
    EXPECT_GE(work["cluster_list_visits"].get<double>(), work["light_evaluations"].get<double>());
}

// Every light reaches the whole view: no pairs, every light in the global list.
TEST_P(GlobalLights, LightsOverTheWholeViewHaveNoPairs)
{
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    constexpr int kWide = 300;
    const std::string scene = writeScene(dir, kWide, 0);
    const Image forward = renderPfm(scene, dir / "forward.pfm", {"--size", "160x90", "--technique", "forward"});
    const Image image = renderPfm(scene, dir / "image.pfm",
                                  {"--size", "160x90", "--gbuffer", "seed", "--technique", technique, "--count-work",
                                   "--stats", (dir / "work.json").string()});
    const nlohmann::json work = readStats(dir / "work.json");
    // All lights global, summed in the lights' order as forward sums them: on llvmpipe, where
    // both run the same arithmetic (TechniqueAgreementTest.cpp), the same bits. (llvmpipe's
    // atomics hand out the candidates' slots nearly in the lights' order, so whether the list
    // is sorted is tests/gl/GlobalLightOrderTest.cpp's to check.)
    if (work["device"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(image.rgb, forward.rgb) << technique;
    }
    test::expectImagesNear(forward, image, test::kAgreementTolerance, technique);
    EXPECT_EQ(work["global_lights"].get<int>(), kWide);
    EXPECT_EQ(work["cluster_pairs"].get<double>(), 0.0);
    EXPECT_EQ(work["light_evaluations"], work["in_range_pairs"]);
    // Each covered pixel walks the global list once.
    EXPECT_EQ(work["cluster_list_visits"].get<std::uint64_t>() % kWide, 0u);
}

// More candidates than the global list holds: none is global, all get pairs as wide lights, and
// every one still lights the image (forward's, in the lights' order).
TEST_P(GlobalLights, MoreThanTheCapacityAllFallBackToPairs)
{
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    constexpr int kWide = static_cast<int>(kGlobalLightCapacity) + 100;
    const std::string scene = writeScene(dir, kWide, 0);
    const Image forward = renderPfm(scene, dir / "forward.pfm", {"--size", "64x48", "--technique", "forward"});
    const Image image = renderPfm(scene, dir / "image.pfm",
                                  {"--size", "64x48", "--gbuffer", "seed", "--technique", technique, "--count-work",
                                   "--stats", (dir / "work.json").string()});
    test::expectImagesNear(forward, image, test::kAgreementTolerance, technique);
    const nlohmann::json work = readStats(dir / "work.json");
    EXPECT_EQ(work["global_lights"].get<int>(), 0);
    EXPECT_EQ(work["light_evaluations"], work["in_range_pairs"]);
    EXPECT_EQ(work["light_evaluations"].get<std::uint64_t>() % kWide, 0u) << "every light at every covered pixel";
    EXPECT_GE(work["cluster_pairs"].get<double>(), static_cast<double>(kWide));
}

INSTANTIATE_TEST_SUITE_P(ListTechniques, GlobalLights, ::testing::Values("tiled", "clustered"));

// The measuring knobs of the lists and of the CPU's culling (docs/cli.md) are read like a user's
// input: a bad value of `variable` is one line naming the variable, `expected` and the value,
// exit status 1, and the earlier image of each of `techniques` kept; each of `good` is taken.
void expectKnobChecked(const std::string& variable, const std::vector<std::string>& bad, const std::string& expected,
                       const std::vector<std::string>& good,
                       const std::vector<std::string>& techniques = {"clustered", "tiled"})
{
    const auto dir = scratchDirectory();
    const std::string image = (dir / "old.png").string();
    for (const std::string& technique : techniques) {
        const std::vector<std::string> args = {"render", "-o", image, "--size", "64x36", "--technique", technique};
        ASSERT_EQ(test::runExecutable(args).exitCode, 0);
        const auto before = std::filesystem::last_write_time(image);
        for (const std::string& value : bad) {
            const test::ProcessResult result = test::runExecutable(args, variable + "=" + value);
            EXPECT_EQ(result.exitCode, 1) << value << ": " << result.stderrText;
            EXPECT_NE(result.stderrText.find(variable + ": " + expected + ", got '" + value + "'"), std::string::npos)
                << result.stderrText;
            EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
            EXPECT_EQ(std::filesystem::last_write_time(image), before) << value;
        }
        for (const std::string& value : good)
            EXPECT_EQ(test::runExecutable(args, variable + "=" + value).exitCode, 0) << variable << "=" << value;
    }
}

// A number > 0 (above 1: only unbounded lights would be global).
TEST(GlobalLightFraction, ABadValueIsExitOneAndKeepsTheOldImage)
{
    expectKnobChecked("MANYLIGHTS_GLOBAL_LIGHT_FRACTION", {"abc", "0", "-1", "nan", "inf", "0.5x"},
                      "expected a number > 0", {"0.25", "2"});
}

// A whole number of lights up to kMaskedListLights, 0 included (every frame sorts its pairs;
// render/culling/ClusterLists.h: more would take the masks' walk past the loop bound).
TEST(MaskedListLights, ABadValueIsExitOneAndKeepsTheOldImage)
{
    expectKnobChecked("MANYLIGHTS_MASKED_LIST_LIGHTS", {"abc", "-1", "1.5", "12x", "", "16385", "99999999999"},
                      "expected a whole number of lights up to 16384", {"0", "16384"});
}

// tiled-quads' culling threads (render/culling/TileCulling.h): a whole number from 1 to 256.
TEST(CullingThreads, ABadValueIsExitOneAndKeepsTheOldImage)
{
    expectKnobChecked("MANYLIGHTS_CULLING_THREADS", {"abc", "0", "-1", "1.5", "", "257"},
                      "expected a whole number of threads from 1 to 256", {"1", "3"}, {"tiled-quads"});
}

}  // namespace
}  // namespace manylights
