// The shadow maps' and the shadow-page pool's caching and the choice of shadowed lights, on a
// headless context: the numbers of maps, markings and faces drawn are deterministic, so an
// unchanged frame must draw none (issue 47, item 4).
#include <gtest/gtest.h>

#include <memory>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/effects/ShadowMaps.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"
#include "scene/ShadowSelection.h"

namespace manylights {
namespace {

class ShadowPoolTest : public GlContextTest {};

// A directional light with shadows, a narrow spot (one face), a point light and a 120° spot
// (six faces each), over a floor with a box in the air and a bouncing box far from the lights
// at the side of the view.
const char* kShadowedScene = R"({
    "camera": {"eye": [3, 6, 7], "look_at": [0, 0, 0], "fov_y": 50},
    "ambient": [0.05, 0.05, 0.05],
    "directional": {"direction": [1, -2, 0], "intensity": [0.3, 0.3, 0.3], "shadows": true},
    "lights": [
        {"type": "spot", "pos": [0, 5, 0], "direction": [0, -1, 0], "cutoff": 40, "intensity": [5, 5, 5], "range": 12},
        {"type": "point", "pos": [-3, 2.5, 2], "intensity": [2, 1, 1], "range": 4},
        {"type": "spot", "pos": [3, 3, -2], "direction": [-1, -1, 0], "cutoff": 120, "intensity": [1, 1, 2],
         "range": 5}],
    "objects": [
        {"mesh": {"primitive": "plane", "size": [20, 20]}},
        {"mesh": {"primitive": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 2, 0]}},
        {"mesh": {"primitive": "box", "size": [0.3, 0.3, 0.3]}, "transform": {"translate": [-6, 0.15, -1]},
         "animation": {"bounce": {"height": 0.2, "period": 1}}}]})";

constexpr std::uint64_t kDirectionalPasses = 1;

TEST_F(ShadowPoolTest, AStillFrameMarksAndDrawsNothing)
{
    const Scene scene = parseScene(kShadowedScene, "<shadow pool test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    RendererDesc desc{.width = 96, .height = 64, .shadowLights = kAllShadowLights};
    Renderer renderer(scene, lights, desc);
    Technique& forward = renderer.technique("forward");

    renderer.renderFrame(forward, ViewMode::Final);
    const ShadowPool& pool = renderer.shadowPool();
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), kDirectionalPasses);
    EXPECT_EQ(pool.shadowedLights().size(), 3u);
    EXPECT_EQ(pool.markingsTotal(), 1u);
    const std::uint64_t drawn = pool.facesDrawnTotal();
    EXPECT_GT(drawn, 0u);
    // Every face with pages was drawn once (a part with its coarse page counts twice).
    EXPECT_GE(drawn, pool.lastFrame().faces);

    // Nothing moved: nothing is marked or drawn again.
    renderer.renderFrame(forward, ViewMode::Final);
    renderer.renderFrame(forward, ViewMode::Final);
    EXPECT_EQ(pool.markingsTotal(), 1u);
    EXPECT_EQ(pool.facesDrawnTotal(), drawn);
    EXPECT_EQ(pool.lastFrame().facesDrawn, 0u);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), kDirectionalPasses);

    // Invalidating forgets every page: all are marked and drawn again.
    renderer.invalidateShadowMaps();
    renderer.renderFrame(forward, ViewMode::Final);
    EXPECT_EQ(pool.markingsTotal(), 2u);
    EXPECT_EQ(pool.facesDrawnTotal(), 2 * drawn);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), 2 * kDirectionalPasses);
}

TEST_F(ShadowPoolTest, AMovingObjectRedrawsOnlyTheFacesItMeets)
{
    const Scene scene = parseScene(kShadowedScene, "<shadow pool test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    RendererDesc desc{.width = 96, .height = 64, .shadowLights = kAllShadowLights};
    Renderer renderer(scene, lights, desc);
    renderer.setTime(0.25);
    renderer.renderFrame("deferred", ViewMode::Final);
    const ShadowPool& pool = renderer.shadowPool();
    const std::size_t faces = pool.lastFrame().faces;
    ASSERT_GT(faces, 0u);
    const std::uint64_t drawn = pool.facesDrawnTotal();
    // The bouncing box moves: the receivers are marked again, but it lies beyond every light's
    // reach, so no face is drawn again.
    renderer.setTime(0.5);
    renderer.renderFrame("deferred", ViewMode::Final);
    EXPECT_EQ(pool.markingsTotal(), 2u);
    EXPECT_EQ(pool.facesDrawnTotal(), drawn);
    // --rebuild-shadows draws every face every frame.
    desc.rebuildShadowsEveryFrame = true;
    renderer.apply(desc);
    renderer.renderFrame("deferred", ViewMode::Final);
    EXPECT_EQ(pool.lastFrame().faces, faces);
    EXPECT_GE(pool.lastFrame().facesDrawn, faces);
}

TEST_F(ShadowPoolTest, TheCapChoosesTheBrightestOnScreen)
{
    const Scene scene = parseScene(kShadowedScene, "<shadow pool test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    RendererDesc desc{.width = 96, .height = 64};
    Renderer renderer(scene, lights, desc);

    // The default: only the directional light.
    renderer.renderFrame("forward", ViewMode::Final);
    EXPECT_EQ(renderer.shadowMaps().passesRendered(), kDirectionalPasses);
    EXPECT_TRUE(renderer.shadowPool().shadowedLights().empty());
    EXPECT_EQ(renderer.shadowPool().markingsTotal(), 0u);

    // One local light: the brightest on screen, the narrow spot (5 × its coverage wins), with
    // its one face. The renderer keeps its lights in an order of its own
    // (render/scene/SceneLights.h): the index is into that order.
    desc.shadowLights = 1;
    renderer.apply(desc);
    renderer.renderFrame("forward", ViewMode::Final);
    ASSERT_EQ(renderer.shadowPool().shadowedLights().size(), 1u);
    const Light chosen = renderer.gpuScene().light(renderer.shadowPool().shadowedLights()[0]);
    EXPECT_EQ(chosen.position, lights[0].position);
    EXPECT_EQ(renderer.shadowPool().lastFrame().faces, 1u);

    // The directional switch of the viewer.
    desc.directionalShadows = false;
    renderer.apply(desc);
    renderer.renderFrame("forward", ViewMode::Final);
    EXPECT_FALSE(renderer.shadowMaps().directionalActive());
}

}  // namespace
}  // namespace manylights
