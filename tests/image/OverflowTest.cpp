// No light is ever silently dropped: where a technique's per-region list has a capacity,
// exceeding it must still light correctly and be reported. The seed G-buffer layout keeps the
// comparison with forward exact (the compact layout's own bound is TechniqueAgreementTest's).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/TiledTechnique.h"

namespace manylights {
namespace {

TEST(Overflow, TiledListsOverflowAndStillMatchForward)
{
    // 1200 lights whose ranges each cover the whole scene: every tile is reached by more
    // lights than its shared-memory list holds (kTiledTileCapacity = 1024).
    static_assert(kTiledTileCapacity < 1200);
    const auto dir = test::scratchDirectory();
    const std::string scene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/every_light_everywhere.json";
    const Image forward = test::renderPfm(scene, dir / "forward.pfm", {"--size", "64x48", "--technique", "forward"});
    const Image tiled = test::renderPfm(
        scene, dir / "tiled.pfm",
        {"--size", "64x48", "--gbuffer", "seed", "--technique", "tiled", "--stats", (dir / "stats.json").string()});
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_GT(stats["tile_overflows"].get<double>(), 0.0);
    ASSERT_EQ(forward.rgb.size(), tiled.rgb.size());
    int lit = 0;
    for (std::size_t i = 0; i < forward.rgb.size(); ++i) {
        // The same tolerance as TechniqueAgreementTest.cpp, for the same reasons.
        ASSERT_NEAR(tiled.rgb[i], forward.rgb[i], 1e-5 * std::abs(forward.rgb[i]) + 1e-6) << "value " << i;
        lit += forward.rgb[i] > 0.01f;
    }
    EXPECT_GT(lit, 1000);
}

TEST(Overflow, ClusteredMasksHoldEveryLightInEveryCluster)
{
    // The clustered masks have a bit for every light of a batch, so a cluster reached by all
    // of them keeps all of them: every covered pixel evaluates all 1200 lights, exactly the
    // pairs in range, and the image matches forward.
    const auto dir = test::scratchDirectory();
    const std::string scene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/every_light_everywhere.json";
    const Image forward = test::renderPfm(scene, dir / "forward.pfm", {"--size", "64x48", "--technique", "forward"});
    const Image clustered =
        test::renderPfm(scene, dir / "clustered.pfm",
                        {"--size", "64x48", "--gbuffer", "seed", "--technique", "clustered", "--count-work", "--stats",
                         (dir / "stats.json").string()});
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    const auto inRange = stats["in_range_pairs"].get<std::uint64_t>();
    EXPECT_GT(inRange, 1200u * 1000u);
    EXPECT_EQ(inRange % 1200u, 0u);
    EXPECT_EQ(stats["light_evaluations"].get<std::uint64_t>(), inRange);
    for (std::size_t i = 0; i < forward.rgb.size(); ++i)
        ASSERT_NEAR(clustered.rgb[i], forward.rgb[i], 1e-5 * std::abs(forward.rgb[i]) + 1e-6) << "value " << i;
}

}  // namespace
}  // namespace manylights
