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

TEST(Overflow, ClusteredListsGrowWithTheLights)
{
    // The clustered index buffer has no fixed capacity: with every light in every cluster
    // it holds lights × occupied clusters entries, and the image still matches forward.
    const auto dir = test::scratchDirectory();
    const std::string scene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/every_light_everywhere.json";
    const Image forward = test::renderPfm(scene, dir / "forward.pfm", {"--size", "64x48", "--technique", "forward"});
    const Image clustered = test::renderPfm(scene, dir / "clustered.pfm",
                                            {"--size", "64x48", "--gbuffer", "seed", "--technique", "clustered", "--stats",
                                             (dir / "stats.json").string()});
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_GE(stats["cluster_light_indices"].get<double>(), 1200.0 * 4.0);
    for (std::size_t i = 0; i < forward.rgb.size(); ++i)
        ASSERT_NEAR(clustered.rgb[i], forward.rgb[i], 1e-5 * std::abs(forward.rgb[i]) + 1e-6) << "value " << i;
}

}  // namespace
}  // namespace manylights
