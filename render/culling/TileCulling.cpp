#include "render/culling/TileCulling.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "render/culling/ScreenBounds.h"
#include "scene/Falloff.h"

namespace manylights {

namespace {

// Margins. The shaders decide A·S at a surface position interpolated in 32-bit floats, and
// this code works in 32-bit floats too: either side may be off by a few ulps of the
// coordinates involved (~1e-7 relative). The margins are a hundred times that; they widen
// no light by anything a tile boundary could notice.
constexpr float kRelativeMargin = 1e-5f;
// A spot's cone is a hard edge of light (A·S jumps from zero there), decided by comparing
// cos θ with cos(cutoff) in floats. Their resolution near 1 is ~3.5e-4 rad of angle, so the
// cone is widened in cos and in angle.
constexpr float kCosineMargin = 2e-6f;
constexpr float kAngleMargin = 1e-3f;
// Surfaces are clipped at the near and far planes, up to the rounding of the depth.
constexpr float kDepthMargin = 1e-3f;

// The side planes of every tile, all through the eye, and the rays along their edges.
class TileFrustums {
public:
    TileFrustums(const TileCullingView& view, int tilesX, int tilesY) : tilesX_(tilesX)
    {
        const double tanY = std::tan(0.5 * static_cast<double>(view.fovY));
        const double tanX = tanY * static_cast<double>(view.aspect());
        // Slopes (view-space x / depth) of the pixel edges between tiles; the last edge is
        // the image's, which may cut the last tile short.
        const auto slopes = [](int tiles, int tileSize, int pixels, double tanHalf) {
            std::vector<float> result(static_cast<std::size_t>(tiles) + 1);
            for (int i = 0; i <= tiles; ++i) {
                const int edge = std::min(i * tileSize, pixels);
                result[static_cast<std::size_t>(i)] = static_cast<float>((2.0 * edge / pixels - 1.0) * tanHalf);
            }
            return result;
        };
        const std::vector<float> sx = slopes(tilesX, view.tileSize, view.width, tanX);
        const std::vector<float> sy = slopes(tilesY, view.tileSize, view.height, tanY);
        // The plane x = s·depth (depth = −z) has the unit normal (1, 0, s)/|..|, pointing to
        // larger x / depth: inwards for the tile to its right, outwards for the one to its
        // left. Likewise for rows.
        for (float s : sx)
            columnPlanes_.push_back(glm::normalize(glm::vec3(1.0f, 0.0f, s)));
        for (float s : sy)
            rowPlanes_.push_back(glm::normalize(glm::vec3(0.0f, 1.0f, s)));
        for (float y : sy)
            for (float x : sx)
                corners_.push_back(glm::normalize(glm::vec3(x, y, -1.0f)));
    }

    glm::vec3 left(int tx) const { return columnPlanes_[static_cast<std::size_t>(tx)]; }
    glm::vec3 right(int tx) const { return -columnPlanes_[static_cast<std::size_t>(tx) + 1]; }
    glm::vec3 bottom(int ty) const { return rowPlanes_[static_cast<std::size_t>(ty)]; }
    glm::vec3 top(int ty) const { return -rowPlanes_[static_cast<std::size_t>(ty) + 1]; }
    // The unit ray from the eye through the grid vertex (cx, cy) (pixel corner cx·size, cy·size).
    glm::vec3 corner(int cx, int cy) const
    {
        return corners_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(tilesX_ + 1) +
                        static_cast<std::size_t>(cx)];
    }

