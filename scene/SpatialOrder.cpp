#include "scene/SpatialOrder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace manylights {

namespace {

constexpr int kBitsPerAxis = 10;
constexpr float kCellsPerAxis = float(1 << kBitsPerAxis);

// The low 10 bits of v spread to every third bit (bit i to bit 3i).
std::uint32_t spreadBits(std::uint32_t v)
{
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

std::uint32_t quantise(float x, float lo, float hi)
{
    if (!(hi > lo) || !std::isfinite(x))
        return 0u;
    const float cell = std::floor((x - lo) / (hi - lo) * kCellsPerAxis);
    return static_cast<std::uint32_t>(std::clamp(cell, 0.0f, kCellsPerAxis - 1.0f));
}

}  // namespace

std::uint32_t mortonCode(const glm::vec3& point, const glm::vec3& lo, const glm::vec3& hi)
{
    return spreadBits(quantise(point.x, lo.x, hi.x)) | spreadBits(quantise(point.y, lo.y, hi.y)) << 1 |
           spreadBits(quantise(point.z, lo.z, hi.z)) << 2;
}

std::vector<std::size_t> mortonOrder(const std::vector<glm::vec3>& points)
{
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : points)
        for (int axis = 0; axis < 3; ++axis)
            if (std::isfinite(p[axis])) {
                lo[axis] = std::min(lo[axis], p[axis]);
                hi[axis] = std::max(hi[axis], p[axis]);
            }
    // Code and index in one integer: a plain sort of them is the stable sort by code.
    std::vector<std::uint64_t> keyed(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        keyed[i] = std::uint64_t{mortonCode(points[i], lo, hi)} << 32 | i;
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::size_t> order(points.size());
    for (std::size_t i = 0; i < keyed.size(); ++i)
        order[i] = static_cast<std::size_t>(keyed[i] & 0xffffffffu);
    return order;
}

}  // namespace manylights
