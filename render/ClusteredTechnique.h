// clustered (Olsson, Billeter, Assarsson, HPG 2012): the view frustum cut into clusters:
// screen tiles times depth slices. Each frame, a compute pass finds each tile's depth range
// and the slices of it that hold surfaces (the slices adapt to each tile: Olsson et al.'s
// compaction to occupied clusters, and Harada's 2.5D culling, in one); then, per light
// batch, a compute pass sets each light's bit in the mask of every occupied cluster it
// reaches, and the lighting pass shades each pixel with the lights of its cluster's mask.
// The masks have a fixed size (a bit per light of the batch), so no light can be dropped,
// nothing is read back and no pass loops more than a bounded number of times
// (docs/techniques.md says why bit masks and not lists).
#pragma once

#include <cstdint>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/LightBatches.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

namespace manylights {

// The cluster grid: 16-pixel tiles, each with 8 depth slices spaced exponentially between
// its nearest and farthest surface (the shaders get them as CLUSTER_TILE_SIZE and
// CLUSTER_SLICES; docs/techniques.md has the measurements behind them).
inline constexpr int kClusterTileSize = 16;
inline constexpr int kClusterSlices = 8;
// The cluster masks of one batch may take this much memory; at sizes where a batch of
// kLightsPerBatch lights would need more, the batches get smaller (in whole mask words).
inline constexpr std::size_t kClusterMaskBudgetBytes = std::size_t{64} << 20;

class ClusteredTechnique : public Technique {
public:
    explicit ClusteredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "clustered"; }
    void render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler) override;

    // clusters (the grid's size) and light_batches (passes of the last frame).
    std::vector<TechniqueCounter> counters() const override;

    // The most lights one batch takes for an image of this size (a multiple of 32).
    static std::uint32_t lightsPerBatch(int width, int height);

private:
    // Sizes the grid's buffers for the image and the frame's largest light batch.
    void resizeGrid(int width, int height, std::uint32_t largestBatch);
    void bindGrid() const;
    void findTileRanges(const GpuScene& scene, FrameTargets& targets);
    void assignLights(const GpuScene& scene, const LightBatch& batch);

    gl::Program tiles_;
    gl::Program assign_;
    LightingProgram lighting_;
    // A frame of one batch that fits a uniform window reads its lights from it
    // (render/LightBatches.h); larger frames keep batches as large as the mask budget allows.
    bool lightWindows_;
    int gridWidth_ = 0;
    int gridHeight_ = 0;
    std::uint32_t clusterCount_ = 0;
    std::uint32_t batchCount_ = 0;
    gl::Buffer tileDepthRanges_;
    gl::Buffer tileSlices_;
    gl::Buffer masks_;
    gl::Buffer summaries_;
};

}  // namespace manylights
