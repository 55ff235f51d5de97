// Shadow-map caching and the local-light budget on a headless context: the number of
// shadow-map passes is deterministic, so an unchanged frame must render none.
#include <gtest/gtest.h>

#include <memory>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/effects/ShadowMaps.h"
#include "render/frame/PassProfiler.h"
#include "render/scene/GpuScene.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

class ShadowMapsTest : public GlContextTest {};

// A directional light with shadows, a narrow spot (one map), a point light and a 120° spot
// (a cube map of six faces each).
const char* kScene = R"({
    "camera": {"eye": [3, 6, 7], "look_at": [0, 0, 0], "fov_y": 50},
    "ambient": [0.05, 0.05, 0.05],
    "directional": {"direction": [1, -2, 0], "intensity": [0.3, 0.3, 0.3], "shadows": true},
    "lights": [
        {"type": "spot", "pos": [0, 5, 0], "direction": [0, -1, 0], "cutoff": 40, "intensity": [5, 5, 5], "range": 12},
        {"type": "point", "pos": [-3, 2.5, 2], "intensity": [2, 1, 1], "range": 8},
        {"type": "spot", "pos": [3, 3, -2], "direction": [-1, -1, 0], "cutoff": 120, "intensity": [1, 1, 2],
         "range": 8}],
    "objects": [
        {"mesh": {"primitive": "plane", "size": [20, 20]}},
        {"mesh": {"primitive": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 2, 0]}}]})";

constexpr std::uint64_t kDirectionalPasses = 1;
constexpr std::uint64_t kSpotPasses = 1;
constexpr std::uint64_t kCubePasses = 6;

TEST_F(ShadowMapsTest, UnchangedFrameRendersNoShadowPass)
{
    const Scene scene = parseScene(kScene, "<shadow maps test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    RendererDesc desc{.width = 96, .height = 64, .shadowLights = 3};
    Renderer renderer(scene, lights, desc);
    Technique& forward = renderer.technique("forward");

    renderer.renderFrame(forward, ViewMode::Final);
    const std::uint64_t all = kDirectionalPasses + kSpotPasses + 2 * kCubePasses;
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), all);
    EXPECT_EQ(renderer.shadowMaps().shadowedLights().size(), 3u);

    // Nothing moved: every map is reused.
    renderer.renderFrame(forward, ViewMode::Final);
    renderer.renderFrame(forward, ViewMode::Final);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), all);

    // A new image size changes the view the directional map is fitted to, not the local lights.
    desc.width = 80;
    renderer.apply(desc);
    renderer.renderFrame(forward, ViewMode::Final);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), all + kDirectionalPasses);

    // Invalidating forgets every map.
    renderer.invalidateShadowMaps();
    renderer.renderFrame(forward, ViewMode::Final);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), 2 * all + kDirectionalPasses);
}

TEST_F(ShadowMapsTest, MovedObjectsRebuildEveryMap)
{
    const Scene scene = parseScene(kScene, "<shadow maps test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    GpuScene gpuScene(scene, lights, resolveDriverChoices({.profile = DriverProfile::Auto}));
    gpuScene.setViewport(96, 64);
    ShadowMaps maps;
    maps.setLocalLightBudget(3);
    PassProfiler profiler;
    FrameTargets targets(96, 64);
    const auto update = [&] {
        profiler.beginFrame();
        FramePasses passes(gpuScene, targets, profiler);
        maps.update(passes);
        passes.finish();
        profiler.endFrame();
    };
    const std::uint64_t all = kDirectionalPasses + kSpotPasses + 2 * kCubePasses;
    update();
    update();
    EXPECT_EQ(maps.passesRendered(), all);
    // What moves objects (animation) reports it; every map may now be stale.
    gpuScene.noteTransformsChanged();
    update();
    EXPECT_EQ(maps.passesRendered(), 2 * all);
    update();
    EXPECT_EQ(maps.passesRendered(), 2 * all);
}

TEST_F(ShadowMapsTest, BudgetLimitsTheShadowedLights)
{
    const Scene scene = parseScene(kScene, "<shadow maps test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    RendererDesc desc{.width = 96, .height = 64};
    Renderer renderer(scene, lights, desc);

    // The default budget: only the directional light.
    renderer.renderFrame("forward", ViewMode::Final);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), kDirectionalPasses);
    EXPECT_TRUE(renderer.shadowMaps().shadowedLights().empty());

    // One local light: the brightest on screen, the narrow spot (5 × its coverage wins). The
    // renderer keeps its lights in an order of its own (render/scene/SceneLights.h): the index is
    // into that order.
    desc.shadowLights = 1;
    renderer.apply(desc);
    renderer.renderFrame("forward", ViewMode::Final);
    ASSERT_EQ(renderer.shadowMaps().shadowedLights().size(), 1u);
    const Light chosen = renderer.gpuScene().light(renderer.shadowMaps().shadowedLights()[0]);
    EXPECT_EQ(chosen.position, lights[0].position);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), kDirectionalPasses + kSpotPasses);

    // The directional switch of the viewer.
    desc.directionalShadows = false;
    renderer.apply(desc);
    renderer.renderFrame("forward", ViewMode::Final);
    EXPECT_FALSE(renderer.shadowMaps().directionalActive());
}

}  // namespace
}  // namespace manylights
