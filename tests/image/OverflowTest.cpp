// No light is ever silently dropped by a per-region light set. tiled and clustered list every
// light that may reach a tile or cluster (render/culling/ClusterLists.h: storage planned from the
// frame before, the frame redone when it did not hold), so a region reached by all of them
// keeps all of them. The seed G-buffer layout keeps the comparison with forward exact (the
// compact layout's own bound is TechniqueAgreementTest's). Lights over the whole view are in
// the lists' global list (walked by every pixel, in the lights' order); GlobalLightsTest.cpp
// has more of them than it holds, which take pairs again.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "TestSupport.h"

namespace manylights {
namespace {

class EveryLightEverywhere : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLightEverywhere, EveryPixelEvaluatesEveryLightAndMatchesForward)
{
    // 1200 lights whose ranges each cover the whole scene (more than the 1024 that tiled's
    // shared-memory list once held): every covered pixel must evaluate all 1200, exactly the
    // pairs in range, and the image must match forward.
    const auto dir = test::scratchDirectory();
    const std::string scene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/every_light_everywhere.json";
    const Image forward = test::renderPfm(scene, dir / "forward.pfm", {"--size", "64x48", "--technique", "forward"});
    const Image image = test::renderPfm(scene, dir / "technique.pfm",
                                        {"--size", "64x48", "--gbuffer", "seed", "--technique", GetParam(),
                                         "--count-work", "--stats", (dir / "stats.json").string()});
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    const auto inRange = stats["in_range_pairs"].get<std::uint64_t>();
    EXPECT_GT(inRange, 1200u * 1000u);
    EXPECT_EQ(inRange % 1200u, 0u);
    EXPECT_EQ(stats["light_evaluations"].get<std::uint64_t>(), inRange);
    ASSERT_EQ(forward.rgb.size(), image.rgb.size());
    for (std::size_t i = 0; i < forward.rgb.size(); ++i) {
        // The same tolerance as TechniqueAgreementTest.cpp, for the same reasons.
        ASSERT_NEAR(image.rgb[i], forward.rgb[i], 1e-5 * std::abs(forward.rgb[i]) + 1e-6) << "value " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Overflow, EveryLightEverywhere, ::testing::Values("tiled", "clustered"));

}  // namespace
}  // namespace manylights
