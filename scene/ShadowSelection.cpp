#include "scene/ShadowSelection.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace manylights {

Bounds transformedBounds(const Bounds& local, const glm::mat4& transform)
{
    Bounds world;
    if (local.empty())
        return world;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z);
        world.extend(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
    return world;
}

bool boxIntersectsSphere(const Bounds& box, const glm::vec3& centre, float radius)
{
    const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
    const glm::vec3 offset = centre - nearest;
    return glm::dot(offset, offset) <= radius * radius;
}

bool boxMayIntersectCone(const Bounds& box, const glm::vec3& apex, const glm::vec3& axis, float cutoffDegrees,
                         float radius)
{
    if (!boxIntersectsSphere(box, apex, radius))
        return false;
    if (cutoffDegrees >= 90.0f)
        return true;  // a cone wider than a half-space: the sphere test is all we do
    // The box's bounding sphere against the cone (the classic sphere–cone test): the sphere
    // is outside when its centre is farther than its radius from the cone's surface.
    const glm::vec3 centre = 0.5f * (box.min + box.max);
    const float sphereRadius = 0.5f * glm::length(box.max - box.min);
    const glm::vec3 v = centre - apex;
    const float along = glm::dot(v, axis);
    const float across = glm::length(v - along * axis);
    const float angle = glm::radians(cutoffDegrees);
    // Signed distance from the centre to the cone's lateral surface (positive outside).
    const float distanceToSurface = std::cos(angle) * across - std::sin(angle) * along;
    return distanceToSurface <= sphereRadius && along >= -sphereRadius;
}

double screenCoverage(const glm::vec3& centre, float radius, const glm::mat4& viewProjection)
{
    // An unbounded light (docs/lighting.md: a = b = 0) reaches every pixel.
    if (!(radius < 1e30f))
        return 1.0;
    glm::vec2 low(1.0f);
    glm::vec2 high(-1.0f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 offset((corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius,
                               (corner & 4) ? radius : -radius);
        const glm::vec4 clip = viewProjection * glm::vec4(centre + offset, 1.0f);
        // A corner at or behind the eye: the projected rectangle is unbounded. Whether the
        // sphere is in view at all is then not decided here; counting it as the whole screen
        // ranks a light around the camera first, which is what a viewer notices most.
        if (clip.w <= 0.0f)
            return 1.0;
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        low = glm::min(low, ndc);
        high = glm::max(high, ndc);
    }
    low = glm::max(low, glm::vec2(-1.0f));
    high = glm::min(high, glm::vec2(1.0f));
    if (low.x >= high.x || low.y >= high.y)
        return 0.0;
    return static_cast<double>(high.x - low.x) * static_cast<double>(high.y - low.y) / 4.0;
}

std::vector<std::size_t> selectShadowLights(const std::vector<ShadowCandidate>& candidates,
                                            const glm::mat4& viewProjection, int budget)
{
    std::vector<double> score(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const ShadowCandidate& light = candidates[i];
        score[i] = light.maxIntensity > 0.0f && light.radius > 0.0f
                       ? screenCoverage(light.position, light.radius, viewProjection) * light.maxIntensity
                       : 0.0;
    }
    std::vector<std::size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Stable: equal scores keep index order.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return score[a] > score[b]; });
    std::vector<std::size_t> chosen;
    for (std::size_t i : order) {
        if (static_cast<int>(chosen.size()) >= budget || score[i] <= 0.0)
            break;
        chosen.push_back(i);
    }
    return chosen;
}

}  // namespace manylights
