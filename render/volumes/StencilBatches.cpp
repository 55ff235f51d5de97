#include "render/volumes/StencilBatches.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/Error.h"
#include "render/culling/ScreenBounds.h"

namespace manylights {

namespace {

// The GPU places a volume's corners in 32-bit floats (shaders/volume.vert), and this code
// bounds them in 32-bit floats too: either may be off by a few ulps of the coordinates
// involved (~1e-7 relative). A hundred times that widens no volume by a visible amount.
constexpr float kRelativeMargin = 1e-5f;

// How far the drawn sphere's corners reach, in radii: the icosahedron's circumradius over its
// inradius (render/volumes/LightVolumes.h), 1.26.
float sphereMeshReach()
{
    static const float reach = [] {
        float farthest = 0.0f;
        for (const Vertex& vertex : makeBoundingSphere().vertices)
            farthest = std::max(farthest, glm::length(vertex.position));
        return farthest;
    }();
    return reach;
}

// The cone's mesh before shaders/volume.vert scales it by (R tan θ, R tan θ, R): the farthest
// its vertices lie from the axis and along it.
struct ConeMeshExtent {
    float radial = 0.0f;
    float axial = 0.0f;
};

const ConeMeshExtent& coneMeshExtent()
{
    static const ConeMeshExtent extent = [] {
        ConeMeshExtent result;
        for (const Vertex& vertex : makeBoundingCone().vertices) {
            result.radial = std::max(result.radial, glm::length(glm::vec2(vertex.position)));
            result.axial = std::max(result.axial, std::abs(vertex.position.z));
        }
        return result;
    }();
    return extent;
}

// How far a light's drawn volume reaches from the light, as shaders/volume.vert places it.
float volumeReach(const GpuLight& light, bool cone)
{
    const float radius = light.positionRadius.w;
    if (!cone)
        return radius * sphereMeshReach();
    const float cosCutoff = light.spotAxisCosCutoff.w;
    const float tanCutoff = std::sqrt(std::max(1.0f - cosCutoff * cosCutoff, 0.0f)) / cosCutoff;
    const ConeMeshExtent& extent = coneMeshExtent();
    return radius * std::hypot(tanCutoff * extent.radial, extent.axial);
}

}  // namespace

void StencilCellOccupancy::reset(std::size_t cells, int cellsX)
{
    cells_ = cells;
    cellsX_ = cellsX;
    rows_.assign(kOpenBatchWords * cells, 0);
    firstFree_.assign(cells, 0);
    firstOpenWord_ = 0;
    words_ = 0;
}

template <typename Visit>
void StencilCellOccupancy::forEachCell(const CellRect& rect, Visit&& visit)
{
    for (int y = rect.y0; y <= rect.y1; ++y)
        for (int x = rect.x0; x <= rect.x1; ++x)
            visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(cellsX_) + static_cast<std::size_t>(x));
}

std::uint32_t StencilCellOccupancy::place(const CellRect& rect)
{
    if (rect.isEmpty())
        return 0;
    // No batch below a cell's first free one can take the light: start the search above all of
    // them (a light on a spot that a thousand batches hold is placed without a look at those).
    std::size_t start = firstOpenWord_ * 64;
    forEachCell(rect, [&](std::size_t cell) { start = std::max<std::size_t>(start, firstFree_[cell]); });
    for (std::size_t word = start / 64; word < words_; ++word) {
        const std::uint64_t* const cells = row(word);
        std::uint64_t taken = word == start / 64 ? (std::uint64_t{1} << (start % 64)) - 1 : 0;
        forEachCell(rect, [&](std::size_t cell) { taken |= cells[cell]; });
        if (~taken != 0)
            return mark(rect, static_cast<std::uint32_t>(word * 64 + static_cast<std::size_t>(std::countr_one(taken))));
    }
    // A new batch, closing the oldest 64 when the ring is full.
    if (words_ - firstOpenWord_ == kOpenBatchWords)
        ++firstOpenWord_;
    std::fill_n(row(words_), cells_, 0);
    ++words_;
    return mark(rect, static_cast<std::uint32_t>((words_ - 1) * 64));
}

std::uint32_t StencilCellOccupancy::mark(const CellRect& rect, std::uint32_t batch)
{
    std::uint64_t* const cells = row(batch / 64);
    const std::uint64_t bit = std::uint64_t{1} << (batch % 64);
    forEachCell(rect, [&](std::size_t cell) {
        cells[cell] |= bit;
        // Every open batch below firstFree_[cell] occupies the cell: past the new one, and past
        // those above it that do too.
        std::uint32_t& free = firstFree_[cell];
        if (free != batch)
            return;
        while (free < words_ * 64 && (row(free / 64)[cell] >> (free % 64) & 1) != 0)
            ++free;
    });
    return batch;
}

