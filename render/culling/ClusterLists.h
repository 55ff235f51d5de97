// The light lists of the clustered and tiled techniques (issue 29): per cluster of a
// ClusterGrid, the lights that may reach it, built on the GPU every frame in one sequence
// whatever the light count, and read by one lighting pass (shaders/lib/cluster_lists.glsl).
//
// The sequence (passes named "cluster pairs", "cluster lists" and "pair sort" or "mask lists"):
// 1. cluster_pairs.comp counts each light's (cluster, light) pairs: an invocation per light of
//    at most 64 tiles (ClusterLists.cpp), a workgroup per wider light and band of tile rows, the
//    culling tests of lib/cluster_culling.glsl; it lists the wide lights and the narrow lights
//    it found pairs for, each list the size of an indirect dispatch. The lights covering most
//    of the grid it lists for the global list instead (below), which global_light_order.comp
//    then sorts.
// 2. A scan (render/culling/GpuScan.h) of the counts gives each light its first slot, and the total.
// 3. cluster_pairs.comp again, compiled for writing, writes the pairs there and counts each
//    cluster's: an invocation per listed narrow light, a workgroup per wide light and band.
// 4. cluster_long_lists.comp notes the longest list and the tiles of lists longer than a part.
// 5. A scan of the clusters' counts gives each list its first entry.
// 6. A stable radix sort by cluster (pair_sort.comp and the scan, kSortRadixBits a digit)
//    puts each cluster's lights together, in the lights' order: the sum over a pixel's lights
//    runs in one order on every run, so the image is a function of the scene alone. Its last
//    digit also copies each pair's light sphere beside it, for the lighting's reach test.
// A frame of at most kMaskedListLights lights (and masks within kMaskedListBudgetBytes) sorts
// nothing: steps 1 and 3 set each pair as the light's bit in its cluster's mask instead (the
// narrow lights in the counting run, which then needs no writing run, nor step 2), and after
// step 5 cluster_mask_lists.comp walks each cluster's mask in bit order into its list: the
// same lists, in the same order, as the sort makes. The sort costs what the pairs are (the
// courtyard has 200,000 to 230,000 at 1280x720 from 1,024 to 16,384 lights: 10 ms on
// llvmpipe, four digits of 15-bit keys), the masks a bit per light per cluster, which at
// 1,024 lights is 32 words a cluster and at 16,384 lights 512 (docs/techniques.md has the
// measurements).
//
// Sorted pairs rather than bit masks over light batches (the grid's other user, the
// transparency pass, keeps masks): a mask costs a bit per light for every cluster, so a frame
// of a million lights needed 128 batches, each a mask clear, an assignment and a lighting pass
// over the whole image; the pairs cost what the lights reach.
//
// The global list: a light whose screen rectangle covers at least kGlobalLightGridFraction of
// the grid's tiles, or that is unbounded, would be in nearly every list, so it gets no pairs
// and goes to one list that every pixel walks before its cluster's (lib/cluster_lists.glsl).
// The counting run lists the candidates in any order; global_light_order.comp sorts them into
// the lights' order, so that the sum runs in one order on every run. The list holds
// kGlobalLightCapacity lights: where the candidates are more, none is global and all of them
// get pairs as wide lights, in the same frame. All or none: the set of the first
// kGlobalLightCapacity to arrive would change from run to run, and with it the image.
//
// Nothing is read back during the frame, and nothing waits for it. The storage for pairs and
// the number of parts the lighting walks are planned from the last frame whose status has been
// read (with headroom); the GPU counts what the frame needs into the status buffer, which
// frameIssued() copies, after the frame's commands, into a small ring of buffers the CPU reads
// through a persistent mapping behind a fence: a frame or two later where frames are issued
// back to back (PassTiming::Gpu), at once where the renderer waits for the frame anyway.
// oldestFrameFitted() then says whether the plan that frame was built with held. When it did
// not (the first frame, or a frame whose lights moved into more clusters), the lists are
// resized and the renderer redoes the frame (or, issuing frames back to back, drops it from its
// samples and issues another): counted as cluster_rebuilds. No pair is ever dropped from an
// image that is kept.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/culling/ClusterGrid.h"
#include "render/culling/CullingVariant.h"
#include "render/culling/GpuScan.h"
#include "render/frame/FramePasses.h"
#include "render/frame/FrameTargets.h"
#include "render/frame/ReadbackRing.h"
#include "render/frame/TechniqueOptions.h"
#include "render/programs/LightingPrograms.h"
#include "render/programs/ProgramVariants.h"

