#include "render/culling/ClusterGrid.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "gl/Driver.h"
#include "render/culling/CullingVariant.h"
#include "render/culling/LightTiles.h"
#include "render/programs/LightingPrograms.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

// Binding points shared with shaders/lib/clusters.glsl and the passes.
constexpr GLuint kTileDepthRangesBinding = bindings::CLUSTER_TILE_DEPTHS_BUFFER_BINDING;
constexpr GLuint kTileSlicesBinding = bindings::CLUSTER_TILE_SLICES_BUFFER_BINDING;
constexpr GLuint kMasksBinding = bindings::CLUSTER_LIGHT_MASKS_BUFFER_BINDING;
constexpr GLuint kSummariesBinding = bindings::CLUSTER_MASK_SUMMARIES_BUFFER_BINDING;
constexpr GLuint kTileGroupSize = 64;  // local_size_x of cluster_tiles.comp

GLuint groupsFor(std::uint32_t items, GLuint groupSize) { return (items + groupSize - 1) / groupSize; }

}  // namespace

ClusterGrid::ClusterGrid(GBufferLayout gbufferLayout, const ClusterGridShape& shape)
    : shape_(shape),
      tiles_("cluster tiles", {{GL_COMPUTE_SHADER, "cluster_tiles.comp"}},
             // The G-buffer's layout is a dimension of the lighting programs' key.
             CullingVariant{.grid = shape}.toDefines(
                 ShaderVariant{.technique = {.gbufferLayout = gbufferLayout}}.toDefines({}))),
      // The masks are the transparency grid's, whose boxes are the frustum's sections.
      assign_("cluster light masks", {{GL_COMPUTE_SHADER, "cluster_assign.comp"}},
              CullingVariant{.grid = ClusterGridShape{.tileSize = shape.tileSize, .slices = shape.slices},
                             .lightTiles = true}
                  .toDefines())
{
}

std::uint32_t ClusterGrid::lightsPerBatch(int width, int height, int slices)
{
    const std::size_t clusters = static_cast<std::size_t>(tilesAlong(width, kClusterTileSize)) *
                                 static_cast<std::size_t>(tilesAlong(height, kClusterTileSize)) *
                                 static_cast<std::size_t>(slices);
    const std::size_t affordableWords = kClusterMaskBudgetBytes / (sizeof(std::uint32_t) * clusters);
    return static_cast<std::uint32_t>(std::clamp<std::size_t>(affordableWords * 32, 32, kLightsPerBatch));
}

