// deferred's and clustered's two lighting stages (--lighting-stage fragment|compute,
// render/techniques/Technique.h): the compute pass is the same lighting in the same order, so
// the same image (to the byte on llvmpipe) and the same light evaluations, under both driver profiles (the
// GPU's choices, branching on a light's reach among them, and llvmpipe's). Both stages are
// compared with forward by TechniqueAgreementTest, the compute one under the GPU profile
// (image.gpu.*), whose default it is.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;

struct StageCase {
    std::string name;
    std::string scene;  // "" for the default scene
    std::vector<std::string> args;
    friend void PrintTo(const StageCase& c, std::ostream* os) { *os << c.name; }
};

class LightingStages : public ::testing::TestWithParam<StageCase> {};

TEST_P(LightingStages, ComputeGivesTheFragmentPassesImageToTheByte)
{
    const StageCase& c = GetParam();
    const auto dir = scratchDirectory();
    std::string scene = c.scene;
    if (c.name == "long_lists_and_batches") {
        // 10,000 lights on a few pixels: clustered's list of them is three parts long
        // (kClusterListPart), and deferred walks them in ten light windows under the GPU
        // profile (kLightsPerWindow) and two batches under the software one.
        nlohmann::json json = nlohmann::json::parse(std::ifstream(test::kTestScenes + "lights_on_one_spot.json"));
        json["light_sets"][0]["count"] = 10000;
        scene = (dir / "spot.json").string();
        test::writeFile(scene, json.dump());
    }
    for (const std::string profile : {"software", "gpu"}) {
        for (const std::string technique : {"deferred", "clustered"}) {
            const auto render = [&](const std::string& stage) {
                std::vector<std::string> args = c.args;
                args.insert(args.end(), {"--technique", technique, "--driver-profile", profile, "--lighting-stage",
                                         stage, "--count-work", "--stats", (dir / (stage + ".json")).string()});
                return renderPfm(scene, dir / (stage + ".pfm"), args);
            };
            const std::string where = technique + " under the " + profile + " profile";
            const Image fragment = render("fragment");
            const Image compute = render("compute");
            const auto stats = [&](const std::string& stage) {
                return nlohmann::json::parse(std::ifstream(dir / (stage + ".json")));
            };
            // The two stages are two programs: llvmpipe compiles the shared lighting code alike
            // in both, and the images are the same to the byte there. Another driver's compiler
            // may contract multiply-adds differently in each, which the agreement tolerance
            // covers (tests/support/ImageComparison.h).
            if (stats("compute")["device"].get<std::string>().find("llvmpipe") != std::string::npos)
                EXPECT_EQ(compute.rgb, fragment.rgb) << where;
            else
                test::expectImagesNear(fragment, compute, test::kAgreementTolerance, where);
            EXPECT_EQ(stats("compute")["lighting_stage"], "compute") << where;
            EXPECT_EQ(stats("fragment")["lighting_stage"], "fragment") << where;
            EXPECT_EQ(stats("compute")["light_evaluations"], stats("fragment")["light_evaluations"]) << where;
            EXPECT_GT(stats("compute")["light_evaluations"].get<double>(), 0.0) << where;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, LightingStages,
                         ::testing::Values(StageCase{"default_scene", "", {"--size", "192x108"}},
                                           StageCase{"global_lights",
                                                     test::kTestScenes + "every_light_everywhere.json",
                                                     {"--size", "160x90"}},
                                           StageCase{"long_lists_and_batches", "", {"--size", "1280x720"}}),
                         [](const ::testing::TestParamInfo<StageCase>& param) { return param.param.name; });

// Without --lighting-stage, the driver profile decides: the fragment pass on a software
// rasteriser, the compute pass on a GPU (DriverChoices::lightingStage).
TEST(LightingStages, TheProfileChoosesByDefault)
{
    const auto dir = scratchDirectory();
    for (const std::string profile : {"software", "gpu"}) {
        renderPfm("", dir / "out.pfm",
                  {"--size", "64x36", "--technique", "clustered", "--driver-profile", profile, "--stats",
                   (dir / "stats.json").string()});
        const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / "stats.json"));
        EXPECT_EQ(stats["lighting_stage"], profile == "gpu" ? "compute" : "fragment") << profile;
    }
}

}  // namespace
}  // namespace manylights
