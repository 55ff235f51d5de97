// The tiles whose cluster lists are longer than a part (shaders/cluster_long_lists.comp,
// render/culling/ClusterLists.h): listed for the lighting's later parts, with the indirect
// dispatch over them grown along x up to 32,768 workgroups and then along z
// (shaders/lib/listed_dispatch.glsl), since GL promises only 65,535 along x and an 8K image has
// 129,600 tiles. The pass alone, on list lengths made here for a 8192x4352 viewport (139,264
// tiles): rendering a frame whose every tile holds a long list at that size would take hours
// on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ClusterListStatus.h"
#include "GlContextTest.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/culling/ClusterGrid.h"
#include "render/culling/ClusterLists.h"
#include "render/culling/CullingVariant.h"
#include "render/programs/Bindings.h"
#include "render/scene/GpuFrame.h"

namespace manylights {
namespace {

class LongListTilesTest : public GlContextTest {};

// Where the long tiles' counts sit in ClusterListStatus (tests/gl/ClusterListStatus.h).
constexpr std::size_t kLongTileGroupsIndex = 0;  // x, y, z
constexpr std::size_t kLongestListIndex = 4;
constexpr std::size_t kLongTilesIndex = 15;

TEST_F(LongListTilesTest, ListsEveryLongTilePastOneRowOfWorkgroups)
{
    const gl::Program program("long list tiles test", {{GL_COMPUTE_SHADER, "cluster_long_lists.comp"}},
                              CullingVariant{.grid = kClusteredGridShape, .lightLists = true}.toDefines());
    constexpr std::uint32_t kWidth = 8192;
    constexpr std::uint32_t kHeight = 4352;
    const std::uint32_t tilesX = kWidth / kClusteredGridShape.tileSize;
    const std::uint32_t tiles = tilesX * (kHeight / kClusteredGridShape.tileSize);
    const auto slices = static_cast<std::uint32_t>(kClusteredGridShape.slices);
    ASSERT_GT(tiles, 4u * 32768u);

    // Every tile but every seventh has one slice over a part long (in a different slice from
    // tile to tile), the others short lists only; one tile holds the longest.
    std::vector<std::uint32_t> counts(std::size_t{tiles} * slices, 0u);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t tile = 0; tile < tiles; ++tile) {
        const bool isLong = tile % 7 != 0;
        counts[std::size_t{tile} * slices + tile % slices] = isLong ? kClusterListPart + 1 + tile % 100 : 17;
        if (isLong)
            expected.push_back(tile);
    }
    counts[std::size_t{12345} * slices + 3] = 9000;
    const auto longTiles = static_cast<std::uint32_t>(expected.size());
    ASSERT_GT(longTiles, 3u * 32768u);

    FrameUniforms frame{};
    frame.viewport = glm::vec4(kWidth, kHeight, 1.0f / kWidth, 1.0f / kHeight);
    gl::Buffer frameBuffer("test frame", sizeof frame, &frame, 0);
    gl::Buffer countBuffer("test list counts", counts.size() * sizeof(std::uint32_t), counts.data(), 0);
    std::vector<std::uint32_t> status(test::kClusterListStatusUints, 0u);
    status[kLongTileGroupsIndex + 1] = 1;  // as ClusterLists::Status starts: x and z grow from 0
    gl::Buffer statusBuffer("test status", status.size() * sizeof(std::uint32_t), status.data(), 0);
    gl::Buffer listed("test long tiles", std::size_t{tiles} * sizeof(std::uint32_t), nullptr, 0);
    frameBuffer.bindBase(GL_UNIFORM_BUFFER, bindings::FRAME_BLOCK_BINDING);
    countBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_COUNTS_BUFFER_BINDING);
    statusBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
    listed.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LONG_TILES_BUFFER_BINDING);
    program.use();
    glDispatchCompute((tiles + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

    statusBuffer.read(0, status.size() * sizeof(std::uint32_t), status.data());
    EXPECT_EQ(status[kLongTilesIndex], longTiles);
    EXPECT_EQ(status[kLongestListIndex], 9000u);
    // One workgroup per listed tile: a full first row, then rows along z.
    EXPECT_EQ(status[kLongTileGroupsIndex], 32768u);
    EXPECT_EQ(status[kLongTileGroupsIndex + 1], 1u);
    EXPECT_EQ(status[kLongTileGroupsIndex + 2], (longTiles + 32767u) / 32768u);
    // Every long tile once, in whatever order the invocations ran.
    std::vector<std::uint32_t> tilesListed(longTiles);
    listed.read(0, tilesListed.size() * sizeof(std::uint32_t), tilesListed.data());
    std::sort(tilesListed.begin(), tilesListed.end());
    EXPECT_EQ(tilesListed, expected);
}

}  // namespace
}  // namespace manylights
