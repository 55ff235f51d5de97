// CPU tile culling for tiled-quads (render/culling/TileCulling.h); no GL context needed.
//
// The hand-computed cases use the simplest camera: the eye at the origin looking along −Z,
// a 90° vertical field of view (tan 45° = 1) and a square 256x256 image, so 8x8 tiles of 32
// pixels, and the view-space point (x, y, −d) lands on pixel ((x/d + 1)·128, (y/d + 1)·128)
// (y up, as GL's window coordinates).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <span>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "PackedLights.h"
#include "render/culling/TileCulling.h"
#include "scene/Falloff.h"

namespace manylights {
namespace {

using test::pointLight;
using test::spotLight;

TileCullingView simpleView()
{
    TileCullingView view;
    view.view = glm::mat4(1.0f);
    view.fovY = glm::radians(90.0f);
    view.nearPlane = 0.1f;
    view.farPlane = 100.0f;
    view.width = 256;
    view.height = 256;
    view.tileSize = 32;
    return view;
}

using TileSet = std::set<std::pair<int, int>>;

// The tiles (tx, ty) whose list holds `light`.
TileSet tilesOf(const TileLightLists& lists, std::uint32_t light)
{
    TileSet tiles;
    for (int ty = 0; ty < lists.tilesY; ++ty)
        for (int tx = 0; tx < lists.tilesX; ++tx) {
            const auto lights = lists.lightsOf(lists.tileIndex(tx, ty));
            if (std::find(lights.begin(), lights.end(), light) != lights.end())
                tiles.insert({tx, ty});
        }
    return tiles;
}

TileSet tilesOfOneLight(const TileCullingView& view, const GpuLight& light)
{
    return tilesOf(cullLightsToTiles(view, std::vector<GpuLight>{light}), 0);
}

TileSet allTiles(int tilesX, int tilesY)
{
    TileSet tiles;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx)
            tiles.insert({tx, ty});
    return tiles;
}

TEST(TileCulling, GridCoversTheImageWithPartialTiles)
{
    TileCullingView view = simpleView();
    view.width = 320;
    view.height = 180;  // 5.6 rows of 32 pixels: the last row is 20 pixels high
    const TileLightLists lists = cullLightsToTiles(view, std::vector<GpuLight>{});
    EXPECT_EQ(lists.tilesX, 10);
    EXPECT_EQ(lists.tilesY, 6);
    EXPECT_EQ(lists.tileCount(), 60u);
    EXPECT_TRUE(lists.lightIndices.empty());
}

TEST(TileCulling, SmallSphereInsideOneTile)
{
    // Centred on pixel (48, 48), the middle of tile (1, 1); its image is about 2 pixels wide.
    EXPECT_EQ(tilesOfOneLight(simpleView(), pointLight({-6.25f, -6.25f, -10.0f}, 0.1f)), (TileSet{{1, 1}}));
}

TEST(TileCulling, SmallSphereOnATileEdgeAndOnATileCorner)
{
    // Pixel (96, 80): on the edge between columns 2 and 3, inside row 2.
    EXPECT_EQ(tilesOfOneLight(simpleView(), pointLight({-2.5f, -3.75f, -10.0f}, 0.1f)), (TileSet{{2, 2}, {3, 2}}));
    // Pixel (64, 128): the corner shared by columns 1, 2 and rows 3, 4.
    EXPECT_EQ(tilesOfOneLight(simpleView(), pointLight({-5.0f, 0.0f, -10.0f}, 0.1f)),
              (TileSet{{1, 3}, {2, 3}, {1, 4}, {2, 4}}));
}

TEST(TileCulling, SphereOnTheAxisCoversADiscOfTiles)
{
    // On the axis the sphere projects to a circle of radius tan(asin(r / d)) · 128 pixels
    // about the centre (128, 128): r = 2.9827 at d = 10 gives 40 pixels, reaching into
    // columns and rows 2..5 (64..192) but not the corners of the 4x4 block, whose nearest
    // points, e.g. (96, 96), are 45.3 pixels away. The four planes of a corner tile alone
    // would keep it.
    TileSet expected;
    for (int t = 2; t <= 5; ++t)
        for (int u = 3; u <= 4; ++u) {
            expected.insert({t, u});
            expected.insert({u, t});
        }
    ASSERT_EQ(expected.size(), 12u);
    EXPECT_EQ(tilesOfOneLight(simpleView(), pointLight({0.0f, 0.0f, -10.0f}, 2.9827f)), expected);

    // The same through a view matrix: the camera moved and looking along −Z from (5, 1, 10).
    TileCullingView moved = simpleView();
    moved.view = glm::lookAt(glm::vec3(5.0f, 1.0f, 10.0f), glm::vec3(5.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(tilesOfOneLight(moved, pointLight({5.0f, 1.0f, 0.0f}, 2.9827f)), expected);
}

TEST(TileCulling, LightsBehindTheEyeOrBeyondTheFarPlaneLandNowhere)
{
    const TileCullingView view = simpleView();
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, 5.0f}, 2.0f)).empty());
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({3.0f, -2.0f, 1.0f}, 0.5f)).empty());
    // Within the eye's plane but wholly in front of the near plane (depth < 0.1).
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, -0.02f}, 0.05f)).empty());
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, -104.0f}, 3.0f)).empty());
    // Just reaching past the far plane still counts.
    EXPECT_FALSE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, -104.0f}, 4.5f)).empty());
    // Off to the side, outside the field of view.
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({30.0f, 0.0f, -10.0f}, 2.0f)).empty());
}