    // Whether the ball (c, r) meets tile (tx, ty)'s pyramid (apex at the eye): exactly, up
    // to rounding. The plane tests alone keep balls beyond a tile's corner, outside two
    // planes at once but within r of each; the distance to the pyramid does not.
    bool ballTouches(const glm::vec3& c, float r, int tx, int ty) const
    {
        const glm::vec3 l = left(tx), rt = right(tx), b = bottom(ty), t = top(ty);
        const float sl = glm::dot(l, c), sr = glm::dot(rt, c), sb = glm::dot(b, c), st = glm::dot(t, c);
        if (std::min({sl, sr, sb, st}) < -r)
            return false;  // wholly outside one side plane
        if (std::min({sl, sr, sb, st}) >= 0.0f)
            return true;  // the centre is inside
        // The centre is outside, within r of every side plane. Where it lies outside a face's
        // plane and its foot on that plane falls within the face (inside the two
        // neighbouring planes), that face is the nearest part of the pyramid, at |s| ≤ r.
        if (faceHolds(c, l, sl, b, t) || faceHolds(c, rt, sr, b, t) || faceHolds(c, b, sb, l, rt) ||
            faceHolds(c, t, st, l, rt))
            return true;
        // Otherwise the nearest point lies on one of the four edges (or the apex): a face
        // whose plane the centre is inside of cannot hold it in its interior, since the
        // segment to it would cross the pyramid first.
        const float distance = std::min({rayDistance(c, corner(tx, ty)), rayDistance(c, corner(tx + 1, ty)),
                                         rayDistance(c, corner(tx, ty + 1)), rayDistance(c, corner(tx + 1, ty + 1))});
        return distance <= r;
    }

private:
    // Distance from c to the ray from the eye along the unit direction a (the eye itself
    // when c lies behind it). As a vector difference, not sqrt(|c|² − (c·a)²), which loses
    // all precision when c is near the ray.
    static float rayDistance(const glm::vec3& c, const glm::vec3& a)
    {
        const float along = glm::dot(c, a);
        return along <= 0.0f ? glm::length(c) : glm::length(c - along * a);
    }

    // Whether c lies outside the plane with inward normal n (c·n = s < 0) and its foot on
    // the plane is inside the neighbouring planes n0 and n1: within the face's wedge.
    static bool faceHolds(const glm::vec3& c, const glm::vec3& n, float s, const glm::vec3& n0, const glm::vec3& n1)
    {
        if (s >= 0.0f)
            return false;
        const glm::vec3 foot = c - s * n;
        return glm::dot(n0, foot) >= 0.0f && glm::dot(n1, foot) >= 0.0f;
    }

    int tilesX_;
    std::vector<glm::vec3> columnPlanes_;
    std::vector<glm::vec3> rowPlanes_;
    std::vector<glm::vec3> corners_;
};

// The region a spot narrower than 90° can light: its sphere cut by its cone, a convex
// spherical sector (widened by the margins).
struct Sector {
    glm::vec3 apex;
    glm::vec3 axis;  // unit
    float cosAngle;
    float sinAngle;
    float radius;

    // The support function: max over the sector's points x of n·(x − apex), for unit n. When
    // n lies within the cone the farthest point is apex + radius·n; otherwise it is on the
    // cone's edge nearest n, at angle φ − θ from n (or the apex, beyond 90°).
    float support(const glm::vec3& n) const
    {
        const float cosPhi = glm::dot(n, axis);
        if (cosPhi >= cosAngle)
            return radius;
        const float sinPhi = std::sqrt(std::max(0.0f, 1.0f - cosPhi * cosPhi));
        return radius * std::max(0.0f, cosPhi * cosAngle + sinPhi * sinAngle);
    }

    // False only when the whole sector lies more than `margin` outside the half-space
    // n·x ≥ 0 (n unit, inward).
    bool reaches(const glm::vec3& n, float margin) const { return glm::dot(n, apex) + support(n) >= -margin; }
};

// Chunks per thread (TileCuller::cull): enough that the threads finish together where the lights'
// costs differ, few enough that the counting sort's pass over every chunk's counts stays small.
constexpr std::size_t kChunksPerThread = 16;

// Runs task(i) for every i < count on `threads` threads, the caller's one of them, each taking
// the next i as it finishes one.
template <typename Task>
void runOnThreads(unsigned threads, std::size_t count, const Task& task)
{
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i = next++; i < count; i = next++)
            task(i);
    };
    std::vector<std::jthread> helpers;
    for (unsigned t = 1; t < threads && t < count; ++t)
        helpers.emplace_back(work);
    work();
}

}  // namespace

