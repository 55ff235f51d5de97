// Light culling against screen tiles on the CPU (the tiled-quads technique): for every tile
// of the image, the lights that may reach a surface seen through it. Pure C++, no GL, so the
// tests can check it against the falloff functions directly.
//
// Conservative by construction: a (tile, light) pair is dropped only when the light's A·S is
// zero at every point the tile's pixels can see between the near and the far plane
// (docs/lighting.md). Each test below proves emptiness of an intersection, with margins for the
// float rounding of the shaders and of this code; anything it cannot prove empty is kept.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/scene/GpuScene.h"

namespace manylights {

// tiled-quads' tiles. 16 pixels rather than 32: each pixel evaluates fewer lights, for four
// times the tiles to cull (courtyard, 4096 lights, 1280x720: lighting 154 -> 125 ms as quads,
// culling 1.2 -> 2.9 ms; 8 and 24 pixels were slower, docs/performance.md).
inline constexpr int kDefaultTileSize = 16;

// The camera and image the tiles are cut from. View space looks along −Z with +Y up, like
// glm::lookAt and glm::perspective.
struct TileCullingView {
    glm::mat4 view{1.0f};  // world to view space
    float fovY = 0.0f;     // vertical field of view, radians
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    int width = 0;  // image size, pixels
    int height = 0;
    int tileSize = kDefaultTileSize;

    float aspect() const { return static_cast<float>(width) / static_cast<float>(height); }
};

// One tile's lights within TileLightLists::lightIndices; std430 layout of a uvec2.
struct TileRange {
    std::uint32_t offset = 0;
    std::uint32_t count = 0;
};
static_assert(sizeof(TileRange) == 8);

// Tiles are numbered row by row from the bottom-left corner, in GL window coordinates: tile
// (tx, ty), number ty · tilesX + tx, covers the pixels tx·size ≤ x < (tx+1)·size and
// ty·size ≤ y < (ty+1)·size (gl_FragCoord, y up), clipped to the image. Each tile's light
// indices are in ascending order.
struct TileLightLists {
    int tileSize = 0;
    int tilesX = 0;
    int tilesY = 0;
    std::vector<TileRange> tiles;
    std::vector<std::uint32_t> lightIndices;

    std::size_t tileCount() const { return tiles.size(); }
    std::size_t tileIndex(int tx, int ty) const { return static_cast<std::size_t>(ty) * tilesX + tx; }
    std::span<const std::uint32_t> lightsOf(std::size_t tile) const
    {
        return std::span<const std::uint32_t>(lightIndices).subspan(tiles[tile].offset, tiles[tile].count);
    }
};

// Culls `lights` (as packed for the GPU, GpuScene::packedLights) against the tiles of
// `view`:
// - radius 0 (never lit): in no tile; radius falloff::kUnboundedRadius: in every tile;
// - other lights: in the tiles whose view-space frustum (four side planes, near and far)
//   meets the light's sphere, tested exactly against each tile's pyramid, not just its
//   planes; only the tiles within the sphere's projected screen rectangle are visited
//   (the whole screen when the sphere contains the eye or crosses the near plane);
// - spots narrower than 90°: also dropped from tiles whose planes separate them from the
//   spherical sector (sphere ∩ cone) their light fills.
// Keeps its working memory from call to call, so culling every frame allocates nothing
// once the lists have reached their size.
//
// Culls on several threads (issue 41: tiled-quads culls on every core), each taking runs of
// consecutive lights; the lists are the same to the byte whatever the number of threads.
class TileCuller {
public:
    // On `threads` threads (1 to kMaxCullingThreads; CullingTuning::cullingThreads); 0: on every
    // core for kParallelCullingLights lights or more and on one below (where starting threads
    // would cost more than they save).
    explicit TileCuller(unsigned threads = 0) : threads_(threads) {}
    const TileLightLists& cull(const TileCullingView& view, std::span<const GpuLight> lights);
    const TileLightLists& lists() const { return lists_; }

private:
    // The threads that cull `lightCount` lights.
    unsigned threadsFor(std::size_t lightCount) const;

    // A run of consecutive lights: every (tile, light) pair accepted, in ascending light
    // order, and the count of each tile's, before the counting sort that groups all chunks'
    // pairs by tile (which turns the counts into where the chunk's next pair of each tile goes).
    // A cache line each: threads appending to neighbouring chunks would otherwise write to one
    // line (the vectors' ends) at every pair.
    struct alignas(64) Chunk {
        std::vector<std::uint32_t> pairTiles;
        std::vector<std::uint32_t> pairLights;
        std::vector<std::uint32_t> tileCounts;
    };
    unsigned threads_;
    TileLightLists lists_;
    std::vector<Chunk> chunks_;
};

// Below this many lights TileCuller culls on one thread unless told otherwise: one thread culls
// 4,096 courtyard-like lights at 1280x720 in about 2 ms, and on a busy machine a helper thread
// may start milliseconds late (idle, a thread's start and join take about 20 µs).
inline constexpr std::size_t kParallelCullingLights = 4096;

// The most threads a TileCuller may be told to cull on (for measuring,
// scripts/measure-tile-culling.sh, and testing: MANYLIGHTS_CULLING_THREADS).
inline constexpr unsigned kMaxCullingThreads = 256;

// One-shot form of TileCuller::cull.
TileLightLists cullLightsToTiles(const TileCullingView& view, std::span<const GpuLight> lights);

}  // namespace manylights