namespace manylights {

// The lights one invocation of the lighting walks (a part of a list): within the loop bound
// of render/programs/LightBatches.h, with room for the iterations around the walk (each entry
// may take two: its reach test and its shading, ClusterLists.cpp).
inline constexpr std::uint32_t kClusterListPart = 4096;
// The radix sort's digit: 16 values, each chunk's counts in 16 registers' worth of a local array.
inline constexpr int kSortRadixBits = 4;
inline constexpr std::uint32_t kSortChunk = 64;  // pairs one invocation of pair_sort.comp walks
// The most lights the global list holds. Part 0 of a list is walked after the global list, so
// both are within the loop bound together, with the shadow filters (ClusterLists.cpp checks:
// 4,096 did not fit beside the chunked walk of a part), and the sort's rank count walks the
// list once per light: 2,048 lights that each cover half the screen cost far more to light
// than either.
inline constexpr std::uint32_t kGlobalLightCapacity = 2048;
// The share of the grid's tiles a light's screen rectangle must cover to be global
// (docs/techniques.md has the measurements).
inline constexpr double kGlobalLightGridFraction = 0.5;

// The most tiles one invocation of cluster_pairs.comp walks for a light (CLUSTER_PAIR_NARROW_TILES);
// lights covering more are wide, a workgroup each per band (lib/light_tiles.glsl). 32 and 64
// measured alike on the courtyard (256 was slower for clustered at 1,024 lights, its lanes out
// of step); 64 keeps 131,072 lights of 36 tiles each (tests/scenes/lights_on_one_spot.json,
// tiled) narrow: as 262,144 workgroups they took 21 s and 20 GB under AddressSanitizer, whose
// allocator llvmpipe's per-workgroup allocations then go through.
inline constexpr std::uint32_t kNarrowLightTiles = 64;

// The most lights whose lists are built from bit masks (above) rather than sorted, where the
// masks of every cluster take at most kMaskedListBudgetBytes (a frame of 16,384 lights at
// 1280x720 in clustered's grid: 60.8 MB; at 1920x1080 from 8,192 lights on, clustered sorts).
// On the courtyard at 1280x720 the masks' lists cost 12 against 20 ms at 1,024 lights, 19
// against 24 at 16,384, and tiled's 20 against 23-24 at 32,768 (docs/techniques.md).
// CullingTuning::maskedListLights (MANYLIGHTS_MASKED_LIST_LIGHTS) sets a lower number for
// measuring (scripts/measure-masked-lists.sh) and testing: 0 sorts every frame's pairs. Not a
// higher one: the masks' walk of a cluster every light reaches stays within the loop bound up
// to kMaskedListLights (ClusterLists.cpp checks).
inline constexpr std::uint32_t kMaskedListLights = 16384;
inline constexpr std::size_t kMaskedListBudgetBytes = std::size_t{64} << 20;

// The shape of the clustered technique's grid (docs/techniques.md has the measurements).
inline constexpr ClusterGridShape kClusteredGridShape{.tileSize = 16, .slices = 8, .surfaceBounds = true};

class ClusterLists {
public:
    // For grids of `shape` (their programs are compiled for it), made as `tuning` asks.
    explicit ClusterLists(const ClusterGridShape& shape, const CullingTuning& tuning = {});

