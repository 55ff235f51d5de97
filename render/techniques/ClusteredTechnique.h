// clustered (Olsson, Billeter, Assarsson, HPG 2012): the view frustum cut into clusters:
// screen tiles times depth slices. Each frame, a compute pass finds each tile's depth range
// and the slices of it that hold surfaces (the slices adapt to each tile: Olsson et al.'s
// compaction to occupied clusters, and Harada's 2.5D culling, in one); then the light lists
// of the occupied clusters are built on the GPU (render/culling/ClusterLists.h: pairs counted,
// written and sorted by cluster), and one lighting pass shades each pixel with its cluster's
// list, testing each light against the pixel's surface before shading it: a full-screen
// fragment pass, or under --lighting-stage compute (the GPU profile's) a compute pass of a
// workgroup per tile, the same image bit for bit (docs/techniques.md). Lists longer than
// one invocation may walk are finished by passes over their tiles only. Nothing is read back
// during the frame, and no light is dropped at any count (docs/techniques.md).
#pragma once

#include "render/culling/ClusterGrid.h"
#include "render/culling/ClusterLists.h"
#include "render/techniques/ListLighting.h"
#include "render/techniques/Technique.h"

namespace manylights {

class ClusteredTechnique : public Technique {
public:
    explicit ClusteredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "clustered"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;
    void frameIssued() override { lists_.frameIssued(); }
    bool oldestFrameFitted() override { return lists_.oldestFrameFitted(); }

    // clusters (the grid's size), cluster_pairs and longest_cluster_list (of the last frame),
    // cluster_rebuilds (frames redone so far) and gpu_memory_bytes (lists and grid).
    std::vector<TechniqueCounter> counters() const override;

private:
    ClusterGrid grid_;
    ClusterLists lists_;
    ListLighting lighting_;  // in the stage of the technique's options
};

}  // namespace manylights
