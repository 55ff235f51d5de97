// An order of points along a Morton (Z-order) curve, so that points near each other in space are
// near each other in the order. The renderer keeps its lights in this order
// (render/scene/SceneLights.h): a cluster's lights are then neighbours in memory, and the passes that
// walk lights side by side in SIMD lanes walk neighbours (docs/techniques.md, "The light lists
// of tiled and clustered"). No GL: unit-tested (tests/unit/SpatialOrderTest.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace manylights {

// The 30-bit Morton code of a point of the box lo..hi: each axis quantised to 10 bits over the
// box (points outside it clamp to its faces), bits interleaved x, y, z from the lowest. An axis
// along which the box is flat quantises to 0.
std::uint32_t mortonCode(const glm::vec3& point, const glm::vec3& lo, const glm::vec3& hi);

// The indices of `points` sorted by their Morton codes over the points' bounding box; equal
// codes keep their order, so the result depends on the points alone. Non-finite coordinates
// count as the box's low face.
std::vector<std::size_t> mortonOrder(const std::vector<glm::vec3>& points);

}  // namespace manylights
