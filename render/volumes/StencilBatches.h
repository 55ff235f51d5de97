// The stencil technique's light batches (issue 41, docs/techniques.md "stencil"): lights whose
// volumes cannot share a pixel on screen are marked in the stencil by one instanced draw and lit
// by one more, where each light took two draws and their state changes of its own.
//
// Exact by construction: a batch's volumes touch disjoint sets of pixels, so a pixel's stencil
// counts the faces of one volume only, exactly as with a light at a time, and the lighting pass
// that resets every mark it passes leaves the stencil clean for the next batch. Disjoint because
// every volume's screen rectangle (its bounding ball's projection, padded for rounding:
// render/culling/ScreenBounds.h) is rounded out to cells of kStencilBatchCellPixels, and no two
// volumes of a batch occupy a common cell. Pure C++, no GL, so the tests check the grouping
// directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/scene/GpuScene.h"
#include "render/volumes/LightVolumes.h"

namespace manylights {

// The screen cells volumes occupy. A volume conflicts with those that share one of its cells,
// overlapping or not: coarser cells cost more batches, finer ones more cells per light to test
// and mark. 8 pixels keeps a small light (the courtyard's at 65,536 lights span 10 to 30 pixels
// at 1280x720) within a few cells.
inline constexpr int kStencilBatchCellPixels = 8;

// The camera and image the volumes are drawn with. View space looks along −Z with +Y up.
struct StencilBatchView {
    glm::mat4 view{1.0f};  // world to view space
    glm::vec3 eye{0.0f};   // in world space
    float tanHalfFovX = 1.0f;
    float tanHalfFovY = 1.0f;
    int width = 0;  // image size, pixels
    int height = 0;

    bool operator==(const StencilBatchView&) const = default;
};

// Lights of one batch: StencilBatches::order[first, first + spheres) are spheres, the `cones`
// after them cones, each part in ascending light order.
struct StencilBatch {
    std::uint32_t first = 0;
    std::uint32_t spheres = 0;
    std::uint32_t cones = 0;
};

struct StencilBatches {
    // Indices into the light buffer: the spheres around the eye (order[0, aroundEye)), which
    // need no stencil pass (eyeInsideSphereVolume), then the batches' lights.
    std::vector<std::uint32_t> order;
    std::uint32_t aroundEye = 0;
    std::vector<StencilBatch> batches;
};

// Cells [x0, x1] × [y0, y1] of kStencilBatchCellPixels; none when x0 > x1 or y0 > y1.
struct CellRect {
    int x0 = 1;
    int x1 = 0;
    int y0 = 1;
    int y1 = 0;
    bool isEmpty() const { return x0 > x1 || y0 > y1; }
};

// Which batches occupy which cells, for the first fit of StencilBatcher. Batch b is bit b % 64
// of word b / 64 of a cell. Only the last kOpenBatchWords words' batches take more lights: their
// rows are a ring (word-major: word w of cell c at (w % kOpenBatchWords) · cells + c), and a
// light that fits none of them opens the next 64, closing the oldest 64 once the ring is full.
// That bounds the memory (1.8 MB at 1280x720) and the search whatever the number of batches: a
// thousand lights on one spot are a thousand batches.
class StencilCellOccupancy {
public:
    static constexpr std::size_t kOpenBatchWords = 16;

    // No batch yet, over `cells` cells in rows of `cellsX`.
    void reset(std::size_t cells, int cellsX);
    // The lowest open batch none of whose lights occupies a cell of `rect`, which the light of
    // `rect` then occupies too; 0 for no cells (the light draws nothing, any batch takes it).
    std::uint32_t place(const CellRect& rect);

private:
    std::uint64_t* row(std::size_t word) { return rows_.data() + (word % kOpenBatchWords) * cells_; }
    template <typename Visit>
    void forEachCell(const CellRect& rect, Visit&& visit);
    std::uint32_t mark(const CellRect& rect, std::uint32_t batch);

    std::size_t cells_ = 0;
    int cellsX_ = 0;
    std::vector<std::uint64_t> rows_;
    // Per cell, a batch at or below its lowest open batch that does not occupy it.
    std::vector<std::uint32_t> firstFree_;
    std::size_t firstOpenWord_ = 0;
    std::size_t words_ = 0;  // opened so far
};

// Groups the spheres and cones of `groups` (indices into `lights`) into batches, each light into
// the first batch none of whose volumes occupies one of its cells. A volume the eye's plane cuts
// (it may cover any part of the screen) occupies every cell; one wholly behind the eye, or
// wholly outside the image, none (it draws nothing), and goes to the first batch. Keeps its
// working memory from call to call.
class StencilBatcher {
public:
    const StencilBatches& group(const StencilBatchView& view, std::span<const GpuLight> lights,
                                const LightVolumeGroups& groups);
    const StencilBatches& batches() const { return batches_; }

private:
    StencilCellOccupancy occupancy_;
    // Each light's batch, in the order spheres then cones, before they are grouped by batch.
    std::vector<std::uint32_t> batchOf_;
    std::vector<std::uint32_t> cursors_;
    StencilBatches batches_;
};

}  // namespace manylights