    // Builds the frame's lists for the scene's lights (bound by the passes) over `grid`, fitted
    // to the frame's surfaces already.
    void build(const GpuScene& scene, FramePasses& passes, const ClusterGrid& grid);
    // Binds what the lighting programs read: the lists and the long lists' tiles.
    void bind() const;
    // Whether the lighting reads the lists as R32UI texels, and so needs programs built with
    // ShaderVariant::listTexels: where the scene reads its lights from texels too
    // (RendererDesc::lightTexels) and the driver's texture buffers hold the planned storage.
    bool readsTexels() const { return texels_ && sceneTexels_; }
    // Whether the frame built last has a global list, which part 0's lighting must walk (with
    // programs of ShaderVariant::globalLightList). Planned from the frame before: a
    // frame has one where that frame found candidates, and no more of them than the list
    // holds, so that the lighting of a scene without any does not carry the walk of an empty
    // list (on the courtyard the difference measured within the spread). A frame without one
    // gives its candidates pairs, as any other light: nothing waits for the plan.
    bool hasGlobalList() const { return globalListOfBuild_; }
    // The parts after part 0 that the lists of the frame built last were planned with
    // (render/techniques/ListLighting.h lights each).
    std::uint32_t laterParts() const { return laterParts_; }
    // Dispatches the bound compute program over the tiles whose lists are longer than a part
    // (listed by cluster_long_lists.comp; an indirect dispatch: the CPU does not know how many).
    void dispatchOverLongListTiles() const;

    // After all of a frame's commands are issued: copies the status of the frame built last
    // (if one was built since) for oldestFrameFitted, behind a fence.
    void frameIssued();
    // Of the oldest frame issued and not yet checked: whether its lists held every pair and its
    // parts covered the longest list (true where no frame is pending). If not, plans the storage
    // and parts the frame needs: the frame must be redone (and counts as a rebuild). Reads the
    // frame's status through the mapping, waiting for its fence where the GPU has not passed
    // it yet.
    bool oldestFrameFitted();
    // Frames issued whose status oldestFrameFitted has not read yet.
    std::size_t framesPending() const { return statusCopies_.pending(); }

    std::uint64_t rebuilds() const { return rebuilds_; }
    std::uint32_t pairs() const { return status_.pairsNeeded; }
    std::uint32_t longestList() const { return status_.longestList; }
    // List entries the lighting walked (all pixels, all parts, the global list's too), when
    // counting work.
    std::uint32_t listVisits() const { return status_.listVisits; }
    // The lights of the last frame's global list (0 where it had none or the candidates were too many).
    std::uint32_t globalLights() const { return globalLightsOfFrame_; }
    // The GPU memory of the lists and their culling structures.
    std::size_t memoryBytes() const;
    // The --stats counters of a technique lit from these lists over `grid`, of the last frame:
    // clusters (the grid's size), cluster_pairs, longest_cluster_list, global_lights,
    // cluster_list_visits (when counting work), cluster_rebuilds (frames redone so far),
    // cluster_lists_from_masks (1 where the last frame's lists were made from bit masks) and
    // gpu_memory_bytes (the lights and their motions, the lists, the global list and the grid).
    std::vector<TechniqueCounter> counters(const ClusterGrid& grid) const;

private:
    struct Status {  // lib/cluster_list_status.glsl
        // The long-list tiles' workgroups: x up to 32,768, then z (lib/listed_dispatch.glsl).
        std::uint32_t longTileGroups[3] = {0, 1, 0};
        std::uint32_t pairsNeeded = 0;
        std::uint32_t longestList = 0;
        std::uint32_t wideLightGroups[3] = {0, 1, 0};  // y: the bands
        std::uint32_t listVisits = 0;
        std::uint32_t wideLights = 0;
        // The writing run's workgroups of narrow lights: x up to 32,768, then z (the counting
        // run adds them as it lists the lights it found pairs for).
        std::uint32_t pairedLightGroups[3] = {0, 1, 0};
        std::uint32_t pairedLights = 0;
        std::uint32_t globalLightCandidates = 0;
        std::uint32_t longTiles = 0;
    };

