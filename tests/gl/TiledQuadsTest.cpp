// tiled-quads on a headless context: every tile is drawn once, over exactly its pixels, by
// the shader variant of its light count, and the image is deferred's; as points (where the
// driver draws points of the tile's size, as llvmpipe does) and as quads (the fallback).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/techniques/TiledQuadsTechnique.h"
#include "scene/Meshes.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

constexpr int kTile = kDefaultTileSize;
constexpr int kTilesWidth = 5 * kTile;  // 5x2 tiles
constexpr int kTilesHeight = 2 * kTile;
constexpr float kEyeHeight = 10.0f;
constexpr float kLightHeight = 0.3f;

// A floor seen from straight above, narrower than the view so that the image's left and
// right edges show background.
Scene floorScene()
{
    Scene scene;
    scene.source = "<tiled-quads test>";
    scene.camera.eye = glm::vec3(0.0f, kEyeHeight, 0.0f);
    scene.camera.lookAt = glm::vec3(0.0f);
    scene.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);  // screen right is +X, screen up is −Z
    scene.camera.fovYDegrees = 30.0f;
    scene.camera.nearPlane = 0.5f;
    scene.camera.farPlane = 50.0f;
    scene.ambient = glm::vec3(0.02f);
    Material grey;
    grey.diffuse = glm::vec3(0.7f);
    grey.specular = glm::vec3(0.2f);
    scene.materials.push_back(grey);
    scene.meshes.push_back(makePlane(10.0f, 20.0f));
    scene.objects.push_back(Object{"floor", 0, 0, glm::mat4(1.0f)});
    return scene;
}

// `count` small lights just above the floor under the middle of tile (tx, ty): random
// pixels at least 5 from the edges of the 16-pixel tile, where a light of range 0.5 (about 3
// pixels in radius here) cannot reach a neighbouring tile.
void addLightsOverTile(std::vector<Light>& lights, int tx, int ty, int count, std::mt19937& random)
{
    const float tanY = std::tan(glm::radians(30.0f) / 2.0f);
    const float tanX = tanY * static_cast<float>(kTilesWidth) / static_cast<float>(kTilesHeight);
    const float depth = kEyeHeight - kLightHeight;
    static_assert(kTile == 16, "the margins below are for 16-pixel tiles");
    std::uniform_real_distribution<float> within(5.0f, 11.0f);
    std::uniform_real_distribution<float> hue(0.0f, 1.0f);
    for (int i = 0; i < count; ++i) {
        const float px = static_cast<float>(tx * kTile) + within(random);
        const float py = static_cast<float>(ty * kTile) + within(random);
        const float slopeX = (2.0f * px / kTilesWidth - 1.0f) * tanX;
        const float slopeY = (2.0f * py / kTilesHeight - 1.0f) * tanY;
        Light light;
        light.position = glm::vec3(slopeX * depth, kLightHeight, -slopeY * depth);
        light.range = 0.5f;
        light.intensity = 0.02f * glm::vec3(hue(random), hue(random), hue(random));
        lights.push_back(light);
    }
}

class TiledQuadsPrimitiveTest : public GlContextTest, public ::testing::WithParamInterface<bool> {};

