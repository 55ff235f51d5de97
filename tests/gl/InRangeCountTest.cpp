// in_range_pairs, the least work any technique can do, is counted per pixel over the lights
// a per-tile cull keeps (shaders/in_range.comp): minutes of brute force became seconds. The
// cull may only skip lights that reach no pixel of the tile, so the count must equal the
// brute-force count, every light tested at every pixel, exactly.
#include <gtest/gtest.h>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

struct InRangeCase {
    std::string name;
    std::string scene;  // under the source tree
    std::optional<int> lights;
    int width;
    int height;
    friend void PrintTo(const InRangeCase& c, std::ostream* os) { *os << c.name; }
};

class InRangeCount : public GlContextTest, public ::testing::WithParamInterface<InRangeCase> {};

TEST_P(InRangeCount, CulledCountEqualsBruteForce)
{
    const InRangeCase& c = GetParam();
    const Scene scene = loadSceneFile(std::string(MANYLIGHTS_SOURCE_DIR) + "/" + c.scene);
    const std::vector<Light> lights = expandLights(scene, c.lights);
    RendererDesc desc{.width = c.width, .height = c.height, .countWork = true};
    Renderer renderer(scene, lights, desc);
    renderer.renderFrame("deferred", ViewMode::Final);
    const std::uint64_t culled = renderer.lastWorkCounts().inRangePairs;
    desc.inRangeBruteForce = true;
    renderer.apply(desc);
    renderer.renderFrame("deferred", ViewMode::Final);
    const std::uint64_t bruteForce = renderer.lastWorkCounts().inRangePairs;
    EXPECT_GT(bruteForce, 1000u);
    EXPECT_EQ(culled, bruteForce);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, InRangeCount,
    ::testing::Values(
        InRangeCase{"courtyard_4096_lights", "bench/courtyard.json", 4096, 320, 180},
        InRangeCase{"spots_and_points", "tests/scenes/spots_and_points.json", 300, 160, 120},
        InRangeCase{"big_light", "tests/scenes/big_light.json", std::nullopt, 320, 240},
        InRangeCase{"camera_inside_spot_cone", "tests/scenes/camera_inside_spot_cone.json", std::nullopt, 160, 120},
        // Past the driver's loop limit, at a size people render:
        // 16 batches of lights on a few pixels.
        InRangeCase{"lights_on_one_spot_1280_720", "tests/scenes/lights_on_one_spot.json", std::nullopt, 1280, 720}),
    [](const ::testing::TestParamInfo<InRangeCase>& param) { return param.param.name; });

}  // namespace
}  // namespace manylights