TEST(TileCulling, LightsContainingTheEyeOrCrossingTheNearPlaneCanLandEverywhere)
{
    const TileCullingView view = simpleView();
    EXPECT_EQ(tilesOfOneLight(view, pointLight({0.5f, 0.5f, 0.5f}, 3.0f)), allTiles(8, 8));
    // Crossing the near plane off-centre: its screen rectangle is the whole screen, but the
    // tile test still drops the tiles on the far side, which it cannot reach.
    const TileSet crossing = tilesOfOneLight(view, pointLight({1.0f, 0.0f, -0.5f}, 0.6f));
    EXPECT_TRUE(crossing.count({7, 4}));
    EXPECT_FALSE(crossing.count({0, 4}));
}

TEST(TileCulling, UnboundedLightsLandEverywhereAndDarkLightsNowhere)
{
    const TileCullingView view = simpleView();
    // a = b = 0: the light never fades, even behind the eye it may light what is seen.
    EXPECT_EQ(tilesOfOneLight(view, pointLight({0.0f, 0.0f, 50.0f}, falloff::kUnboundedRadius)), allTiles(8, 8));
    EXPECT_TRUE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, -10.0f}, 0.0f)).empty());
}

TEST(TileCulling, SpotConesAreDroppedFromTilesOnTheWrongSide)
{
    const TileCullingView view = simpleView();
    // At the screen's centre (pixel 128, between columns 3 and 4) pointing right: a 20° cone
    // lights only x ≥ 0, so no tile wholly left of the centre; column 3 touches the apex.
    const glm::vec3 position(0.0f, 0.0f, -10.0f);
    const TileSet sphere = tilesOfOneLight(view, pointLight(position, 5.0f));
    const TileSet spot = tilesOfOneLight(view, spotLight(position, 5.0f, {1.0f, 0.0f, 0.0f}, 20.0f));
    EXPECT_TRUE(sphere.count({1, 4}));
    EXPECT_TRUE(sphere.count({2, 4}));
    for (const auto& [tx, ty] : spot)
        EXPECT_GE(tx, 3) << "tile (" << tx << ", " << ty << ")";
    EXPECT_TRUE(spot.count({4, 4}));
    EXPECT_TRUE(spot.count({5, 3}));
    EXPECT_LT(spot.size(), sphere.size() / 2);
    // The cone narrows it vertically too: the lit sector rises at most 5 sin 20° = 1.71
    // above or below the light and comes no nearer than depth 10 − 1.71, so its slope
    // y / depth stays within ±0.21: rows 3 and 4 (slopes −0.25..0.25) only.
    for (const auto& [tx, ty] : spot)
        EXPECT_TRUE(ty == 3 || ty == 4) << "tile (" << tx << ", " << ty << ")";

    // Behind the eye and pointing away: its sphere reaches into view, its cone does not.
    EXPECT_FALSE(tilesOfOneLight(view, pointLight({0.0f, 0.0f, 1.0f}, 5.0f)).empty());
    EXPECT_TRUE(tilesOfOneLight(view, spotLight({0.0f, 0.0f, 1.0f}, 5.0f, {0.0f, 0.0f, 1.0f}, 30.0f)).empty());
    // A spot of 90° or wider is culled as its sphere.
    EXPECT_EQ(tilesOfOneLight(view, spotLight(position, 5.0f, {1.0f, 0.0f, 0.0f}, 120.0f)), sphere);
}