TEST_P(TiledQuadsPrimitiveTest, EveryVariantDrawsItsTilesOverExactlyTheirPixels)
{
    const Scene scene = floorScene();
    // One tile per variant (up to 8, 16, ..., 1024 lights, and up to a light batch), and one
    // with none.
    const int counts[2][5] = {{0, 5, 12, 24, 48}, {96, 192, 384, 768, 1500}};
    std::mt19937 random(1);
    std::vector<Light> lights;
    for (int ty = 0; ty < 2; ++ty)
        for (int tx = 0; tx < 5; ++tx)
            addLightsOverTile(lights, tx, ty, counts[ty][tx], random);

    Renderer renderer(scene, lights, {.width = kTilesWidth, .height = kTilesHeight, .countWork = true});
    auto& tiled = dynamic_cast<TiledQuadsTechnique&>(renderer.technique("tiled-quads"));
    tiled.drawTilesAsQuads(GetParam());
    renderer.renderFrame(tiled, ViewMode::LightCount);
    const Image evaluations = renderer.readColour();
    const std::vector<bool> covered = renderer.readCoverage();
    const TileLightLists& lists = tiled.lastLists();
    ASSERT_EQ(lists.tilesX, 5);
    ASSERT_EQ(lists.tilesY, 2);

    // The lights stayed over their tiles, so each tile's count picks a different variant.
    std::set<std::size_t> variants;
    for (int ty = 0; ty < 2; ++ty)
        for (int tx = 0; tx < 5; ++tx) {
            const std::uint32_t count = lists.tiles[lists.tileIndex(tx, ty)].count;
            EXPECT_EQ(count, static_cast<std::uint32_t>(counts[ty][tx])) << "tile " << tx << ", " << ty;
            if (count > 0)
                variants.insert(
                    static_cast<std::size_t>(std::lower_bound(kTileLightBounds.begin(), kTileLightBounds.end(), count) -
                                             kTileLightBounds.begin()));
        }
    EXPECT_EQ(variants.size(), kTileLightBounds.size());

    // Each covered pixel evaluated exactly its tile's lights, once; the background none.
    int coveredPixels = 0;
    int wrong = 0;
    for (int y = 0; y < kTilesHeight; ++y)
        for (int x = 0; x < kTilesWidth; ++x) {
            const int glY = kTilesHeight - 1 - y;  // Image rows run top to bottom
            const bool surface = covered[static_cast<std::size_t>(y) * kTilesWidth + x];
            coveredPixels += surface;
            const float expected =
                surface ? static_cast<float>(lists.tiles[lists.tileIndex(x / kTile, glY / kTile)].count) : 0.0f;
            if (evaluations.pixel(x, y)[0] != expected && ++wrong <= 5)
                ADD_FAILURE() << "pixel (" << x << ", " << glY << "): " << evaluations.pixel(x, y)[0]
                              << " evaluations, expected " << expected;
        }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(coveredPixels, kTilesWidth * kTilesHeight / 2);
    EXPECT_LT(coveredPixels, kTilesWidth * kTilesHeight) << "the image should show some background";
    EXPECT_GE(renderer.lastWorkCounts().lightEvaluations, renderer.lastWorkCounts().inRangePairs);
    EXPECT_GT(renderer.lastWorkCounts().inRangePairs, 0u);

    // And the image is deferred's (which loops over all 3,029 lights everywhere).
    renderer.renderFrame(tiled, ViewMode::Final);
    const Image image = renderer.readColour();
    renderer.renderFrame("deferred", ViewMode::Final);
    test::expectImagesNear(renderer.readColour(), image, test::kAgreementTolerance);
}

TEST_P(TiledQuadsPrimitiveTest, NoLightsAndResizing)
{
    const Scene scene = floorScene();
    // No local lights: nothing to draw but the global terms.
    {
        Renderer renderer(scene, {}, {.width = 40, .height = 30});
        auto& tiled = dynamic_cast<TiledQuadsTechnique&>(renderer.technique("tiled-quads"));
        tiled.drawTilesAsQuads(GetParam());
        renderer.renderFrame(tiled, ViewMode::Final);
        EXPECT_TRUE(tiled.lastLists().lightIndices.empty());
        const Image image = renderer.readColour();
        renderer.renderFrame("deferred", ViewMode::Final);
        test::expectImagesNear(renderer.readColour(), image, test::kAgreementTolerance);
    }
    // The grid follows the image size from frame to frame; at 97x45 the last row and column
    // of tiles are cut at the image's edge (the centres of the last row's points lie beyond it).
    std::mt19937 random(2);
    std::vector<Light> lights;
    addLightsOverTile(lights, 1, 1, 40, random);
    addLightsOverTile(lights, 3, 0, 10, random);
    addLightsOverTile(lights, 4, 1, 10, random);
    // And one over the whole floor, in every tile, the cut ones too.
    Light wide;
    wide.position = glm::vec3(0.0f, 2.0f, 0.0f);
    wide.range = 40.0f;
    wide.intensity = glm::vec3(0.3f);
    lights.push_back(wide);
    Renderer renderer(scene, lights, {.width = kTilesWidth, .height = kTilesHeight});
    auto& tiled = dynamic_cast<TiledQuadsTechnique&>(renderer.technique("tiled-quads"));
    tiled.drawTilesAsQuads(GetParam());
    for (const auto& [width, height] :
         {std::pair{kTilesWidth, kTilesHeight}, std::pair{97, 45}, std::pair{kTilesWidth, kTilesHeight}}) {
        renderer.apply({.width = width, .height = height});
        renderer.renderFrame(tiled, ViewMode::Final);
        EXPECT_EQ(tiled.lastLists().tilesX, (width + kTile - 1) / kTile);
        EXPECT_EQ(tiled.lastLists().tilesY, (height + kTile - 1) / kTile);
        const Image image = renderer.readColour();
        renderer.renderFrame("deferred", ViewMode::Final);
        test::expectImagesNear(renderer.readColour(), image, test::kAgreementTolerance);
    }
}

INSTANTIATE_TEST_SUITE_P(PointsAndQuads, TiledQuadsPrimitiveTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) { return param.param ? "quads" : "points"; });

}  // namespace
}  // namespace manylights
