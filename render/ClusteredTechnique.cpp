#include "render/ClusteredTechnique.h"

#include <string>

#include "render/DeferredTechnique.h"
#include "render/GpuScene.h"
#include "render/PassProfiler.h"

namespace manylights {

namespace {

// Binding points and locations shared with shaders/lib/clusters.glsl and the passes.
constexpr GLuint kOccupiedBinding = 2;
constexpr GLuint kCountsBinding = 3;
constexpr GLuint kOffsetsBinding = 4;
constexpr GLuint kIndicesBinding = 5;
constexpr GLuint kDepthRangeBinding = 7;
constexpr GLint kClusterCountLocation = 0;
constexpr GLuint kDepthUnit = 5;
constexpr GLuint kPixelGroupSize = 8;   // local_size of cluster_occupancy.comp
constexpr GLuint kLightGroupSize = 64;  // local_size of cluster_assign.comp and cluster_sort.comp

gl::Defines gridDefines(gl::Defines defines = {})
{
    defines.emplace_back("CLUSTER_TILE_SIZE", std::to_string(kClusterTileSize));
    defines.emplace_back("CLUSTER_SLICES", std::to_string(kClusterSlices));
    return defines;
}

gl::Defines fillDefines()
{
    gl::Defines defines = gridDefines();
    defines.emplace_back("FILL_LISTS", "1");
    return defines;
}

GLuint groupsFor(std::uint32_t items, GLuint groupSize) { return (items + groupSize - 1) / groupSize; }

void clearToZero(const gl::Buffer& buffer)
{
    const std::uint32_t zero = 0;
    glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

}  // namespace

ClusteredTechnique::ClusteredTechnique(const TechniqueOptions& options)
    : depthRange_("cluster depth range", {{GL_COMPUTE_SHADER, "cluster_depth_range.comp"}},
                  gridDefines(gbufferDefines(options.gbufferLayout))),
      occupancy_("cluster occupancy", {{GL_COMPUTE_SHADER, "cluster_occupancy.comp"}},
                 gridDefines(gbufferDefines(options.gbufferLayout))),
      countLights_("cluster light counts", {{GL_COMPUTE_SHADER, "cluster_assign.comp"}}, gridDefines()),
      offsets_("cluster offsets", {{GL_COMPUTE_SHADER, "cluster_offsets.comp"}}, gridDefines()),
      fillLists_("cluster light lists", {{GL_COMPUTE_SHADER, "cluster_assign.comp"}}, fillDefines()),
      sortLists_("cluster list sort", {{GL_COMPUTE_SHADER, "cluster_sort.comp"}}, gridDefines()),
      lighting_("clustered lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
                gridDefines(shaderDefines(options))),
      depthRangeBuffer_("cluster depth range", 2 * sizeof(std::uint32_t), nullptr)
{
}

void ClusteredTechnique::resizeGrid(int width, int height)
{
    const int gridWidth = (width + kClusterTileSize - 1) / kClusterTileSize;
    const int gridHeight = (height + kClusterTileSize - 1) / kClusterTileSize;
    if (gridWidth == gridWidth_ && gridHeight == gridHeight_)
        return;
    gridWidth_ = gridWidth;
    gridHeight_ = gridHeight;
    clusterCount_ = static_cast<std::uint32_t>(gridWidth * gridHeight * kClusterSlices);
    const std::size_t bytes = sizeof(std::uint32_t) * clusterCount_;
    occupied_ = gl::Buffer("cluster occupancy", bytes, nullptr, 0);
    counts_ = gl::Buffer("cluster light counts", bytes, nullptr, 0);
    offsetsBuffer_ = gl::Buffer("cluster offsets", bytes + sizeof(std::uint32_t), nullptr, 0);
    // The index buffer grows on demand (buildClusters); start with a few lights per cluster.
    indices_ = gl::Buffer("cluster light indices", 4 * bytes, nullptr, 0);
}

void ClusteredTechnique::buildClusters(const GpuScene& scene, FrameTargets& targets)
{
    resizeGrid(targets.width, targets.height);
    clearToZero(occupied_);
    clearToZero(counts_);
    occupied_.bindBase(GL_SHADER_STORAGE_BUFFER, kOccupiedBinding);
    counts_.bindBase(GL_SHADER_STORAGE_BUFFER, kCountsBinding);
    offsetsBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kOffsetsBinding);
    indices_.bindBase(GL_SHADER_STORAGE_BUFFER, kIndicesBinding);
    // Nearest starts at the largest float, farthest at 0: the atomics only move them inwards.
    const std::uint32_t emptyRange[2] = {0x7F7FFFFFu, 0u};
    depthRangeBuffer_.update(0, sizeof(emptyRange), emptyRange);
    depthRangeBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kDepthRangeBinding);
    scene.bind();
    targets.gbuffer.bindForReading();
    targets.depthStencil.bindUnit(kDepthUnit);

    const GLuint pixelGroupsX = groupsFor(static_cast<std::uint32_t>(targets.width), kPixelGroupSize);
    const GLuint pixelGroupsY = groupsFor(static_cast<std::uint32_t>(targets.height), kPixelGroupSize);
    depthRange_.use();
    glDispatchCompute(pixelGroupsX, pixelGroupsY, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    occupancy_.use();
    glDispatchCompute(pixelGroupsX, pixelGroupsY, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const auto lightCount = static_cast<std::uint32_t>(scene.lightCount());
    countLights_.use();
    glDispatchCompute(groupsFor(lightCount, kLightGroupSize), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    offsets_.set(kClusterCountLocation, clusterCount_);
    offsets_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    // The one read-back of the frame: the lists' total length, so the index buffer can
    // hold every list whatever the lights do (no per-cluster cap, nothing dropped).
    glGetNamedBufferSubData(offsetsBuffer_.id(), static_cast<GLintptr>(sizeof(std::uint32_t) * clusterCount_),
                            sizeof(std::uint32_t), &lastIndexCount_);
    const std::size_t needed = sizeof(std::uint32_t) * lastIndexCount_;
    if (needed > indices_.size()) {
        indices_ = gl::Buffer("cluster light indices", needed + needed / 2, nullptr, 0);
        indices_.bindBase(GL_SHADER_STORAGE_BUFFER, kIndicesBinding);
    }

    clearToZero(counts_);  // now the lists' cursors
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    fillLists_.use();
    glDispatchCompute(groupsFor(lightCount, kLightGroupSize), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    sortLists_.set(kClusterCountLocation, clusterCount_);
    sortLists_.use();
    glDispatchCompute(groupsFor(clusterCount_, kLightGroupSize), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

std::vector<TechniqueCounter> ClusteredTechnique::counters() const
{
    return {{"clusters", static_cast<double>(clusterCount_)},
            {"cluster_light_indices", static_cast<double>(lastIndexCount_)}};
}

void ClusteredTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    targets.gbuffer.fill(scene, profiler);
    {
        auto pass = profiler.pass("clusters");
        buildClusters(scene, targets);
    }
    auto pass = profiler.pass("lighting");
    shadeCoveredPixels(scene, targets, lighting_);
}

}  // namespace manylights
