// An axis-aligned box and where a ray enters it, in double precision: the analytic shadow tests'
// occluders (tests/image/ShadowTest.cpp, tests/gl/ShadowPagesTest.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

namespace manylights::test {

struct Box {
    glm::dvec3 min;
    glm::dvec3 max;
    // Whether `p` lies in the box grown by `slack` on every side.
    bool holds(const glm::dvec3& p, double slack = 0.0) const
    {
        return glm::all(glm::greaterThanEqual(p, min - slack)) && glm::all(glm::lessThanEqual(p, max + slack));
    }
};

// Where the ray origin + t · direction (t ≥ 0) enters `box` (slab test), or none.
inline std::optional<double> rayEntersBox(const glm::dvec3& origin, const glm::dvec3& direction, const Box& box)
{
    double near = 0.0;
    double far = 1e30;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-12) {
            if (origin[axis] < box.min[axis] || origin[axis] > box.max[axis])
                return std::nullopt;
            continue;
        }
        double t0 = (box.min[axis] - origin[axis]) / direction[axis];
        double t1 = (box.max[axis] - origin[axis]) / direction[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
    }
    if (near > far)
        return std::nullopt;
    return near;
}

}  // namespace manylights::test
