// clustered (Olsson, Billeter, Assarsson, HPG 2012): the view frustum cut into froxels
// (screen tiles times exponential depth slices); each frame, compute passes find the
// froxels that hold visible surfaces, give each such cluster the list of lights that reach
// it (compact lists in one global index buffer, with offsets from a prefix sum), and the
// lighting pass shades each pixel with its cluster's list. The lists have no capacity: the
// index buffer grows to the frame's total, so no light is ever dropped.
#pragma once

#include <cstdint>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/Technique.h"

namespace manylights {

// The cluster grid: 16-pixel tiles, 64 exponential depth slices (measured on the default scene:
// light evaluations 1.75 x the in-range pairs, against 2.8 x for 32-pixel tiles and 32 slices) (the shaders get them as
// CLUSTER_TILE_SIZE and CLUSTER_SLICES).
inline constexpr int kClusterTileSize = 16;
inline constexpr int kClusterSlices = 64;

class ClusteredTechnique : public Technique {
public:
    explicit ClusteredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "clustered"; }
    void render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler) override;

    // clusters (the grid's size) and cluster_light_indices (entries of the global index
    // buffer in the last frame: the sum of all clusters' list lengths).
    std::vector<TechniqueCounter> counters() const override;

private:
    void resizeGrid(int width, int height);
    void buildClusters(const GpuScene& scene, FrameTargets& targets);

    gl::Program depthRange_;
    gl::Program occupancy_;
    gl::Program countLights_;
    gl::Program offsets_;
    gl::Program fillLists_;
    gl::Program sortLists_;
    gl::Program lighting_;
    int gridWidth_ = 0;
    int gridHeight_ = 0;
    std::uint32_t clusterCount_ = 0;
    gl::Buffer depthRangeBuffer_;
    gl::Buffer occupied_;
    gl::Buffer counts_;
    gl::Buffer offsetsBuffer_;
    gl::Buffer indices_;
    std::uint32_t lastIndexCount_ = 0;
};

}  // namespace manylights
