// The shadow-page pool's size as a user meets it through the executable (issue 47, "The
// pool"): a pool below what the frame's faces need at one page each says so in one stderr line
// that names the size needed, and that size then holds every face; a pool between the two
// lowers levels and shadows every light the default pool does. The scene is the closed room of
// tests/support/ShadowRoomScene.h (4,097 lights, about 9,000 faces seen from inside at 64x64);
// tests/gl/ShadowPagesTest.cpp checks its pixels. Bad sizes exiting 2 are CliTest's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "scene/ShadowSelection.h"
#include "tests/support/ShadowRoomScene.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;
using test::writeFile;

struct PoolRun {
    int exitCode = -1;
    std::string stderrText;
    nlohmann::json stats;
};

// Renders the room three frames (the line is said once, not per frame) with every light
// shadowed in a pool of `poolMiB` (0: the default).
PoolRun renderRoom(const std::filesystem::path& dir, int poolMiB)
{
    std::vector<std::string> args{"render",
                                  (dir / "room.json").string(),
                                  "-o",
                                  (dir / "room.pfm").string(),
                                  "--size",
                                  "64x64",
                                  "--frames",
                                  "3",
                                  "--shadow-lights",
                                  "all",
                                  "--stats",
                                  (dir / "stats.json").string()};
    if (poolMiB != 0) {
        args.push_back("--shadow-pool-mib");
        args.push_back(std::to_string(poolMiB));
    }
    const test::ProcessResult result = runExecutable(args);
    PoolRun run{.exitCode = result.exitCode, .stderrText = result.stderrText, .stats = {}};
    if (result.exitCode == 0) {
        std::ifstream in(dir / "stats.json");
        run.stats = nlohmann::json::parse(in);
    }
    std::filesystem::remove(dir / "stats.json");
    return run;
}

double counter(const PoolRun& run, const char* name) { return run.stats.at(name).get<double>(); }

TEST(ShadowPoolCli, APoolTooSmallForAPageAFaceSaysTheSizeNeededOnce)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "room.json", test::roomSceneJson(test::kRoomOutsideLights));

    // 4 MiB is 4,096 pages: fewer than the faces.
    const PoolRun small = renderRoom(dir, 4);
    ASSERT_EQ(small.exitCode, 0) << small.stderrText;
    EXPECT_EQ(std::count(small.stderrText.begin(), small.stderrText.end(), '\n'), 1) << small.stderrText;
    const std::regex line(R"(^manylights: warning: the shadow pool of 4 MiB cannot give each of this frame's (\d+) )"
                          R"(shadow faces a page: it needs (\d+) MiB \(--shadow-pool-mib\).*\n$)");
    std::smatch match;
    ASSERT_TRUE(std::regex_match(small.stderrText, match, line)) << small.stderrText;
    const int faces = std::stoi(match[1].str());
    const int neededMiB = std::stoi(match[2].str());
    EXPECT_GT(counter(small, "shadow_faces_dropped"), 0.0);
    EXPECT_EQ(counter(small, "shadow_faces") + counter(small, "shadow_faces_dropped"), faces);
    EXPECT_EQ(counter(small, "shadow_pool_bytes"), 4.0 * (1 << 20));
    // A page (1 KiB) for each face, at least.
    EXPECT_GE(neededMiB * 1024, faces);

    // The size named, rounded up to the pool's grain, holds a page for every face: no line, no
    // face dropped, and levels lowered (it is the least that holds them).
    const PoolRun named =
        renderRoom(dir, (neededMiB + kShadowPoolGrainMiB - 1) / kShadowPoolGrainMiB * kShadowPoolGrainMiB);
    ASSERT_EQ(named.exitCode, 0) << named.stderrText;
    EXPECT_EQ(named.stderrText, "");
    EXPECT_EQ(counter(named, "shadow_faces_dropped"), 0.0);
    EXPECT_EQ(counter(named, "shadow_faces"), faces);
    EXPECT_GT(counter(named, "shadow_levels_lowered"), 0.0);

    // The default pool shadows the same lights.
    const PoolRun standard = renderRoom(dir, 0);
    ASSERT_EQ(standard.exitCode, 0) << standard.stderrText;
    EXPECT_EQ(counter(standard, "shadow_faces_dropped"), 0.0);
    EXPECT_EQ(counter(named, "shadow_lights_with_faces"), counter(standard, "shadow_lights_with_faces"));
    EXPECT_GT(counter(standard, "shadow_lights_with_faces"), 1000.0);
}

