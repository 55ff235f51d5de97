// No light dropped at any count or size (issue 11). Mesa's llvmpipe silently ends a shader's
// loops after 65,535 iterations in all (tests/gl/GlTest.cpp, LoopLimit), so a technique
// that looped over more lights in one invocation lost the rest without an error; every
// technique now takes lights in batches (render/programs/LightBatches.h). These tests put more lights
// on one spot than that limit, and check every technique's work against the pairs in range
// at a size people render at.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/culling/ClusterLists.h"
#include "render/programs/LightBatches.h"
#include "render/techniques/Technique.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;

class ManyLightsOnOneSpot : public ::testing::TestWithParam<std::string> {};

// The spot scenes at a quarter of 1280x720 through a camera of 11.25° (tan 5.625° is a quarter of
// tan 22.5° within 5%): the square and each light's sphere cover the pixels (and the 16-pixel
// tiles) they cover at 1280x720 through the scenes' 45°, within 5%, so every technique meets the
// same lights per pixel and per tile, at a sixteenth of the pixels that the techniques walking
// every light at every pixel pay for.
const std::vector<std::string> kSpotView = {"--size", "320x180", "--fov-y", "11.25"};
constexpr double kSpotViewHalfHeight = 90.0;
constexpr double kSpotViewHalfFovDegrees = 11.25 / 2.0;

// `scene` of tests/scenes/ written to `dir` with every light's range `range`.
std::string withRange(const std::filesystem::path& dir, const std::string& scene, double range)
{
    nlohmann::json json = nlohmann::json::parse(std::ifstream(test::kTestScenes + scene));
    if (json.contains("light_sets"))
        for (auto& set : json["light_sets"])
            set["range"] = {range, range};
    if (json.contains("lights"))
        for (auto& light : json["lights"])
            light["range"] = range;
    const auto path = dir / ("range-" + std::to_string(range) + "-" + scene);
    test::writeFile(path, json.dump());
    return path.string();
}

// tests/scenes/lights_on_one_spot.json: a 2 cm square facing the camera 10 m away (a few
// pixels at 1280x720, and through kSpotView) under 131,072 point lights at one position 5 cm
// in front of it, with one range (a light set whose box is a point) and random hues. Nothing
// else is in the scene, so the techniques that evaluate every light at every covered pixel stay
// fast. The test shortens the range from 0.2 to 0.07 m, which still reaches every point of the
// square and of the pane below (at most 5.2 cm from the lights), so that the volume techniques,
// which draw each light's sphere (lights on one spot take a stencil batch each), fill a ninth of
// the pixels.
// one_light_on_one_spot.json: the same with one white light of intensity 1.
TEST_P(ManyLightsOnOneSpot, SumsEveryLight)
{
    // Twice the driver's loop limit, and 16 light batches.
    constexpr int kLights = 131072;
    static_assert(kLights > 65535 && kLights > 8 * static_cast<int>(kLightsPerBatch));
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    // Each light adds its intensity times what a unit light adds there, so the image is the
    // one-light image times the lights' summed intensity, per channel.
    constexpr double kRange = 0.07;
    const std::vector<Light> lights = expandLights(loadSceneFile(withRange(dir, "lights_on_one_spot.json", kRange)));
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

    // The same with a transparent pane between the square and the camera (issue 16): a pane of
    // opacity 0.5 facing the lights, 5 cm in front of them, drawn by the transparency pass in
    // 16 batches of its grid (or of every light, under forward). The pixel is 0.5 · pane +
    // 0.5 · square, each a sum over the lights, so the one-light rule still holds.
    const auto withPane = [&](const std::string& scene) {
        nlohmann::json json = nlohmann::json::parse(std::ifstream(withRange(dir, scene, kRange)));
        json["objects"].push_back({{"mesh", {{"primitive", "plane"}, {"size", {0.02, 0.02}}}},
                                   {"transform", {{"translate", {0, 0, 0.1}}, {"rotate", {-90, 0, 0}}}},
                                   {"material", {{"diffuse", {0.3, 0.5, 0.9}}, {"opacity", 0.5}}}});
        const auto path = dir / ("pane-" + scene);
        test::writeFile(path, json.dump());
        return path.string();
    };
    std::vector<std::string> args = kSpotView;
    args.insert(args.end(), {"--gbuffer", "seed", "--technique", technique});
    Image squareAlone;
    for (const auto& [label, one, many] :
         {std::tuple{std::string("square"), withRange(dir, "one_light_on_one_spot.json", kRange),
                     withRange(dir, "lights_on_one_spot.json", kRange)},
          std::tuple{std::string("square behind a pane"), withPane("one_light_on_one_spot.json"),
                     withPane("lights_on_one_spot.json")}}) {
        const Image oneImage = renderPfm(one, dir / "one.pfm", args);
        const Image manyImage = renderPfm(many, dir / "many.pfm", args);
        Image expected = oneImage;
        int lit = 0;
        for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
            expected.rgb[i] = static_cast<float>(static_cast<double>(oneImage.rgb[i]) * total[i % 3]);
            lit += expected.rgb[i] > 0.0f;
        }
        test::expectImagesNear(expected, manyImage, {.relative = kTolerance}, technique + ", " + label);
        EXPECT_GE(lit, 3) << label << ": the square should cover a pixel";
        if (squareAlone.rgb.empty()) {
            squareAlone = oneImage;
            continue;
        }
        // The pane is there and lit: its blue shifts the square's colour (kd 0.3, 0.5, 0.9 over
        // 0.8, 0.6, 0.4), so the check above was not of the square alone.
        int bluer = 0;
        for (std::size_t i = 2; i < oneImage.rgb.size(); i += 3)
            bluer += oneImage.rgb[i] > 1.1f * squareAlone.rgb[i] + 1e-6f;
        EXPECT_GE(bluer, 3) << technique << ": the pane should tint the square";
    }
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
        const nlohmann::json stats =
            countWork(dir, test::kTestScenes + scene, {"--size", "1280x720", "--technique", technique});
        const auto inRange = stats["in_range_pairs"].get<std::uint64_t>();
        EXPECT_GT(inRange, 300000u) << scene;
        EXPECT_GE(stats["light_evaluations"].get<std::uint64_t>(), inRange) << technique << " on " << scene;
    }
}