TEST(TileCulling, ListsAreCompactAndAscending)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
    std::vector<GpuLight> lights;
    for (int i = 0; i < 200; ++i)
        lights.push_back(pointLight({coordinate(random), coordinate(random), -std::abs(coordinate(random)) - 1.0f},
                                    1.0f + std::abs(coordinate(random)) / 4.0f));
    const TileLightLists lists = cullLightsToTiles(simpleView(), lights);
    std::uint32_t offset = 0;
    for (const TileRange& range : lists.tiles) {
        EXPECT_EQ(range.offset, offset);
        offset += range.count;
    }
    EXPECT_EQ(offset, lists.lightIndices.size());
    for (std::size_t tile = 0; tile < lists.tileCount(); ++tile) {
        const auto indices = lists.lightsOf(tile);
        EXPECT_TRUE(std::is_sorted(indices.begin(), indices.end()));
        EXPECT_EQ(std::adjacent_find(indices.begin(), indices.end()), indices.end());
    }
    // The same lists from a culler reused across frames.
    TileCuller culler;
    culler.cull(simpleView(), std::vector<GpuLight>(lights.begin(), lights.begin() + 50));
    culler.cull(simpleView(), lights);
    EXPECT_EQ(culler.lists().lightIndices, lists.lightIndices);
}

// A⋅S of docs/lighting.md at `point`, through the shared falloff functions, as lightReach in
// shaders/lib/lighting.glsl computes it.
float reachAt(const GpuLight& light, const glm::vec3& point)
{
    const glm::vec3 v = point - glm::vec3(light.positionRadius);
    const float d = glm::length(v);
    const float radius = light.positionRadius.w;
    if (d >= radius || d == 0.0f)
        return 0.0f;
    const glm::vec4& k = light.attenuation;
    const float a =
        k.w == 0.0f ? falloff::classicAttenuation(d, radius, k.x, k.y, k.z) : falloff::rangeAttenuation(d, k.x);
    const float s = falloff::spotFactor(glm::dot(v / d, glm::vec3(light.spotAxisCosCutoff)), light.spotAxisCosCutoff.w,
                                        light.intensityExponent.w);
    return a * s;
}

struct BruteForceResult {
    int dropped = 0;           // (tile, light) pairs seen lit but not listed
    int listedAndSeenLit = 0;  // listed pairs the sampling saw lit
    std::size_t listedPairs = 0;
    std::size_t allPairs = 0;  // lights × tiles
};