// The transparent surfaces' receivers are marked too ("the visible depth and the transparent
// surfaces' receivers"): a glass pane lit by one point light at (0, 0, 1) through a box halfway
// between them, with no opaque surface in view and the box beyond the camera's narrow view, so
// that only the pane's own pixels can ask for the light's pages. The rays from the light to the
// pane's centre (3, 0, 0) pass through the box (1.35..1.65, ±0.15, 0.35..0.65) at (1.5, 0, 0.5):
// there the pane gets nothing of the light, exactly as under the same light of intensity 0; at
// |y| = 0.55 no ray meets the box (it would need |y| ≤ 0.15 at a fraction 1/s of the way, s at
// most 2.86), so the pane is lit exactly as without shadows. Exact equalities: the shadow factor
// is 0 in the umbra and 1 where lit, and adding a zero term changes no float.
TEST(ShadowPoolCli, TransparentReceiversAreMarkedAndShadowed)
{
    const auto scene = [](double intensity) {
        return R"({"camera": {"eye": [3, 0, 6], "look_at": [3, 0, 0], "fov_y": 15},
            "ambient": [0.05, 0.05, 0.05],
            "lights": [{"type": "point", "pos": [0, 0, 1], "intensity": [)" +
               std::to_string(intensity) + ", " + std::to_string(intensity) + ", " + std::to_string(intensity) +
               R"(], "range": 6}],
            "materials": {"glass": {"diffuse": [0.8, 0.8, 0.8], "opacity": 0.5},
                          "grey": {"diffuse": [0.5, 0.5, 0.5]}},
            "objects": [
              {"mesh": {"primitive": "plane", "size": [1.2, 1.2]}, "material": "glass",
               "transform": {"translate": [3, 0, 0], "rotate": [90, 0, 0]}},
              {"mesh": {"primitive": "box", "size": [0.3, 0.3, 0.3]}, "material": "grey",
               "transform": {"translate": [1.5, 0, 0.5]}}]})";
    };
    const auto dir = scratchDirectory();
    writeFile(dir / "lit.json", scene(2.0));
    writeFile(dir / "dark.json", scene(0.0));
    const std::vector<std::string> size{"--size", "64x64"};
    std::vector<std::string> shadowed = size;
    shadowed.insert(shadowed.end(), {"--shadow-lights", "all", "--stats", (dir / "stats.json").string()});
    const Image withShadows = test::renderPfm((dir / "lit.json").string(), dir / "shadowed.pfm", shadowed);
    const Image without = test::renderPfm((dir / "lit.json").string(), dir / "unshadowed.pfm", size);
    const Image dark = test::renderPfm((dir / "dark.json").string(), dir / "dark.pfm", size);
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(stats["shadow_lights_with_faces"].get<double>(), 1.0);  // asked for by the pane alone

    // The pane's centre: pixel (32, 32) looks at (3, 0, 0) (the camera looks straight at it).
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(withShadows.pixel(32, 32)[c], dark.pixel(32, 32)[c]) << c;
        EXPECT_LT(withShadows.pixel(32, 32)[c], without.pixel(32, 32)[c]) << c;
    }
    // |y| = 0.55: rows 32 ∓ 0.55 / (6 tan 7.5°) · 32 = 32 ∓ 22.3, columns across the pane.
    for (const int row : {10, 54})
        for (const int column : {16, 32, 48})
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(withShadows.pixel(column, row)[c], without.pixel(column, row)[c]) << column << ", " << row;
                EXPECT_GT(without.pixel(column, row)[c], dark.pixel(column, row)[c]) << column << ", " << row;
            }
}

}  // namespace
}  // namespace manylights
