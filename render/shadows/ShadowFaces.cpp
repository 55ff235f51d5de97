#include "render/shadows/ShadowFaces.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "core/Error.h"
#include "render/shadows/ShadowPageLayout.h"
#include "scene/ShadowSelection.h"

namespace manylights {

using namespace shadowpages;

namespace {

// The up vector each cube face's view is built with (lookAt's), in the faces' order. The
// shaders' table (lib/shadow_pages.glsl: shadowCubeFaceUp) is the same.
constexpr std::array<glm::vec3, 6> kCubeFaceUp = {{
    {0.0f, -1.0f, 0.0f},
    {0.0f, -1.0f, 0.0f},
    {0.0f, 0.0f, 1.0f},
    {0.0f, 0.0f, -1.0f},
    {0.0f, -1.0f, 0.0f},
    {0.0f, -1.0f, 0.0f},
}};

ShadowFaceFrame frameAlong(const glm::vec3& axis, const glm::vec3& upHint, float tanHalf)
{
    ShadowFaceFrame frame;
    frame.axis = axis;
    frame.across = glm::normalize(glm::cross(axis, upHint));
    frame.up = glm::cross(frame.across, axis);
    frame.tanHalf = tanHalf;
    return frame;
}

}  // namespace

int shadowFaceResolution(int level)
{
    ML_ASSERT(level >= 0 && level <= SHADOW_MAX_LEVEL);
    return (SHADOW_PAGE_TEXELS << level) - 2 * SHADOW_GUARD_TEXELS;
}

int shadowFaceCount(const GpuLight& light)
{
    return light.spotAxisCosCutoff.w >= SHADOW_SPOT_FACE_MIN_COS ? 1 : SHADOW_CUBE_FACES;
}

ShadowFaceFrame shadowFaceFrame(const GpuLight& light, int face)
{
    if (shadowFaceCount(light) == 1) {
        const glm::vec3 axis(light.spotAxisCosCutoff);
        const float c = light.spotAxisCosCutoff.w;
        const glm::vec3 upHint = std::abs(axis.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
        return frameAlong(axis, upHint, std::sqrt(std::max(1.0f - c * c, 0.0f)) / c * SHADOW_SPOT_FACE_SCALE);
    }
    ML_ASSERT(face >= 0 && face < SHADOW_CUBE_FACES);
    glm::vec3 axis(0.0f);
    axis[face / 2] = face % 2 == 0 ? 1.0f : -1.0f;
    return frameAlong(axis, kCubeFaceUp[static_cast<std::size_t>(face)], 1.0f);
}

glm::mat4 shadowFaceViewProjection(const glm::vec3& position, const ShadowFaceFrame& frame, float near, float far)
{
    // The view: rows across, up and −axis (lookAt's), so that clip w is the depth along the axis.
    glm::mat4 view(1.0f);
    for (int i = 0; i < 3; ++i) {
        view[i][0] = frame.across[i];
        view[i][1] = frame.up[i];
        view[i][2] = -frame.axis[i];
    }
    view[3] = glm::vec4(-glm::dot(frame.across, position), -glm::dot(frame.up, position),
                        glm::dot(frame.axis, position), 1.0f);
    glm::mat4 projection(0.0f);
    projection[0][0] = 1.0f / frame.tanHalf;
    projection[1][1] = 1.0f / frame.tanHalf;
    projection[2][2] = -(far + near) / (far - near);
    projection[2][3] = -1.0f;
    projection[3][2] = -2.0f * far * near / (far - near);
    return projection * view;
}

std::uint32_t markedCells(std::uint32_t mark) { return mark & ((1u << SHADOW_MARK_LEVEL_SHIFT) - 1u); }

int markedLevel(std::uint32_t mark)
{
    const std::uint32_t levels = mark >> SHADOW_MARK_LEVEL_SHIFT;
    return levels == 0 ? -1 : std::bit_width(levels) - 1;
}

ShadowFaceRegion shadowFaceRegion(std::uint32_t cells, int level)
{
    const int wholePages = 1 << level;
    ShadowFaceRegion whole{
        .level = level, .x0 = -SHADOW_GUARD_TEXELS, .y0 = -SHADOW_GUARD_TEXELS, .pages = wholePages, .whole = true};
    if (level == 0 || cells == 0)
        return whole;
    int cellMin[2] = {SHADOW_MARK_CELLS, SHADOW_MARK_CELLS};
    int cellMax[2] = {-1, -1};
    for (int cell = 0; cell < SHADOW_MARK_CELLS * SHADOW_MARK_CELLS; ++cell)
        if ((cells >> cell) & 1u) {
            const int xy[2] = {cell % SHADOW_MARK_CELLS, cell / SHADOW_MARK_CELLS};
            for (int axis = 0; axis < 2; ++axis) {
                cellMin[axis] = std::min(cellMin[axis], xy[axis]);
                cellMax[axis] = std::max(cellMax[axis], xy[axis]);
            }
        }
    const double resolution = shadowFaceResolution(level);
    const double cellTexels = resolution / SHADOW_MARK_CELLS;
    // One texel of margin beyond the cells, then the guard.
    const int reach = SHADOW_GUARD_TEXELS + 1;
    int low[2];
    int span = 0;
    for (int axis = 0; axis < 2; ++axis) {
        low[axis] = static_cast<int>(std::floor(cellMin[axis] * cellTexels)) - reach;
        const int high = static_cast<int>(std::ceil((cellMax[axis] + 1) * cellTexels)) + reach;
        span = std::max(span, high - low[axis]);
    }
    const int pages =
        static_cast<int>(std::bit_ceil(static_cast<unsigned>((span + SHADOW_PAGE_TEXELS - 1) / SHADOW_PAGE_TEXELS)));
    if (pages >= wholePages)
        return whole;
    // Kept inside the whole face's square, so the part holds no texel the whole face would not.
    const int texels = pages * SHADOW_PAGE_TEXELS;
    const int lowest = -SHADOW_GUARD_TEXELS;
    const int highest = static_cast<int>(resolution) + SHADOW_GUARD_TEXELS - texels;
    return {.level = level,
            .x0 = std::clamp(low[0], lowest, highest),
            .y0 = std::clamp(low[1], lowest, highest),
            .pages = pages,
            .whole = false};
}

ShadowFaceRegion coarseShadowFaceRegion() { return shadowFaceRegion(0, 0); }

std::size_t shadowFacePages(const ShadowFaceRegion& region)
{
    const auto side = static_cast<std::size_t>(region.pages);
    return side * side + (region.whole ? 0 : 1);
}

bool casterMayMeetFace(const Bounds& box, const glm::vec3& position, float near, float far,
                       const ShadowFaceFrame& frame, const ShadowFaceRegion& region)
{
    if (box.empty() || !boxIntersectsSphere(box, position, far))
        return false;
    const double resolution = shadowFaceResolution(region.level);
    const double texels = static_cast<double>(region.pages) * SHADOW_PAGE_TEXELS;
    // The region's square in the face's normalised coordinates (−1 to 1 across the face).
    const glm::vec2 regionLow(static_cast<float>(2.0 * region.x0 / resolution - 1.0),
                              static_cast<float>(2.0 * region.y0 / resolution - 1.0));
    const glm::vec2 regionHigh = regionLow + glm::vec2(static_cast<float>(2.0 * texels / resolution));
    glm::vec2 low(std::numeric_limits<float>::max());
    glm::vec2 high(std::numeric_limits<float>::lowest());
    bool allBeyondNear = true;
    bool anyAhead = false;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                              (corner & 4) ? box.max.z : box.min.z);
        const glm::vec3 v = point - position;
        const float depth = glm::dot(frame.axis, v);
        anyAhead = anyAhead || depth > 0.0f;
        allBeyondNear = allBeyondNear && depth > near;
        if (depth > near) {
            const glm::vec2 ndc = glm::vec2(glm::dot(frame.across, v), glm::dot(frame.up, v)) / (depth * frame.tanHalf);
            low = glm::min(low, ndc);
            high = glm::max(high, ndc);
        }
    }
    // Wholly behind the light's view of the face; or reaching behind its near plane, where the
    // projection of the box is unbounded (kept: the depth clamp draws such casters at the light).
    if (!anyAhead)
        return false;
    if (!allBeyondNear)
        return true;
    return low.x <= regionHigh.x && high.x >= regionLow.x && low.y <= regionHigh.y && high.y >= regionLow.y;
}

}  // namespace manylights