    void plan(std::uint32_t pairs);
    // The mask words of each cluster for `lightCount` lights, or 0 where the frame's pairs are
    // sorted instead (kMaskedListLights).
    std::uint32_t maskWordsFor(std::uint32_t lightCount, std::uint32_t clusterCount) const;
    void ensureMasks(std::uint32_t clusterCount, std::uint32_t words);
    void sortPairs(FramePasses& passes, std::uint32_t clusterCount);
    void listMasks(FramePasses& passes, std::uint32_t clusterCount, std::uint32_t words);
    void bindGlobalLights() const;

    // cluster_pairs.comp's program for the wide or the narrow lights, a run, the grid read as
    // texels or not (made when first used).
    const gl::Program& pairProgram(bool wide, PairRun run, bool gridTexels) const;

    ClusterGridShape shape_;
    std::uint32_t maskedListLights_;  // kMaskedListLights or CullingTuning::maskedListLights
    double globalLightGridFraction_;  // kGlobalLightGridFraction or CullingTuning's
    ProgramVariants<CullingVariant> pairPrograms_;
    gl::Program maskLists_;
    gl::Program longLists_;
    gl::Program sortCount_;
    gl::Program sortScatter_;
    gl::Program sortScatterGather_;  // the last digit: with the lights' spheres
    gl::Program globalLightOrder_;
    GpuScan scan_;

    std::uint32_t capacity_ = 0;    // pairs the storage holds
    std::uint32_t laterParts_ = 0;  // planned
    std::uint64_t rebuilds_ = 0;
    std::size_t lightMemoryBytes_ = 0;  // the scene's lights' (GpuScene::lightMemoryBytes), last frame
    Status status_;
    bool built_ = false;             // a frame was built whose status frameIssued() has not copied
    bool globalListPlanned_ = true;  // for the next frame built (hasGlobalList)
    bool globalListOfBuild_ = true;  // of the frame built last
    bool masked_ = false;            // the frame built last made its lists from masks
    std::uint32_t globalLightsOfFrame_ = 0;

    gl::Buffer lightPairOffsets_;
    gl::Buffer lightPairCursors_;
    gl::Buffer wideLights_;
    gl::Buffer pairedLights_;      // the narrow lights the counting run found pairs for
    gl::Buffer lightTileRecords_;  // what the counting run found for a light of a few tiles
    gl::Buffer keys_[2];
    gl::Buffer lights_[2];
    int sorted_ = 0;                    // which of lights_ holds the sorted lists
    gl::BufferTexture lightTexels_[2];  // lights_ as R32UI texels, where texels_
    gl::Buffer spheres_;                // the sorted pairs' light spheres (vec4)
    gl::BufferTexture sphereTexels_;    // spheres_ as RGBA32F texels, where texels_
    bool texels_ = false;               // the driver's texture buffers hold the storage
    bool sceneTexels_ = false;          // the scene of the last build reads its lights from texels
    gl::Buffer clusterCounts_;
    gl::Buffer clusterFirsts_;
    gl::Buffer longListTiles_;
    gl::Buffer histogram_;
    gl::Buffer statusBuffer_;
    // The plan a frame was built with, which its status is checked against.
    struct Plan {
        std::uint32_t capacity = 0;
        std::uint32_t laterParts = 0;
        bool globalList = false;
    };
    // Each frame's status, copied after its commands and read behind a fence (frameIssued).
    ReadbackRing<Status, Plan> statusCopies_{"cluster list status copy"};
    // Each cluster's bit mask over the frame's lights and its summary (a bit per mask word
    // holding a light), where the frame is masked. All zero between frames:
    // cluster_mask_lists.comp clears what it reads.
    gl::Buffer masks_;
    gl::Buffer maskSummaries_;
    gl::Buffer globalLightCandidates_;  // kGlobalLightCapacity lights, in any order
    gl::Buffer globalLights_;           // in the lights' order
    gl::Buffer globalLightRecords_;     // their GpuLight records, beside them
    gl::BufferTexture globalLightTexels_;
    gl::BufferTexture globalLightRecordTexels_;
};

// What tiled and clustered do before their lighting: the G-buffer, the grid fitted to its
// surfaces, and the lists built over that grid.
void buildListsOverSurfaces(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, ClusterGrid& grid,
                            ClusterLists& lists);

}  // namespace manylights