void ClusterGrid::resize(int width, int height, std::uint32_t largestBatch)
{
    gridWidth_ = tilesAlong(width, shape_.tileSize);
    gridHeight_ = tilesAlong(height, shape_.tileSize);
    const auto tiles = static_cast<std::uint32_t>(gridWidth_ * gridHeight_);
    clusterCount_ = tiles * static_cast<std::uint32_t>(shape_.slices);
    const std::size_t tileBytes = sizeof(std::uint32_t) * tiles;
    if (!tileSlices_ || tileSlices_.size() != tileBytes) {
        // Dynamic: coverDepthRanges writes them from the CPU.
        tileDepthRanges_ = gl::Buffer("cluster tile depth ranges", 4 * tileBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
        tileSlices_ = gl::Buffer("cluster tile slices", tileBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
        const bool texels = static_cast<std::int64_t>(tiles) <= gl::queryInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
        tileDepthRangeTexels_ = texels
                                    ? gl::BufferTexture("cluster tile depth range texels", GL_RGBA32F, tileDepthRanges_)
                                    : gl::BufferTexture();
        tileSliceTexels_ =
            texels ? gl::BufferTexture("cluster tile slice texels", GL_R32UI, tileSlices_) : gl::BufferTexture();
    }
    // Sized for the largest batch of this frame: the size is known before any pass runs.
    const std::size_t words = shape_.surfaceBounds ? 0 : std::max<std::size_t>(maskWordsFor(largestBatch), 1);
    const std::size_t maskBytes = sizeof(std::uint32_t) * clusterCount_ * words;
    const std::size_t summaryBytes = sizeof(std::uint32_t) * clusterCount_ * maskWordsFor(words);
    if (words > 0 && (!masks_ || masks_.size() < maskBytes))
        masks_ = gl::Buffer("cluster light masks", maskBytes, nullptr, 0);
    if (words > 0 && (!summaries_ || summaries_.size() < summaryBytes))
        summaries_ = gl::Buffer("cluster mask summaries", summaryBytes, nullptr, 0);
    const std::size_t boundsBytes = 2 * 4 * sizeof(float) * clusterCount_;
    if (shape_.surfaceBounds && (!bounds_ || bounds_.size() != boundsBytes)) {
        bounds_ = gl::Buffer("cluster surface bounds", boundsBytes, nullptr, 0);
        boundTexels_ = static_cast<std::int64_t>(2 * clusterCount_) <= gl::queryInteger(GL_MAX_TEXTURE_BUFFER_SIZE)
                           ? gl::BufferTexture("cluster surface bound texels", GL_RGBA32F, bounds_)
                           : gl::BufferTexture();
    }
}

void ClusterGrid::bind() const
{
    tileDepthRanges_.bindBase(GL_SHADER_STORAGE_BUFFER, kTileDepthRangesBinding);
    tileSlices_.bindBase(GL_SHADER_STORAGE_BUFFER, kTileSlicesBinding);
    if (masks_) {
        masks_.bindBase(GL_SHADER_STORAGE_BUFFER, kMasksBinding);
        summaries_.bindBase(GL_SHADER_STORAGE_BUFFER, kSummariesBinding);
    }
    if (bounds_)
        bounds_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_BOUNDS_BUFFER_BINDING);
}

void ClusterGrid::bindTexels() const
{
    ML_ASSERT(hasTexels());
    tileDepthRangeTexels_.bindUnit(bindings::CLUSTER_TILE_DEPTHS_UNIT);
    tileSliceTexels_.bindUnit(bindings::CLUSTER_TILE_SLICES_UNIT);
    if (boundTexels_)
        boundTexels_.bindUnit(bindings::CLUSTER_BOUNDS_UNIT);
}

Pass ClusterGrid::fitPass()
{
    return {.name = "clusters",
            .sampled = Resource::GBuffer,
            .storage = Resource::LightGrid,
            .writes = Resource::LightGrid};
}

Pass ClusterGrid::assignPass(std::string_view name)
{
    return {.name = name, .storage = Resource::LightGrid, .writes = Resource::LightGrid};
}

void ClusterGrid::fitToSurfaces()
{
    bind();
    tiles_.use();
    glDispatchCompute(groupsFor(static_cast<std::uint32_t>(gridWidth_ * gridHeight_), kTileGroupSize), 1, 1);
}

void ClusterGrid::coverDepthRanges(const std::vector<glm::vec2>& ranges)
{
    ML_ASSERT(ranges.size() == static_cast<std::size_t>(gridWidth_ * gridHeight_));
    const std::uint32_t allSlices = shape_.slices == 32 ? ~0u : (1u << shape_.slices) - 1u;
    std::vector<std::uint32_t> slices(ranges.size());
    // lib/clusters.glsl's tileSlicing, made here: the shaders read it as it is.
    std::vector<glm::vec4> slicings(ranges.size(), glm::vec4(0.0f));
    for (std::size_t tile = 0; tile < ranges.size(); ++tile) {
        const glm::vec2 range = ranges[tile];
        if (!(range.x < range.y))
            continue;
        slices[tile] = allSlices;
        slicings[tile] =
            glm::vec4(range, std::log(range.x), static_cast<float>(shape_.slices) / std::log(range.y / range.x));
    }
    tileDepthRanges_.update(0, slicings.size() * sizeof(glm::vec4), slicings.data());
    tileSlices_.update(0, slices.size() * sizeof(std::uint32_t), slices.data());
}

void ClusterGrid::assignLights(const LightBatch& batch)
{
    ML_ASSERT(masks_);  // a grid with surface bounds lists its lights (ClusterLists) instead
    // The draws that read the masks of the previous build are done with them: the pass waits
    // for them (FramePasses: llvmpipe queues draws but clears buffers and runs compute passes
    // at once; without the wait a transparent layer drawn before a rebuild read the next
    // build's masks, 1,799 values off forward's in a test of it).
    // Cleared by the GL: on llvmpipe a plain memset of the batch's words beats a compute pass
    // that clears only the occupied clusters' words.
    const std::size_t words = maskWordsFor(batch.size());
    masks_.clearToZero(sizeof(std::uint32_t) * clusterCount_ * words);
    summaries_.clearToZero(sizeof(std::uint32_t) * clusterCount_ * maskWordsFor(words));
    // The clears are GL commands before the dispatch: its shaders see them without a barrier.
    bind();
    dispatchLightTiles(assign_, batch, gridWidth_, gridHeight_);
}

}  // namespace manylights
