// The light lists of tiled and clustered built from bit masks (render/culling/ClusterLists.h:
// frames of at most kMaskedListLights lights) against the same lists built by the pair sort
// (CullingTuning::maskedListLights 0, as MANYLIGHTS_MASKED_LIST_LIGHTS=0 sets it). Both paths
// must give the same lists in the same order, so the images must be the same bytes, with no
// tolerance: the lighting adds the same lights in the same order. The light counts cover each
// shape of the masks: fewer than 32 words a cluster, exactly 32 (the most without a summary),
// 33 (a summary of two words), 3,000 and 4,500. The lights drift, and each renderer draws
// several times in turn: a bit left in a mask by one frame would put a light into the next
// frame's lists where it no longer reaches.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/culling/ClusterLists.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

class MaskedListsTest : public GlContextTest {};

// A yard of 24 m with a few blocks, under `count` drifting point lights: 3 whose ranges (30 to
// 40 m) reach the whole view (the global list's), and the others, of `shortestRange` to
// `longestRange` m of range (narrow and wide ones), from 0.1 to 2 m above the ground within
// `spread` m of its centre. Gathered within half a metre, with ranges of 3 to 3.5 m (each
// reaches the ground's centre, none covers half the view), 4,500 of them make lists longer
// than a part (kClusterListPart), which later passes light.
std::string yardScene(int count, double spread, double shortestRange, double longestRange)
{
    const auto lightSet = [](int lights, int seed, double halfWidth, double minRange, double maxRange) {
        return nlohmann::json{{"count", lights},
                              {"seed", seed},
                              {"type", "point"},
                              {"min", {-halfWidth, 0.1, -halfWidth}},
                              {"max", {halfWidth, 2, halfWidth}},
                              {"range", {minRange, maxRange}},
                              {"intensity", {0.02, 0.1}},
                              {"animation", {{"drift", {{"amplitude", {1.5, 0.2, 1.5}}}}}}};
    };
    nlohmann::json scene = {
        {"camera", {{"eye", {0, 14, 14}}, {"look_at", {0, 0, -1}}, {"fov_y", 50}, {"near", 0.5}, {"far", 80}}},
        {"ambient", {0.02, 0.02, 0.02}},
        {"light_sets", {lightSet(3, 5, 12, 30, 40), lightSet(count - 3, 7, spread, shortestRange, longestRange)}},
        {"materials", {{"m", {{"diffuse", {0.7, 0.7, 0.7}}, {"specular", {0.3, 0.3, 0.3}}, {"shininess", 16}}}}},
        {"objects", nlohmann::json::array()}};
    scene["objects"].push_back({{"mesh", {{"primitive", "plane"}, {"size", {24, 24}}}}, {"material", "m"}});
    for (int i = 0; i < 5; ++i)
        scene["objects"].push_back({{"mesh", {{"primitive", "box"}, {"size", {2, 1 + i, 2}}}},
                                    {"material", "m"},
                                    {"transform", {{"translate", {-8 + 4 * i, 0.5 * (1 + i), -3 + (i % 2) * 5}}}}});
    return scene.dump();
}

std::map<std::string, double> countersOf(Technique& technique)
{
    std::map<std::string, double> counters;
    for (const TechniqueCounter& counter : technique.counters())
        counters[counter.name] = counter.value;
    return counters;
}

const std::vector<std::string> kTechniques = {"clustered", "tiled"};

// A renderer of `desc` for the scene whose lists are made from masks up to `maskedListLights`
// lights (unset: the default; 0: every frame sorts), with its techniques made.
void makeRenderer(std::optional<Renderer>& renderer, const Scene& scene, const std::vector<Light>& lights,
                  RendererDesc desc, std::optional<std::uint32_t> maskedListLights)
{
    desc.culling.maskedListLights = maskedListLights;
    renderer.emplace(scene, lights, desc);
    for (const std::string& technique : kTechniques)
        renderer->technique(technique);
}

