// The shadow-page pool's CPU parts, without a GL context: the buddy allocator of the atlas'
// pages (render/shadows/PageAllocator.h) and the faces' geometry (render/shadows/ShadowFaces.h),
// which the shaders' (shaders/lib/shadow_pages.glsl) must match.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include <glm/glm.hpp>

#include "PackedLights.h"
#include "render/shadows/PageAllocator.h"
#include "render/shadows/ShadowFaces.h"
#include "render/shadows/ShadowPageLayout.h"

namespace manylights {
namespace {

bool overlap(const PageBlock& a, const PageBlock& b)
{
    return a.x < b.x + b.side && b.x < a.x + a.side && a.y < b.y + b.side && b.y < a.y + a.side;
}

TEST(PageAllocator, FillsItsRootsWithoutOverlapAndMergesWhatIsFreed)
{
    PageAllocator pages(3, 2);  // two roots in the first row, one in the second
    EXPECT_EQ(pages.pagesAcross(), 2 * PageAllocator::kRootPages);
    EXPECT_EQ(pages.pagesDown(), 2 * PageAllocator::kRootPages);
    EXPECT_EQ(pages.capacityPages(), 3u * PageAllocator::kRootPages * PageAllocator::kRootPages);

    // Largest first, as the pool places them: every page of the three roots used, none twice.
    std::vector<PageBlock> blocks;
    std::vector<int> sides = {64, 32, 32, 32, 32};
    sides.insert(sides.end(), 8, 16);
    sides.insert(sides.end(), 32, 8);
    for (const int side : sides)
        if (const std::optional<PageBlock> block = pages.allocate(side))
            blocks.push_back(*block);
    ASSERT_EQ(blocks.size(), sides.size());
    std::size_t used = 0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        used += static_cast<std::size_t>(blocks[i].side) * blocks[i].side;
        EXPECT_EQ(blocks[i].x % blocks[i].side, 0);
        EXPECT_EQ(blocks[i].y % blocks[i].side, 0);
        // The short second row has one root: nothing in the place of the missing one.
        EXPECT_FALSE(blocks[i].y >= PageAllocator::kRootPages && blocks[i].x >= PageAllocator::kRootPages);
        for (std::size_t j = 0; j < i; ++j)
            EXPECT_FALSE(overlap(blocks[i], blocks[j])) << i << " and " << j;
    }
    EXPECT_EQ(used, pages.usedPages());
    EXPECT_EQ(pages.usedPages(), pages.capacityPages());
    EXPECT_FALSE(pages.allocate(1));  // full