// 262,144 small point and spot lights (tests/scenes/small_lights_262144.json) around a floor, a
// box and a ball: the light lists of clustered and tiled (render/culling/ClusterLists.h) against
// deferred, which walks every light at every pixel. At 96x72 the longest lists pass 4,096
// lights, so the passes over the long lists' tiles run too, and the first frame's storage is
// too small, so the frame is redone. The seed G-buffer keeps every input exact, so the images
// differ only in the order of the sums: deferred adds a light batch at a time, the lists add
// the lights in range in the lights' order. Each addition of positive terms rounds by at most
// 2^-24 of the sum, and no pixel here has more than 1,000 lights in range (the list of its
// cluster is shorter than 20,000 and the pixels' reach tests pass far fewer): 1,000 · 2^-24 =
// 6e-5, so 1e-4 relative, while a dropped light changes a pixel by a whole light.
TEST(SmallLights262144, ClusteredAndTiledEqualDeferredAndEachOtherRunToRun)
{
    const auto dir = scratchDirectory();
    const std::string scene = test::kTestScenes + "small_lights_262144.json";
    const std::vector<std::string> common = {"--size", "96x72", "--gbuffer", "seed"};
    const auto render = [&](const std::string& technique, const std::string& name,
                            const std::vector<std::string>& more = {}) {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"--technique", technique});
        args.insert(args.end(), more.begin(), more.end());
        return renderPfm(scene, dir / name, args);
    };
    const auto stats = [&](const std::string& name) {
        std::ifstream in(dir / name);
        return nlohmann::json::parse(in);
    };
    const Image reference = render("deferred", "deferred.pfm");
    int lit = 0;
    for (float value : reference.rgb)
        lit += value > 0.05f;
    EXPECT_GT(lit, 3000) << "most of the floor should be lit";
    for (const std::string technique : {"clustered", "tiled"}) {
        const Image image = render(technique, technique + ".pfm", {"--stats", (dir / "one.json").string()});
        test::expectImagesNear(reference, image, {.relative = 1e-4, .absolute = 1e-6}, technique);
        // The lists are sorted by a stable sort, whatever order the GPU ran the writes in: the
        // same scene gives the same bytes, here from the third frame of a run.
        const Image third =
            render(technique, technique + "-again.pfm", {"--frames", "2", "--stats", (dir / "three.json").string()});
        EXPECT_EQ(third.rgb, image.rgb) << technique << " run to run";
        // The storage planned from a frame holds the next: only the first frame is redone.
        const nlohmann::json one = stats("one.json");
        EXPECT_GE(one["cluster_rebuilds"].get<double>(), 1.0) << technique;
        EXPECT_EQ(stats("three.json")["cluster_rebuilds"], one["cluster_rebuilds"]) << technique;
        EXPECT_GT(one["longest_cluster_list"].get<double>(), kClusterListPart) << technique;
    }
    // Every pair in range is evaluated; the reach test skips the listed lights that do not
    // reach the pixel, so the walk visits more than it evaluates.
    const nlohmann::json work = countWork(dir, scene, {"--size", "96x72", "--technique", "clustered"});
    const auto inRange = work["in_range_pairs"].get<double>();
    EXPECT_GE(work["light_evaluations"].get<double>(), inRange);
    EXPECT_GT(work["cluster_list_visits"].get<double>(), work["light_evaluations"].get<double>());
}

