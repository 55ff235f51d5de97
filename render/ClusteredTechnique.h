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

#include "render/ClusterGrid.h"
#include "render/LightBatches.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

namespace manylights {

class ClusteredTechnique : public Technique {
public:
    explicit ClusteredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "clustered"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

    // clusters (the grid's size) and light_batches (passes of the last frame).
    std::vector<TechniqueCounter> counters() const override;

private:
    ClusterGrid grid_;
    // Compiled per light source: a frame of one batch that fits a uniform window reads it where
    // the scene reads windows (GpuScene::readsLightWindows); other frames read the light texels
    // and keep batches as large as the mask budget allows.
    LightingProgram lighting_;
    std::uint32_t batchCount_ = 0;  // of the last frame
};

}  // namespace manylights