unsigned TileCuller::threadsFor(std::size_t lightCount) const
{
    if (threads_ > 0)
        return threads_;
    return lightCount >= kParallelCullingLights ? std::max(std::thread::hardware_concurrency(), 1u) : 1;
}

const TileLightLists& TileCuller::cull(const TileCullingView& view, std::span<const GpuLight> lights)
{
    ML_ASSERT(view.width > 0 && view.height > 0 && view.tileSize > 0);
    ML_ASSERT(view.nearPlane > 0.0f && view.farPlane > view.nearPlane && view.fovY > 0.0f);
    ML_ASSERT(view.width > 0 && view.height > 0);
    ML_ASSERT(lights.size() < std::numeric_limits<std::uint32_t>::max());
    const int tilesX = (view.width + view.tileSize - 1) / view.tileSize;
    const int tilesY = (view.height + view.tileSize - 1) / view.tileSize;
    const auto tileCount = static_cast<std::size_t>(tilesX) * static_cast<std::size_t>(tilesY);
    const TileFrustums frustums(view, tilesX, tilesY);
    const double tanY = std::tan(0.5 * static_cast<double>(view.fovY));
    const double tanX = tanY * static_cast<double>(view.aspect());
    const float nearLimit = view.nearPlane * (1.0f - kDepthMargin);
    const float farLimit = view.farPlane * (1.0f + kDepthMargin);
    // The eye in world space: the scale of the coordinates the view transform rounds.
    const glm::mat3 rotation(view.view);
    const glm::vec3 eye = -(glm::transpose(rotation) * glm::vec3(view.view[3]));
    const float eyeScale = glm::length(eye);

    lists_.tileSize = view.tileSize;
    lists_.tilesX = tilesX;
    lists_.tilesY = tilesY;

    // Light i's pairs: accept(tile, i) for each tile it may reach, in ascending tile order.
    const auto cullLight = [&](std::size_t i, auto&& accept) {
        const GpuLight& light = lights[i];
        const auto index = static_cast<std::uint32_t>(i);
        const float radius = light.positionRadius.w;
        if (!(radius > 0.0f))
            return;  // reaches nothing
        if (radius >= falloff::kUnboundedRadius) {
            // Never fades: no tile can be proved out of its reach.
            for (std::size_t tile = 0; tile < tileCount; ++tile)
                accept(tile, index);
            return;
        }
        const glm::vec3 position(light.positionRadius);
        const float margin = kRelativeMargin * (glm::length(position) + eyeScale + radius);
        const float reach = radius + margin;
        const glm::vec3 centre(view.view * glm::vec4(position, 1.0f));
        const float depth = -centre.z;
        if (depth + reach < nearLimit || depth - reach > farLimit)
            return;  // wholly in front of the near plane (or behind the eye), or beyond the far plane

        const float cosCutoff = light.spotAxisCosCutoff.w;
        std::optional<Sector> sector;
        // Point lights carry cos(cutoff) = −2 and are not cones. Spots of 90° and wider fill
        // at least a half-space around the light: their sphere bounds them about as well.
        if (cosCutoff > 0.0f) {
            const float angle = std::acos(std::clamp(cosCutoff - kCosineMargin, -1.0f, 1.0f)) + kAngleMargin;
            if (angle < 0.5f * glm::pi<float>()) {
                const glm::vec3 axis = glm::normalize(rotation * glm::vec3(light.spotAxisCosCutoff));
                sector = Sector{centre, axis, std::cos(angle), std::sin(angle), reach};
                // The sector's own depth range against the near and far planes.
                const glm::vec3 towardsDepth(0.0f, 0.0f, -1.0f);
                if (!sector->reaches(towardsDepth, margin - nearLimit) ||
                    !sector->reaches(-towardsDepth, farLimit + margin))
                    return;
            }
        }

        // The tiles the sphere's projection can touch. A sphere that crosses the near plane
        // (or contains the eye) may cover any part of the screen.
        int tx0 = 0, tx1 = tilesX - 1, ty0 = 0, ty1 = tilesY - 1;
        if (depth - reach > view.nearPlane) {
            const auto [left, right] = projectedPixels(centre.x, depth, reach, tanX, view.width);
            const auto [bottom, top] = projectedPixels(centre.y, depth, reach, tanY, view.height);
            std::tie(tx0, tx1) = tileSpan(left, right, view.tileSize, tilesX);
            std::tie(ty0, ty1) = tileSpan(bottom, top, view.tileSize, tilesY);
        }
        for (int ty = ty0; ty <= ty1; ++ty)
            for (int tx = tx0; tx <= tx1; ++tx) {
                if (!frustums.ballTouches(centre, reach, tx, ty))
                    continue;
                // A side plane that the spot's sector lies wholly outside separates the two.
                if (sector &&
                    !(sector->reaches(frustums.left(tx), margin) && sector->reaches(frustums.right(tx), margin) &&
                      sector->reaches(frustums.bottom(ty), margin) && sector->reaches(frustums.top(ty), margin)))
                    continue;
                accept(lists_.tileIndex(tx, ty), index);
            }
    };

    // The lights in runs of consecutive lights (chunks), each culled by one thread into its own
    // pairs, in ascending light order, and its own count per tile. More chunks than threads, taken
    // as threads finish the last: lights differ in cost (one that crosses the near plane tests
    // every tile), and runs of the lights' space order (render/scene/SceneLights.h) lie off
    // screen or near the eye together.
    const unsigned threads = threadsFor(lights.size());
    const std::size_t chunkCount =
        threads == 1 ? 1
                     : std::clamp<std::size_t>(threads * kChunksPerThread, 1, std::max<std::size_t>(lights.size(), 1));
    if (chunks_.size() < chunkCount)
        chunks_.resize(chunkCount);
    const auto chunkLights = [&](std::size_t chunk) {
        return std::pair(chunk * lights.size() / chunkCount, (chunk + 1) * lights.size() / chunkCount);
    };
    runOnThreads(threads, chunkCount, [&](std::size_t c) {
        Chunk& chunk = chunks_[c];
        chunk.pairTiles.clear();
        chunk.pairLights.clear();
        chunk.tileCounts.assign(tileCount, 0);
        const auto accept = [&](std::size_t tile, std::uint32_t light) {
            chunk.pairTiles.push_back(static_cast<std::uint32_t>(tile));
            chunk.pairLights.push_back(light);
            ++chunk.tileCounts[tile];
        };
        const auto [first, end] = chunkLights(c);
        for (std::size_t i = first; i < end; ++i)
            cullLight(i, accept);
    });

    // Group the pairs by tile (a counting sort): a tile's list is its pairs of the first chunk,
    // then of the second, and so on, so its lights stay in ascending order whatever the chunks.
    // Each chunk's counts become where its next pair of each tile goes.
    lists_.tiles.resize(tileCount);
    std::uint32_t offset = 0;
    for (std::size_t tile = 0; tile < tileCount; ++tile) {
        lists_.tiles[tile].offset = offset;
        for (std::size_t c = 0; c < chunkCount; ++c) {
            const std::uint32_t count = chunks_[c].tileCounts[tile];
            chunks_[c].tileCounts[tile] = offset;
            offset += count;
        }
        lists_.tiles[tile].count = offset - lists_.tiles[tile].offset;
    }
    lists_.lightIndices.resize(offset);
    runOnThreads(threads, chunkCount, [&](std::size_t c) {
        Chunk& chunk = chunks_[c];
        for (std::size_t pair = 0; pair < chunk.pairLights.size(); ++pair)
            lists_.lightIndices[chunk.tileCounts[chunk.pairTiles[pair]]++] = chunk.pairLights[pair];
    });
    return lists_;
}

TileLightLists cullLightsToTiles(const TileCullingView& view, std::span<const GpuLight> lights)
{
    TileCuller culler;
    culler.cull(view, lights);
    return culler.lists();
}

}  // namespace manylights