// The lights on one spot again, each with a range of 0.8 m: at 10 m and 1280x720 (and through
// kSpotView) its sphere is about 140 pixels across on screen, over 64 tiles of 16 pixels, so every one of the 131,072
// is a wide light of the light lists (render/culling/ClusterLists.h), a workgroup each. That is
// more workgroups than a dispatch may have along x (65,535 is all GL promises), so the list of
// wide lights goes on into the dispatch's z. The image is still the one-light image times the
// summed intensities (the rule and the tolerance of SumsEveryLight above).
class WideLightsOnOneSpot : public ::testing::TestWithParam<std::string> {};

TEST_P(WideLightsOnOneSpot, SumsEveryLight)
{
    const std::string& technique = GetParam();
    const auto dir = scratchDirectory();
    constexpr double kRange = 0.8;
    // The sphere's radius on screen, in pixels: range / distance over tan(fov_y / 2), times
    // half the image height.
    const double radiusPixels = kRange / 10.0 / std::tan(kSpotViewHalfFovDegrees * M_PI / 180.0) * kSpotViewHalfHeight;
    ASSERT_GT((2.0 * radiusPixels / 16.0) * (2.0 * radiusPixels / 16.0), 64.0);
    const std::vector<Light> lights = expandLights(loadSceneFile(withRange(dir, "lights_on_one_spot.json", kRange)));
    ASSERT_GT(lights.size(), 2u * 65535u);
    double total[3] = {0.0, 0.0, 0.0};
    for (const Light& light : lights)
        for (int c = 0; c < 3; ++c)
            total[c] += light.intensity[c];
    std::vector<std::string> args = kSpotView;
    args.insert(args.end(), {"--gbuffer", "seed", "--technique", technique});
    const Image one = renderPfm(withRange(dir, "one_light_on_one_spot.json", kRange), dir / "one.pfm", args);
    const Image many = renderPfm(withRange(dir, "lights_on_one_spot.json", kRange), dir / "many.pfm", args);
    Image expected = one;
    int lit = 0;
    for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
        expected.rgb[i] = static_cast<float>(static_cast<double>(one.rgb[i]) * total[i % 3]);
        lit += expected.rgb[i] > 0.0f;
    }
    test::expectImagesNear(expected, many, {.relative = 8e-3}, technique);
    EXPECT_GE(lit, 3) << "the square should cover a pixel";
}

INSTANTIATE_TEST_SUITE_P(LightLists, WideLightsOnOneSpot, ::testing::Values("clustered", "tiled"),
                         test::techniqueTestName);

INSTANTIATE_TEST_SUITE_P(EveryTechnique, WorkAtUserSizes, ::testing::ValuesIn(techniqueNames()),
                         test::techniqueTestName);

}  // namespace
}  // namespace manylights
