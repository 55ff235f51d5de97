// The cluster grid of shaders/lib/clusters.glsl: screen tiles of a shape's size, each cut into
// depth slices spaced exponentially over a depth range of its own. Two users fill it differently:
// - clustered and tiled fit each tile's range to the opaque surfaces seen through it and give
//   lights only to the slices that hold one (fitToSurfaces): Olsson et al.'s compaction; they
//   keep each cluster's surface box and list its lights with render/culling/ClusterLists.h;
// - the transparency pass (render/effects/TransparencyPass.h) needs lights wherever a transparent
//   surface may be, in front of, between or beyond the opaque ones: each tile spans the
//   depths of the transparent objects over it, every slice is occupied (coverDepthRanges), and
//   each cluster has a bit mask over a light batch (assignLights). The masks have a fixed
//   size (a bit per light of the batch), so no light can be dropped, nothing is read back and
//   no pass loops more than a bounded number of times.
#pragma once

#include <compare>
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/frame/FramePasses.h"
#include "render/programs/GBufferLayout.h"
#include "render/programs/LightBatches.h"

namespace manylights {

// 16-pixel tiles, 8 slices each (the shaders get them as CLUSTER_TILE_SIZE and CLUSTER_SLICES;
// docs/techniques.md has the measurements behind them).
inline constexpr int kClusterTileSize = 16;
inline constexpr int kClusterSlices = 8;
// The cluster masks of one batch may take this much memory; at sizes where a batch of
// kLightsPerBatch lights would need more, the batches get smaller (in whole mask words).
inline constexpr std::size_t kClusterMaskBudgetBytes = std::size_t{64} << 20;

// The shape of a grid: its tiles' size in pixels, its slices per tile (at most 32: one bit each
// in lib/clusters.glsl's tileOccupiedSlices), and whether fitting it to the surfaces keeps
// the box around each cluster's surfaces (the light lists test lights against those).
struct ClusterGridShape {
    int tileSize = kClusterTileSize;
    int slices = kClusterSlices;
    bool surfaceBounds = false;

    auto operator<=>(const ClusterGridShape&) const = default;
};

class ClusterGrid {
public:
    // The programs that read the grid are compiled for the same shape (render/culling/
    // CullingVariant.h: grid).
    explicit ClusterGrid(GBufferLayout gbufferLayout, const ClusterGridShape& shape = {});

    // The most lights one batch of masks takes for an image of this size (a multiple of 32), in
    // a grid of kClusterTileSize tiles.
    static std::uint32_t lightsPerBatch(int width, int height, int slices = kClusterSlices);

    // Sizes the buffers for the image and, for a grid with masks, the frame's largest light
    // batch. A grid with surface bounds has none: its lights are listed by ClusterLists.
    void resize(int width, int height, std::uint32_t largestBatch);
    // Binds the buffers at lib/clusters.glsl's binding points.
    void bind() const;
    // Whether the tiles and surface boxes can be read as texels too (lib/cluster_culling.glsl,
    // CLUSTER_GRID_TEXELS): where the driver's texture buffers hold them. After resize.
    bool hasTexels() const { return tileDepthRangeTexels_ && (!bounds_ || boundTexels_); }
    // Binds those texel views at lib/cluster_culling.glsl's units; where hasTexels().
    void bindTexels() const;
    // The passes the grid is built in: fitting it to the surfaces (the G-buffer) and setting
    // the lights (coverDepthRanges and assignLights), which the scene binds for.
    static Pass fitPass();
    static Pass assignPass(std::string_view name);

    // Each tile's range: its opaque surfaces' nearest to farthest view depth (from the depth
    // buffer and the G-buffer); its occupied slices: those holding a surface. In fitPass().
    void fitToSurfaces();
    // Each tile's range (one per tile, row by row): view depths nearest to farthest, with
    // 0 < nearest < farthest; every slice of such a tile is occupied. A tile whose range is
    // empty (nearest >= farthest) has no slice occupied: lights are assigned only where
    // something needs them.
    void coverDepthRanges(const std::vector<glm::vec2>& ranges);
    // Sets each light of the batch in the masks of the occupied clusters it may reach. In
    // assignPass().
    void assignLights(const LightBatch& batch);

    std::uint32_t clusterCount() const { return clusterCount_; }
    // The GPU memory of its buffers.
    std::size_t memoryBytes() const
    {
        return tileDepthRanges_.size() + tileSlices_.size() + masks_.size() + summaries_.size() + bounds_.size();
    }
    const ClusterGridShape& shape() const { return shape_; }
    // The tiles across and down, after resize.
    int gridWidth() const { return gridWidth_; }
    int gridHeight() const { return gridHeight_; }

private:
    ClusterGridShape shape_;
    gl::Program tiles_;
    gl::Program assign_;
    int gridWidth_ = 0;
    int gridHeight_ = 0;
    std::uint32_t clusterCount_ = 0;
    gl::Buffer tileDepthRanges_;
    gl::Buffer tileSlices_;
    gl::Buffer masks_;
    gl::Buffer summaries_;
    gl::Buffer bounds_;  // with surfaceBounds: lib/clusters.glsl's clusterBounds
    // Texel views of the buffers above, where the driver's texture buffers hold them.
    gl::BufferTexture tileDepthRangeTexels_;
    gl::BufferTexture tileSliceTexels_;
    gl::BufferTexture boundTexels_;
};

}  // namespace manylights