// Random lights of every kind around the eye of `view`: points and spots, narrow and wide,
// classic and range falloff, most in front of the eye, some around it, some anywhere.
std::vector<GpuLight> lightsOfEveryKind(const TileCullingView& view, std::uint32_t seed, int lightCount)
{
    const glm::mat3 toWorld = glm::transpose(glm::mat3(view.view));
    const glm::vec3 eye = -(toWorld * glm::vec3(view.view[3]));
    const glm::vec3 viewAxis = toWorld * glm::vec3(0.0f, 0.0f, -1.0f);
    std::mt19937 random(seed);
    const auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); };
    std::vector<GpuLight> lights;
    for (int i = 0; i < lightCount; ++i) {
        Light light;
        // Most in front of the eye, some around it (crossing the near plane, containing the
        // eye), some anywhere (behind it, beyond the far plane).
        const glm::vec3 offset(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
        if (i % 10 == 0)
            light.position = eye + 1.5f * offset;
        else if (i % 10 == 1)
            light.position = eye + view.farPlane * offset;
        else
            light.position = eye + viewAxis * uniform(0.0f, view.farPlane) + 12.0f * offset;
        light.intensity = glm::vec3(uniform(0.1f, 1.0f), uniform(0.1f, 1.0f), uniform(0.1f, 1.0f));
        if (i % 3 == 0) {
            light.falloff = Falloff::Classic;
            light.attenuation = {1.0f, uniform(0.0f, 0.6f), uniform(0.05f, 1.5f)};
        } else {
            light.falloff = Falloff::Range;
            light.range = uniform(0.3f, 7.0f);
        }
        if (i % 2 == 0) {
            light.type = LightType::Spot;
            light.direction = glm::vec3(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
            if (glm::length(light.direction) < 0.1f)
                light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
            light.cutoffDegrees = i % 8 == 0 ? uniform(90.0f, 180.0f) : uniform(1.0f, 89.0f);
            light.exponent = i % 4 == 0 ? 0.0f : uniform(0.0f, 8.0f);
        }
        lights.push_back(packLight(light, 1.0f / 256.0f));
    }
    return lights;
}

// For every tile that does not list a light of lightsOfEveryKind, rays through a grid of the
// tile's pixels (edges included) are sampled densely where they pass through the light's
// sphere, between the near and the far plane: A·S must be zero at every sample.
BruteForceResult bruteForceCheck(const TileCullingView& view, std::uint32_t seed, int lightCount)
{
    const glm::mat3 toWorld = glm::transpose(glm::mat3(view.view));
    const glm::vec3 eye = -(toWorld * glm::vec3(view.view[3]));
    const glm::vec3 viewAxis = toWorld * glm::vec3(0.0f, 0.0f, -1.0f);
    const std::vector<GpuLight> lights = lightsOfEveryKind(view, seed, lightCount);
    const TileLightLists lists = cullLightsToTiles(view, lights);

    const float tanY = std::tan(view.fovY / 2.0f);
    const float tanX = tanY * view.aspect();
    // Whether some sample along the ray through pixel (px, py) is lit by `light`.
    const auto litThroughPixel = [&](const GpuLight& light, float px, float py) {
        const glm::vec3 dir =
            glm::normalize(toWorld * glm::vec3((2.0f * px / static_cast<float>(view.width) - 1.0f) * tanX,
                                               (2.0f * py / static_cast<float>(view.height) - 1.0f) * tanY, -1.0f));
        const glm::vec3 toLight = glm::vec3(light.positionRadius) - eye;
        const float closest = glm::dot(toLight, dir);
        const float miss = glm::length(toLight - closest * dir);
        const float radius = light.positionRadius.w;
        if (miss >= radius)
            return false;
        const float half = std::sqrt(radius * radius - miss * miss);
        constexpr int kSamples = 48;
        for (int s = 0; s <= kSamples; ++s) {
            const float t = closest + half * (2.0f * static_cast<float>(s) / kSamples - 1.0f);
            const float depth = t * glm::dot(dir, viewAxis);
            if (depth < view.nearPlane || depth > view.farPlane)
                continue;
            if (reachAt(light, eye + t * dir) > 0.0f)
                return true;
        }
        return false;
    };

    BruteForceResult result;
    result.listedPairs = lists.lightIndices.size();
    result.allPairs = lights.size() * lists.tileCount();
    for (int ty = 0; ty < lists.tilesY; ++ty)
        for (int tx = 0; tx < lists.tilesX; ++tx) {
            const auto listed = lists.lightsOf(lists.tileIndex(tx, ty));
            const int x0 = tx * view.tileSize, x1 = std::min(x0 + view.tileSize, view.width);
            const int y0 = ty * view.tileSize, y1 = std::min(y0 + view.tileSize, view.height);
            for (std::uint32_t l = 0; l < lights.size(); ++l) {
                const bool inList = std::binary_search(listed.begin(), listed.end(), l);
                bool lit = false;
                // An 11x11 grid of pixel centres, the tile's edge pixels included.
                constexpr int kGrid = 10;
                for (int j = 0; j <= kGrid && !lit; ++j)
                    for (int i = 0; i <= kGrid && !lit; ++i) {
                        const float px = static_cast<float>(x0) + 0.5f +
                                         static_cast<float>((x1 - x0 - 1) * i) / static_cast<float>(kGrid);
                        const float py = static_cast<float>(y0) + 0.5f +
                                         static_cast<float>((y1 - y0 - 1) * j) / static_cast<float>(kGrid);
                        lit = litThroughPixel(lights[l], px, py);
                    }
                if (lit && !inList && ++result.dropped <= 10)
                    ADD_FAILURE() << "light " << l << " lights tile (" << tx << ", " << ty << ") but is not listed";
                result.listedAndSeenLit += lit && inList;
            }
        }
    return result;
}

// Looking down at a slant, as the default scene does.
TileCullingView slantedView(int width, int height)
{
    TileCullingView view;
    view.view = glm::lookAt(glm::vec3(1.0f, 6.0f, 12.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    view.fovY = glm::radians(50.0f);
    view.width = width;
    view.height = height;
    view.nearPlane = 0.5f;
    view.farPlane = 30.0f;
    return view;
}

TEST(TileCulling, NeverDropsALitPixel)
{
    // The last row of tiles is partial.
    const TileCullingView slanted = slantedView(320, 180);
    // A wide, tall view with a distant near plane and small tiles, rolled about its axis.
    TileCullingView wide;
    wide.view = glm::lookAt(glm::vec3(-3.0f, 2.0f, -5.0f), glm::vec3(4.0f, 1.0f, 3.0f), glm::vec3(0.3f, 1.0f, 0.0f));
    wide.fovY = glm::radians(100.0f);
    wide.width = 150;
    wide.height = 200;
    wide.nearPlane = 1.5f;
    wide.farPlane = 25.0f;
    wide.tileSize = 16;

    for (const auto& [view, seed] : {std::pair{slanted, 11u}, std::pair{wide, 12u}}) {
        const BruteForceResult result = bruteForceCheck(view, seed, 400);
        EXPECT_EQ(result.dropped, 0);
        // The sampling does find lit pixels (so it would see a dropped light), and the
        // culling does cull.
        EXPECT_GT(result.listedAndSeenLit, 1000);
        EXPECT_LT(result.listedPairs, result.allPairs / 2);
        RecordProperty("listed_pairs_" + std::to_string(seed), std::to_string(result.listedPairs));
        RecordProperty("listed_pairs_seen_lit_" + std::to_string(seed), std::to_string(result.listedAndSeenLit));
    }
}

// The scale the technique is built for: 65,536 lights at 1280x720. No time limit (this
// machine's speed is not the test's business), but every light in view must land somewhere
// and the lists must stay within what the tiles can see.
TEST(TileCulling, ManyLightsAtFullResolution)
{
    TileCullingView view;
    view.view = glm::lookAt(glm::vec3(0.0f, 6.0f, 14.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    view.fovY = glm::radians(45.0f);
    view.width = 1280;
    view.height = 720;
    view.nearPlane = 0.1f;
    view.farPlane = 200.0f;
    std::mt19937 random(5);
    const auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); };
    std::vector<GpuLight> lights;
    for (int i = 0; i < 65536; ++i)
        lights.push_back(
            pointLight({uniform(-20.0f, 20.0f), uniform(0.2f, 2.0f), uniform(-20.0f, 20.0f)}, uniform(0.2f, 0.5f)));
    TileCuller culler;
    const auto start = std::chrono::steady_clock::now();
    const TileLightLists& lists = culler.cull(view, lights);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("cull_ms", std::to_string(ms));
    ASSERT_EQ(view.tileSize, 16);
    EXPECT_EQ(lists.tileCount(), 80u * 45u);
    EXPECT_GT(lists.lightIndices.size(), lights.size() / 2);
    // Small lights: a handful of tiles each, not the whole screen.
    EXPECT_LT(lists.lightIndices.size(), lights.size() * 8);
}

// Culling on several threads (issue 41) gives the lists of one thread to the byte: each
// thread culls runs of consecutive lights into lists of its own, which are joined in light
// order. Light counts that split unevenly over the threads' runs, fewer lights than runs,
// none; unbounded lights (in every tile) and lights that reach nothing among them; and one
// culler reused at a falling and a rising count, as the technique reuses it every frame.
TEST(TileCulling, ThreadsGiveTheListsOfOneThread)
{
    // Partial tiles in the last row and column.
    TileCullingView view = slantedView(331, 187);
    view.tileSize = 16;
    std::vector<GpuLight> lights = lightsOfEveryKind(view, 21, 5003);
    lights[17].positionRadius.w = falloff::kUnboundedRadius;
    lights[4000].positionRadius.w = falloff::kUnboundedRadius;
    lights[99].positionRadius.w = 0.0f;

    TileCuller serial(1);
    std::vector<std::unique_ptr<TileCuller>> parallel;
    for (const unsigned threads : {2u, 3u, 7u, 16u})
        parallel.push_back(std::make_unique<TileCuller>(threads));
    for (const std::size_t count : {std::size_t{5003}, std::size_t{0}, std::size_t{1}, std::size_t{13},
                                    std::size_t{100}, std::size_t{1001}, std::size_t{5003}}) {
        const std::span<const GpuLight> some(lights.data(), count);
        const TileLightLists& expected = serial.cull(view, some);
        ASSERT_EQ(expected.tileCount(), 21u * 12u);
        for (const auto& culler : parallel) {
            const TileLightLists& lists = culler->cull(view, some);
            ASSERT_EQ(lists.tileCount(), expected.tileCount());
            for (std::size_t tile = 0; tile < lists.tileCount(); ++tile) {
                EXPECT_EQ(lists.tiles[tile].offset, expected.tiles[tile].offset) << count << " lights, tile " << tile;
                EXPECT_EQ(lists.tiles[tile].count, expected.tiles[tile].count) << count << " lights, tile " << tile;
            }
            EXPECT_EQ(lists.lightIndices, expected.lightIndices) << count << " lights";
        }
    }
    // The culling culls: more pairs than the unbounded lights make, fewer than half of all.
    const TileLightLists& lists = serial.cull(view, lights);
    EXPECT_GT(lists.lightIndices.size(), 3 * lists.tileCount());
    EXPECT_LT(lists.lightIndices.size(), lights.size() * lists.tileCount() / 2);
}

}  // namespace
}  // namespace manylights