const StencilBatches& StencilBatcher::group(const StencilBatchView& view, std::span<const GpuLight> lights,
                                            const LightVolumeGroups& groups)
{
    ML_ASSERT(view.width > 0 && view.height > 0 && view.tanHalfFovX > 0.0f && view.tanHalfFovY > 0.0f);
    ML_ASSERT(lights.size() < std::numeric_limits<std::uint32_t>::max());
    const int cellsX = (view.width + kStencilBatchCellPixels - 1) / kStencilBatchCellPixels;
    const int cellsY = (view.height + kStencilBatchCellPixels - 1) / kStencilBatchCellPixels;
    const auto cellCount = static_cast<std::size_t>(cellsX) * static_cast<std::size_t>(cellsY);
    const float eyeScale = glm::length(view.eye);

    batches_.order.clear();
    batches_.batches.clear();
    for (const std::uint32_t light : groups.spheres)
        if (eyeInsideSphereVolume(lights[light], view.eye))
            batches_.order.push_back(light);
    batches_.aroundEye = static_cast<std::uint32_t>(batches_.order.size());

    const auto cellsOf = [&](const GpuLight& light, bool cone) {
        const glm::vec3 position(light.positionRadius);
        float reach = volumeReach(light, cone);
        reach += kRelativeMargin * (glm::length(position) + eyeScale + reach);
        const glm::vec3 centre(view.view * glm::vec4(position, 1.0f));
        const float depth = -centre.z;
        CellRect cells;
        if (depth + reach <= 0.0f)
            return cells;  // wholly behind the eye: GL clips all of it (w ≤ 0), depth clamping or not
        if (depth - reach <= 0.0f)
            return CellRect{0, cellsX - 1, 0, cellsY - 1};  // cut by the eye's plane: anywhere
        const auto [left, right] = projectedPixels(centre.x, depth, reach, view.tanHalfFovX, view.width);
        const auto [bottom, top] = projectedPixels(centre.y, depth, reach, view.tanHalfFovY, view.height);
        std::tie(cells.x0, cells.x1) = tileSpan(left, right, kStencilBatchCellPixels, cellsX);
        std::tie(cells.y0, cells.y1) = tileSpan(bottom, top, kStencilBatchCellPixels, cellsY);
        return cells;
    };
    occupancy_.reset(cellCount, cellsX);
    batchOf_.clear();
    std::uint32_t batchCount = 0;
    const auto placeAll = [&](const std::vector<std::uint32_t>& indices, bool cone, bool skipAroundEye) {
        for (const std::uint32_t light : indices) {
            if (skipAroundEye && eyeInsideSphereVolume(lights[light], view.eye))
                continue;
            const std::uint32_t batch = occupancy_.place(cellsOf(lights[light], cone));
            batchOf_.push_back(batch);
            batchCount = std::max(batchCount, batch + 1);
        }
    };
    placeAll(groups.spheres, false, true);
    placeAll(groups.cones, true, false);

    // Group the lights by batch (a counting sort), spheres before cones within each, both in
    // ascending light order.
    batches_.batches.assign(batchCount, StencilBatch{});
    const std::size_t sphereCount = groups.spheres.size() - batches_.aroundEye;
    for (std::size_t i = 0; i < batchOf_.size(); ++i) {
        StencilBatch& batch = batches_.batches[batchOf_[i]];
        ++(i < sphereCount ? batch.spheres : batch.cones);
    }
    std::uint32_t first = batches_.aroundEye;
    cursors_.resize(2 * static_cast<std::size_t>(batchCount));
    for (std::uint32_t b = 0; b < batchCount; ++b) {
        StencilBatch& batch = batches_.batches[b];
        batch.first = first;
        cursors_[2 * b] = first;
        cursors_[2 * b + 1] = first + batch.spheres;
        first += batch.spheres + batch.cones;
    }
    batches_.order.resize(first);
    std::size_t i = 0;
    const auto scatter = [&](const std::vector<std::uint32_t>& indices, std::size_t part, bool skipAroundEye) {
        for (const std::uint32_t light : indices) {
            if (skipAroundEye && eyeInsideSphereVolume(lights[light], view.eye))
                continue;
            batches_.order[cursors_[2 * batchOf_[i++] + part]++] = light;
        }
    };
    scatter(groups.spheres, 0, true);
    scatter(groups.cones, 1, false);
    return batches_;
}

}  // namespace manylights
