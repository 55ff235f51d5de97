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

}  // namespace
}  // namespace manylights