    // Freeing every block merges the quarters back: a whole root fits again, three of them.
    for (const PageBlock& block : blocks)
        pages.free(block);
    EXPECT_EQ(pages.usedPages(), 0u);
    for (int root = 0; root < 3; ++root)
        EXPECT_TRUE(pages.allocate(PageAllocator::kRootPages)) << root;
    EXPECT_FALSE(pages.allocate(1));
}

TEST(PageAllocator, TheSameRequestsPlaceTheSameBlocks)
{
    PageAllocator a(4, 4);
    PageAllocator b(4, 4);
    for (const int side : {1, 4, 2, 16, 1, 64, 8})
        EXPECT_EQ(a.allocate(side), b.allocate(side));
    // The lowest row, then column, first.
    PageAllocator c(2, 2);
    EXPECT_EQ(c.allocate(1), (PageBlock{0, 0, 1}));
    EXPECT_EQ(c.allocate(1), (PageBlock{1, 0, 1}));
    EXPECT_EQ(c.allocate(1), (PageBlock{0, 1, 1}));
}

using test::pointLight;
using test::spotLight;

TEST(ShadowFaces, LevelsFillWholePagesWithTheirGuardTexels)
{
    for (int level = 0; level <= shadowpages::SHADOW_MAX_LEVEL; ++level)
        EXPECT_EQ(shadowFaceResolution(level) + 2 * shadowpages::SHADOW_GUARD_TEXELS,
                  (1 << level) * shadowpages::SHADOW_PAGE_TEXELS);
    EXPECT_EQ(shadowFaceResolution(0), 14);
    EXPECT_EQ(shadowFaceResolution(6), 1022);
}

TEST(ShadowFaces, SpotsUpTo75DegreesHaveOneFacePointsAndWiderSpotsSix)
{
    EXPECT_EQ(shadowFaceCount(pointLight({0, 0, 0}, 1)), 6);
    EXPECT_EQ(shadowFaceCount(spotLight({0, 0, 0}, 1, {0, -1, 0}, 30)), 1);
    EXPECT_EQ(shadowFaceCount(spotLight({0, 0, 0}, 1, {0, -1, 0}, 74)), 1);
    EXPECT_EQ(shadowFaceCount(spotLight({0, 0, 0}, 1, {0, -1, 0}, 76)), 6);
    EXPECT_EQ(shadowFaceCount(spotLight({0, 0, 0}, 1, {0, -1, 0}, 120)), 6);
}

// The cube faces' frames, as shaders/lib/shadow_pages.glsl writes them with selects: the C++
// frames (lookAt's, for kCubeFaceUp) must be these exactly, or the pages drawn and the texels
// looked up would be mirrored or turned against each other.
TEST(ShadowFaces, CubeFramesAreTheShadersOwn)
{
    const glm::vec3 axis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 across[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
    const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const GpuLight light = pointLight({1, 2, 3}, 5);
    for (int face = 0; face < 6; ++face) {
        const ShadowFaceFrame frame = shadowFaceFrame(light, face);
        EXPECT_EQ(frame.axis, axis[face]) << face;
        EXPECT_EQ(frame.across, across[face]) << face;
        EXPECT_EQ(frame.up, up[face]) << face;
        EXPECT_EQ(frame.tanHalf, 1.0f);
        // A right-handed view (lookAt's): across × up = −axis, so no face is mirrored.
        EXPECT_EQ(glm::cross(frame.across, frame.up), -frame.axis) << face;
    }
}

TEST(ShadowFaces, TheViewProjectionPutsTheAxisAtTheCentreAndTheFarPlaneAtDepthOne)
{
    const GpuLight spot = spotLight({1, 4, -2}, 6, {0.3f, -1, 0.2f}, 40);
    const ShadowFaceFrame frame = shadowFaceFrame(spot, 0);
    // A field of view 5% beyond the cone, in the tangent of its half angle.
    EXPECT_NEAR(frame.tanHalf, std::tan(glm::radians(40.0f)) * shadowpages::SHADOW_SPOT_FACE_SCALE, 1e-5);
    const glm::vec3 position(spot.positionRadius);
    const float near = 0.006f;
    const float far = 6.0f;
    const glm::mat4 viewProjection = shadowFaceViewProjection(position, frame, near, far);
    const auto project = [&](const glm::vec3& p) {
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        return glm::vec3(clip) / clip.w;
    };
    const glm::vec3 centre = project(position + 3.0f * frame.axis);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5);
    EXPECT_NEAR(project(position + far * frame.axis).z, 1.0f, 1e-5);
    EXPECT_NEAR(project(position + near * frame.axis).z, -1.0f, 1e-4);
    // The cone's edge direction across lands at 1 / SHADOW_SPOT_FACE_SCALE of the half-width.
    const glm::vec3 edge = frame.axis + std::tan(glm::radians(40.0f)) * frame.across;
    EXPECT_NEAR(project(position + edge).x, 1.0f / shadowpages::SHADOW_SPOT_FACE_SCALE, 1e-4);
    EXPECT_NEAR(project(position + edge).y, 0.0f, 1e-5);
}

TEST(ShadowFaces, MarksGiveTheirCellsAndHighestLevel)
{
    const std::uint32_t mark = (1u << 5) | (1u << 10) | (1u << (shadowpages::SHADOW_MARK_LEVEL_SHIFT + 1)) |
                               (1u << (shadowpages::SHADOW_MARK_LEVEL_SHIFT + 3));
    EXPECT_EQ(markedCells(mark), (1u << 5) | (1u << 10));
    EXPECT_EQ(markedLevel(mark), 3);
    EXPECT_EQ(markedLevel(1u << 7), -1);  // cells without a level: no mark made it
}

TEST(ShadowFaces, APartIsTheSmallestSquareAroundItsCellsOrTheWholeFace)
{
    // Level 0 is always the whole face, one page.
    EXPECT_EQ(shadowFaceRegion(1u, 0), coarseShadowFaceRegion());
    EXPECT_TRUE(coarseShadowFaceRegion().whole);
    EXPECT_EQ(coarseShadowFaceRegion().pages, 1);
    EXPECT_EQ(shadowFacePages(coarseShadowFaceRegion()), 1u);
    // Every cell marked: the whole face, 2^level pages on a side, no coarse page beside it.
    const ShadowFaceRegion all = shadowFaceRegion(0xffffu, 4);
    EXPECT_TRUE(all.whole);
    EXPECT_EQ(all.pages, 16);
    EXPECT_EQ(all.x0, -shadowpages::SHADOW_GUARD_TEXELS);
    EXPECT_EQ(shadowFacePages(all), 256u);
    // One corner cell at level 4 (254 texels across, 63.5 a cell): 63.5 + 2 + 2 texels of
    // margin and guard, within 8 pages of 16 texels on a side (then the coarse page beside it),
    // kept inside the whole face's square (its first texel the guard's, −1).
    const ShadowFaceRegion corner = shadowFaceRegion(1u, 4);
    EXPECT_FALSE(corner.whole);
    EXPECT_EQ(corner.pages, 8);
    EXPECT_EQ(corner.x0, -shadowpages::SHADOW_GUARD_TEXELS);
    EXPECT_EQ(corner.y0, -shadowpages::SHADOW_GUARD_TEXELS);
    EXPECT_EQ(shadowFacePages(corner), 65u);
    // The far corner cell: the square kept inside the whole face's.
    const ShadowFaceRegion farCorner = shadowFaceRegion(1u << 15, 4);
    EXPECT_EQ(farCorner.pages, 8);
    EXPECT_EQ(farCorner.x0 + farCorner.pages * shadowpages::SHADOW_PAGE_TEXELS,
              shadowFaceResolution(4) + shadowpages::SHADOW_GUARD_TEXELS);
}

TEST(ShadowFaces, CastersAreKeptOnlyWhereTheyMayDrawIntoThePart)
{
    const GpuLight light = pointLight({0, 4, 0}, 10);
    const glm::vec3 position(light.positionRadius);
    const ShadowFaceFrame down = shadowFaceFrame(light, 3);  // −Y
    const ShadowFaceRegion whole = shadowFaceRegion(0xffffu, 3);
    const float near = 0.01f;
    const float far = 10.0f;
    // Below the light: in the −Y face's view.
    EXPECT_TRUE(casterMayMeetFace({{-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}}, position, near, far, down, whole));
    // Above it: behind the face.
    EXPECT_FALSE(casterMayMeetFace({{-0.5f, 5, -0.5f}, {0.5f, 6, 0.5f}}, position, near, far, down, whole));
    // Beyond the light's reach.
    EXPECT_FALSE(casterMayMeetFace({{20, 0, 20}, {21, 1, 21}}, position, near, far, down, whole));
    // Below, but outside the 90° view (x far beyond the depth).
    EXPECT_FALSE(casterMayMeetFace({{6, 3, -0.5f}, {7, 3.5f, 0.5f}}, position, near, far, down, whole));
    // Around the light, reaching behind its near plane: kept (the depth clamp draws it).
    EXPECT_TRUE(casterMayMeetFace({{-1, 3, -1}, {1, 5, 1}}, position, near, far, down, whole));
    // A part of one corner cell: a box under the opposite corner is not drawn into it. The −Y
    // face's image runs along x (across) and −z (up): cell 0 is −x, +z; cell 15 +x, −z.
    const ShadowFaceRegion corner = shadowFaceRegion(1u, 3);
    const ShadowFaceRegion opposite = shadowFaceRegion(1u << 15, 3);
    const Bounds underCorner{{-3.0f, 0, 2.5f}, {-2.5f, 0.5f, 3.0f}};
    const Bounds underOpposite{{2.5f, 0, -3.0f}, {3.0f, 0.5f, -2.5f}};
    EXPECT_TRUE(casterMayMeetFace(underCorner, position, near, far, down, corner));
    EXPECT_FALSE(casterMayMeetFace(underCorner, position, near, far, down, opposite));
    EXPECT_NE(casterMayMeetFace(underOpposite, position, near, far, down, corner),
              casterMayMeetFace(underOpposite, position, near, far, down, opposite));
    EXPECT_NE(casterMayMeetFace(underCorner, position, near, far, down, corner),
              casterMayMeetFace(underCorner, position, near, far, down, opposite));
}

}  // namespace
}  // namespace manylights