// Renders a frame of `technique` at time t with each renderer, checks that `masked` made its
// lists from masks exactly where `expectMasks` says (and `sorted` never), and that both have
// the same pairs, longest list, global lights and image bytes. Returns `masked`'s counters.
std::map<std::string, double> expectSameFrame(Renderer& masked, Renderer& sorted, const std::string& technique,
                                              double t, bool expectMasks, const std::string& where)
{
    masked.setTime(t);
    sorted.setTime(t);
    masked.renderFrame(technique, ViewMode::Final);
    sorted.renderFrame(technique, ViewMode::Final);
    std::map<std::string, double> fromMasks = countersOf(masked.technique(technique));
    std::map<std::string, double> fromSort = countersOf(sorted.technique(technique));
    EXPECT_EQ(fromMasks["cluster_lists_from_masks"], expectMasks ? 1.0 : 0.0) << where;
    EXPECT_EQ(fromSort["cluster_lists_from_masks"], 0.0) << where;
    EXPECT_GT(fromMasks["cluster_pairs"], 0.0) << where;
    for (const char* name : {"cluster_pairs", "longest_cluster_list", "global_lights"})
        EXPECT_EQ(fromMasks[name], fromSort[name]) << where << ": " << name;
    EXPECT_EQ(masked.readColour().rgb, sorted.readColour().rgb) << where;
    return fromMasks;
}

TEST_F(MaskedListsTest, MasksGiveTheSortsListsFrameAfterFrame)
{
    const RendererDesc desc{.width = 320, .height = 180};
    bool sawGlobalLights = false;
    bool sawLongLists = false;
    struct Case {
        int lights;
        double spread;
        double shortestRange;
        double longestRange;
    };
    for (const Case& yard :
         {Case{40, 12, 0.5, 6}, {1024, 12, 0.5, 6}, {1056, 12, 0.5, 6}, {3000, 12, 0.5, 6}, {4500, 0.5, 3, 3.5}}) {
        ASSERT_LE(yard.lights, static_cast<int>(kMaskedListLights));
        const Scene scene = parseScene(yardScene(yard.lights, yard.spread, yard.shortestRange, yard.longestRange),
                                       "<masked lists>", ".");
        const std::vector<Light> lights = expandLights(scene);
        std::optional<Renderer> masked;
        std::optional<Renderer> sorted;
        makeRenderer(masked, scene, lights, desc, std::nullopt);
        makeRenderer(sorted, scene, lights, desc, 0);
        for (const std::string& technique : kTechniques) {
            for (const double t : {0.0, 1.3, 0.4}) {
                const std::map<std::string, double> fromMasks = expectSameFrame(
                    *masked, *sorted, technique, t, true,
                    technique + ", " + std::to_string(yard.lights) + " lights, t = " + std::to_string(t));
                sawGlobalLights = sawGlobalLights || fromMasks.at("global_lights") > 0.0;
                sawLongLists = sawLongLists || fromMasks.at("longest_cluster_list") > kClusterListPart;
            }
        }
    }
    EXPECT_TRUE(sawGlobalLights) << "the scenes should have a global list";
    EXPECT_TRUE(sawLongLists) << "the scenes should have lists longer than a part";
}

// At 1920x1080 the masks' budget (kMaskedListBudgetBytes, 64 MiB) decides: at 8,192 lights
// clustered's masks would take 65,280 cells x (256 + 8) words = 68.9 MB, so it sorts, while
// tiled's 32,400 cells take 34.2 MB and stay masked; at 4,096 lights clustered's take 34.5 MB.
// Either way the image is the sorted lists' to the byte. The lights are small (0.2 to 0.6 m),
// so that the lighting of the full-size frames stays cheap.
TEST_F(MaskedListsTest, TheMemoryBudgetDecidesAtNineteenTwentyByTenEighty)
{
    const RendererDesc desc{.width = 1920, .height = 1080};
    for (const int count : {4096, 8192}) {
        const Scene scene = parseScene(yardScene(count, 12, 0.2, 0.6), "<masked lists>", ".");
        const std::vector<Light> lights = expandLights(scene);
        std::optional<Renderer> masked;
        std::optional<Renderer> sorted;
        makeRenderer(masked, scene, lights, desc, std::nullopt);
        makeRenderer(sorted, scene, lights, desc, 0);
        for (const std::string& technique : kTechniques)
            expectSameFrame(*masked, *sorted, technique, 0.7, technique == "tiled" || count == 4096,
                            technique + ", " + std::to_string(count) + " lights, 1920x1080");
    }
}

}  // namespace
}  // namespace manylights
