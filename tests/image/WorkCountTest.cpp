// Fragment-shader invocation counts (pipeline statistics) are deterministic work, unlike
// milliseconds: they show what each technique's passes cost on any machine.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::runCliOrFail;
using test::scratchDirectory;

nlohmann::json statsFor(const std::filesystem::path& dir, const std::string& technique)
{
    const std::filesystem::path stats = dir / (technique + ".json");
    runCliOrFail({"render", "-o", (dir / (technique + ".png")).string(), "--size", "320x180", "--technique",
                  technique, "--stats", stats.string()});
    std::ifstream in(stats);
    return nlohmann::json::parse(in);
}

TEST(WorkCounts, DeferredShadesEachPixelOnceForwardShadesOverdraw)
{
    const auto dir = scratchDirectory();
    const Image normals = renderPfm("", dir / "normal.pfm", {"--size", "320x180", "--view", "normal"});
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i < normals.rgb.size(); i += 3)
        covered += normals.rgb[i] != 0.0f || normals.rgb[i + 1] != 0.0f || normals.rgb[i + 2] != 0.0f;
    ASSERT_GT(covered, 320u * 180u / 4) << "the default scene should fill much of the frame";

    const nlohmann::json deferred = statsFor(dir, "deferred");
    const nlohmann::json forward = statsFor(dir, "forward");
    if (deferred["passes"][1]["fragment_invocations"].is_null())
        GTEST_SKIP() << "the driver cannot count fragment-shader invocations";
    const auto lighting = deferred["passes"][1]["fragment_invocations"].get<std::uint64_t>();
    const auto geometry = deferred["passes"][0]["fragment_invocations"].get<std::uint64_t>();
    const auto forwardShaded = forward["passes"][0]["fragment_invocations"].get<std::uint64_t>();
    // The full-screen lighting pass shades every covered pixel at least once. Whether the
    // depth test (GL_GREATER against the G-buffer) keeps the background from being counted
    // is the driver's business: a GPU rejects it before shading, llvmpipe counts whole
    // 4x4 blocks it then masks. Either way one screen triangle costs at most one invocation
    // per pixel plus the helper quads along its edges, well under 10% more.
    EXPECT_GE(lighting, covered);
    EXPECT_LE(lighting, 320u * 180u * 11u / 10u);
    // Forward shades every rasterised fragment, hidden ones included: the same geometry as
    // the G-buffer pass, so the same count, and more than the lighting pass.
    EXPECT_EQ(forwardShaded, geometry);
    EXPECT_GT(forwardShaded, lighting);
}

}  // namespace
}  // namespace manylights
