// The Morton order the renderer keeps its lights in (scene/SpatialOrder.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "scene/SpatialOrder.h"

namespace manylights {
namespace {

TEST(SpatialOrder, MortonCodeInterleavesTheAxesFromTheLowestBit)
{
    const glm::vec3 lo(0.0f);
    const glm::vec3 hi(1024.0f);
    // Cell (1, 0, 0) sets bit 0, (0, 1, 0) bit 1, (0, 0, 1) bit 2; cell (2, 0, 0) bit 3.
    EXPECT_EQ(mortonCode({1.5f, 0.0f, 0.0f}, lo, hi), 1u);
    EXPECT_EQ(mortonCode({0.0f, 1.5f, 0.0f}, lo, hi), 2u);
    EXPECT_EQ(mortonCode({0.0f, 0.0f, 1.5f}, lo, hi), 4u);
    EXPECT_EQ(mortonCode({2.5f, 0.0f, 0.0f}, lo, hi), 8u);
    // The far corner: every one of the 30 bits; beyond it, clamped to it.
    EXPECT_EQ(mortonCode(hi, lo, hi), (1u << 30) - 1u);
    EXPECT_EQ(mortonCode(hi * 2.0f, lo, hi), (1u << 30) - 1u);
    EXPECT_EQ(mortonCode(-hi, lo, hi), 0u);
}

TEST(SpatialOrder, FlatAxesAndNonFiniteCoordinatesQuantiseToZero)
{
    const glm::vec3 lo(0.0f, 5.0f, 0.0f);
    const glm::vec3 hi(1024.0f, 5.0f, 1024.0f);
    EXPECT_EQ(mortonCode({0.0f, 5.0f, 1.5f}, lo, hi), 4u);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(mortonCode({nan, 5.0f, 0.0f}, lo, hi), 0u);
    EXPECT_EQ(mortonCode({std::numeric_limits<float>::infinity(), 5.0f, 0.0f}, lo, hi), 0u);
}

TEST(SpatialOrder, OrderIsAPermutationThatKeepsTiesInPlace)
{
    EXPECT_TRUE(mortonOrder({}).empty());
    // Two equal points keep their order; the point at the low corner comes first.
    const std::vector<glm::vec3> points{{1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.5f, 0.0f, 0.0f}};
    EXPECT_EQ(mortonOrder(points), (std::vector<std::size_t>{1, 3, 0, 2}));
}

// What the order is for: neighbours in the order are neighbours in space. Random points in a
// square: consecutive points in Morton order lie far closer together, on average, than
// consecutive points in the order they were drawn (a cell of a 32 x 32 grid against a third of
// the square).
TEST(SpatialOrder, ConsecutivePointsAreNeighbours)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-30.0f, 30.0f);
    std::vector<glm::vec3> points(4096);
    for (glm::vec3& p : points)
        p = {coordinate(random), 0.25f, coordinate(random)};
    const std::vector<std::size_t> order = mortonOrder(points);
    std::vector<std::size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> identity(points.size());
    std::iota(identity.begin(), identity.end(), std::size_t{0});
    ASSERT_EQ(sorted, identity);
    double drawnOrderStep = 0.0;
    double mortonStep = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        drawnOrderStep += glm::distance(points[i - 1], points[i]);
        mortonStep += glm::distance(points[order[i - 1]], points[order[i]]);
    }
    drawnOrderStep /= double(points.size() - 1);
    mortonStep /= double(points.size() - 1);
    EXPECT_GT(drawnOrderStep, 25.0);  // 60 m square: a random step averages about 31 m
    EXPECT_LT(mortonStep, 3.0);       // about one cell of 60 / 64 m, with the curve's jumps
}

}  // namespace
}  // namespace manylights
