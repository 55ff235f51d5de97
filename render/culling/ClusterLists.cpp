#include "render/culling/ClusterLists.h"
#include "render/programs/Bindings.h"
#include "render/programs/WorkgroupRows.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>

#include "core/Error.h"
#include "gl/Driver.h"
#include "render/culling/LightTiles.h"
#include "render/programs/Locations.h"
#include "render/programs/LoopBudget.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

constexpr GLuint kListGroupSize = 64;  // local_size_x of the list passes
// A wide light's walk of a band (lib/light_tiles.glsl): its lane's share of the band's tiles,
// each tile's slices.
static_assert(kTilesPerBand / kLightTileLanes * (kClusterSlices + 1) < kMaxLoopIterations);
// A part's walk: each entry tested once and shaded at most once, two iterations per chunk of 32
// (lib/cluster_lists.glsl); before it, in part 0, the global list, an iteration per light; the
// shadow filters of the shadowed lights (LightBatches.cpp's count); room for the loops around it.
static_assert(2 * kClusterListPart + 2 * (kClusterListPart / 32) + kGlobalLightCapacity + kShadowLookupBudget + 1024 <=
              kMaxLoopIterations);
// cluster_mask_lists.comp's walk of a cluster that every light of a masked frame reaches: the
// summary's words, the mask's words and two lights an iteration.
static_assert(kMaskedListLights / 1024 + kMaskedListLights / 32 + kMaskedListLights / 2 <= kMaxLoopIterations);
// The smallest storage planned: a few small frames fit it without a rebuild.
constexpr std::uint32_t kMinimumCapacity = 1u << 16;
// The first frame's plan, before any frame has said what it needs: 16 pairs per cell (the
// default scene has 6 per cluster at 1280x720, the courtyard 8 to 13 from 1,024 to 1,048,576
// lights), so that a single image is rarely rendered twice.
constexpr std::uint32_t kFirstPlanPairsPerCell = 16;

GLuint groupsFor(std::uint32_t items) { return (items + kListGroupSize - 1) / kListGroupSize; }

Pass listPass(std::string_view name)
{
    return {.name = name, .storage = Resource::LightGrid, .writes = Resource::LightGrid};
}

std::size_t bytesOf(std::uint32_t uints) { return std::size_t{uints} * sizeof(std::uint32_t); }

// A cluster mask's summary words (lib/clusters.glsl clusterMaskSummaryWords).
std::uint32_t summaryWordsOf(std::uint32_t maskWords) { return (maskWords + 31) / 32; }

// The tiles a light's screen rectangle must cover to be global in a grid of `tiles`: at least one.
std::uint32_t globalLightTiles(double gridFraction, std::uint32_t tiles)
{
    const double wanted = std::ceil(gridFraction * tiles);
    return static_cast<std::uint32_t>(std::clamp(wanted, 1.0, static_cast<double>(tiles) + 1.0));
}

// A storage buffer of at least `uints` uints, made anew only when it has fewer.
void ensure(gl::Buffer& buffer, std::string_view label, std::uint32_t uints)
{
    const std::size_t bytes = std::max<std::size_t>(bytesOf(uints), sizeof(std::uint32_t));
    if (!buffer || buffer.size() < bytes)
        buffer = gl::Buffer(label, bytes, nullptr, 0);
}

}  // namespace

ClusterLists::ClusterLists(const ClusterGridShape& shape, const CullingTuning& tuning)
    : shape_(shape),
      maskedListLights_(tuning.maskedListLights.value_or(kMaskedListLights)),
      globalLightGridFraction_(tuning.globalLightGridFraction.value_or(kGlobalLightGridFraction)),
      pairPrograms_("cluster pairs", {{GL_COMPUTE_SHADER, "cluster_pairs.comp"}}),
      maskLists_("cluster mask lists", {{GL_COMPUTE_SHADER, "cluster_mask_lists.comp"}},
                 CullingVariant{.grid = shape}.toDefines()),
      longLists_("cluster long lists", {{GL_COMPUTE_SHADER, "cluster_long_lists.comp"}},
                 CullingVariant{.grid = shape, .lightLists = true}.toDefines()),
      sortCount_("pair sort counts", {{GL_COMPUTE_SHADER, "pair_sort.comp"}},
                 CullingVariant{.sortPass = SortPass::Count}.toDefines()),
      sortScatter_("pair sort scatter", {{GL_COMPUTE_SHADER, "pair_sort.comp"}},
                   CullingVariant{.sortPass = SortPass::Scatter}.toDefines()),
      sortScatterGather_("pair sort scatter with spheres", {{GL_COMPUTE_SHADER, "pair_sort.comp"}},
                         CullingVariant{.sortPass = SortPass::ScatterGather}.toDefines()),
      globalLightOrder_("global light order", {{GL_COMPUTE_SHADER, "global_light_order.comp"}},
                        CullingVariant{.globalLights = true}.toDefines()),
      statusBuffer_("cluster list status", sizeof(Status), nullptr, GL_DYNAMIC_STORAGE_BIT),
      globalLightCandidates_("global light candidates", bytesOf(kGlobalLightCapacity), nullptr, 0),
      globalLights_("global lights", bytesOf(kGlobalLightCapacity + 1), nullptr, 0),  // and the count
      globalLightRecords_("global light records", std::size_t{kGlobalLightCapacity} * sizeof(GpuLight), nullptr, 0),
      // A texture buffer holds 65,536 texels at least: the list always fits.
      globalLightTexels_("global light texels", GL_R32UI, globalLights_),
      globalLightRecordTexels_("global light record texels", GL_RGBA32F, globalLightRecords_)
{
}

void ClusterLists::plan(std::uint32_t pairs)
{
    // A quarter more than the frame had: lights that move a little need no rebuild.
    const std::uint64_t wanted = std::max<std::uint64_t>(kMinimumCapacity, std::uint64_t{pairs} + pairs / 4);
    const auto capacity = static_cast<std::uint32_t>(std::min<std::uint64_t>(wanted, 0xffffffffu / 2));
    // Shrinks only where the storage is over twice what is wanted: no churn from frame to frame.
    if (capacity_ >= capacity && capacity_ <= 2 * capacity)
        return;
    capacity_ = capacity;
    for (int i = 0; i < 2; ++i) {
        keys_[i] = gl::Buffer("cluster pair keys", bytesOf(capacity_), nullptr, 0);
        lights_[i] = gl::Buffer("cluster pair lights", bytesOf(capacity_), nullptr, 0);
    }
    spheres_ = gl::Buffer("cluster pair spheres", std::size_t{capacity_} * sizeof(float) * 4, nullptr, 0);
    const std::uint32_t chunks = (capacity_ + kSortChunk - 1) / kSortChunk;
    histogram_ = gl::Buffer("pair sort histogram", bytesOf(chunks << kSortRadixBits), nullptr, 0);
    // GL promises texture buffers of 65,536 texels only; desktop drivers have 2^27.
    texels_ = static_cast<std::int64_t>(capacity_) <= gl::queryInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
    for (int i = 0; i < 2; ++i)
        lightTexels_[i] =
            texels_ ? gl::BufferTexture("cluster list texels", GL_R32UI, lights_[i]) : gl::BufferTexture();
    sphereTexels_ =
        texels_ ? gl::BufferTexture("cluster list sphere texels", GL_RGBA32F, spheres_) : gl::BufferTexture();
}

const gl::Program& ClusterLists::pairProgram(bool wide, PairRun run, bool gridTexels) const
{
    return pairPrograms_.variant(
        {.grid = shape_, .gridTexels = gridTexels, .lightTiles = wide, .globalLights = true, .pairRun = run});
}

std::uint32_t ClusterLists::maskWordsFor(std::uint32_t lightCount, std::uint32_t clusterCount) const
{
    if (lightCount == 0 || lightCount > maskedListLights_)
        return 0;
    const std::uint32_t words = (lightCount + 31) / 32;
    return std::size_t{clusterCount} * bytesOf(words + summaryWordsOf(words)) <= kMaskedListBudgetBytes ? words : 0;
}

void ClusterLists::ensureMasks(std::uint32_t clusterCount, std::uint32_t words)
{
    if (words == 0) {
        // A frame past the masks' lights: their memory goes back (--stats counts what is held).
        masks_ = gl::Buffer();
        maskSummaries_ = gl::Buffer();
        return;
    }
    const std::size_t maskBytes = std::size_t{clusterCount} * bytesOf(words);
    const std::size_t summaryBytes = std::size_t{clusterCount} * bytesOf(summaryWordsOf(words));
    // Zero when made; cluster_mask_lists.comp leaves them zero after every frame, whatever
    // layout (words a cluster) the next frame has.
    if (!masks_ || masks_.size() < maskBytes) {
        masks_ = gl::Buffer("cluster list masks", maskBytes, nullptr, 0);
        masks_.clearToZero(maskBytes);
    }
    if (!maskSummaries_ || maskSummaries_.size() < summaryBytes) {
        maskSummaries_ = gl::Buffer("cluster list mask summaries", summaryBytes, nullptr, 0);
        maskSummaries_.clearToZero(summaryBytes);
    }
}

void ClusterLists::build(const GpuScene& scene, FramePasses& passes, const ClusterGrid& grid)
{
    const auto lightCount = static_cast<std::uint32_t>(scene.lightCount());
    sceneTexels_ = scene.indexedLightSource() == LightSource::TexelBuffer;
    lightMemoryBytes_ = scene.lightMemoryBytes();
    const std::uint32_t clusters = grid.clusterCount();
    if (capacity_ == 0)
        plan(clusters * kFirstPlanPairsPerCell);
    const auto tiles = static_cast<std::uint32_t>(grid.gridWidth() * grid.gridHeight());
    const std::uint32_t maskWords = maskWordsFor(lightCount, clusters);
    masked_ = maskWords > 0;
    ensure(clusterCounts_, "cluster list counts", clusters);
    ensure(clusterFirsts_, "cluster list firsts", clusters);
    ensure(longListTiles_, "cluster long list tiles", tiles);
    ensure(lightPairOffsets_, "light pair offsets", lightCount);
    ensure(lightPairCursors_, "light pair cursors", lightCount);
    ensure(wideLights_, "wide lights", lightCount);
    ensure(pairedLights_, "paired lights", lightCount);
    ensure(lightTileRecords_, "light tile records", 2 * lightCount);
    // The grid as texels where the lights are (the software rasteriser's choice,
    // RendererDesc::lightTexels) and the driver's texture buffers hold it.
    const bool gridTexels = sceneTexels_ && grid.hasTexels();
    const auto bindAll = [&] {
        grid.bind();
        if (gridTexels)
            grid.bindTexels();
        statusBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
        lightPairOffsets_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LIGHT_PAIR_OFFSETS_BUFFER_BINDING);
        lightPairCursors_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LIGHT_PAIR_CURSORS_BUFFER_BINDING);
        wideLights_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::WIDE_LIGHTS_BUFFER_BINDING);
        pairedLights_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::PAIRED_LIGHTS_BUFFER_BINDING);
        lightTileRecords_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LIGHT_TILE_RECORDS_BUFFER_BINDING);
        keys_[0].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::PAIR_KEYS_IN_BUFFER_BINDING);
        lights_[0].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_LIGHTS_BUFFER_BINDING);
        clusterCounts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_COUNTS_BUFFER_BINDING);
        clusterFirsts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_FIRSTS_BUFFER_BINDING);
        longListTiles_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LONG_TILES_BUFFER_BINDING);
        globalLightCandidates_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING);
        if (masked_) {
            masks_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIGHT_MASKS_BUFFER_BINDING);
            maskSummaries_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_MASK_SUMMARIES_BUFFER_BINDING);
        }
    };
    // The counting run's narrow lights in rows of workgroups (render/programs/WorkgroupRows.h);
    // the writing run's are indirect, as many as the counting run found pairs for, and the wide
    // lights' too, a workgroup each per band of rows (lib/light_tiles.glsl).
    ML_ASSERT(grid.gridWidth() >= 1 && grid.gridWidth() <= kTilesPerBand);
    const auto rowsPerBand = static_cast<std::uint32_t>(kTilesPerBand / grid.gridWidth());
    const auto bands = (static_cast<std::uint32_t>(grid.gridHeight()) + rowsPerBand - 1) / rowsPerBand;
    const Pass pairPass{.name = "cluster pairs",
                        .sampled = Resource::LightGrid,
                        .storage = Resource::LightGrid,
                        .writes = Resource::LightGrid};
    const Pass indirectPass{.name = "cluster pairs",
                            .sampled = Resource::LightGrid,
                            .storage = Resource::LightGrid,
                            .indirect = Resource::LightGrid,
                            .writes = Resource::LightGrid};
    const auto runPairs = [&](PairRun run) {
        const bool emit = run == PairRun::Write;
        passes.run(emit ? indirectPass : pairPass, [&] {
            bindAll();
            const gl::Program& narrow = pairProgram(false, run, gridTexels);
            narrow.set(locations::CLUSTER_PAIR_LIGHT_COUNT_LOCATION, lightCount);
            narrow.set(locations::CLUSTER_PAIR_CAPACITY_LOCATION, capacity_);
            if (!emit) {
                narrow.set(locations::CLUSTER_PAIR_GLOBAL_TILES_LOCATION,
                           globalLightTiles(globalLightGridFraction_, tiles));
                narrow.set(locations::CLUSTER_PAIR_GLOBAL_PLANNED_LOCATION, globalListPlanned_ ? 1u : 0u);
            }
            if (run == PairRun::Mask)
                narrow.set(locations::CLUSTER_MASK_WORDS_LOCATION, maskWords);
            narrow.use();
            if (emit) {
                statusBuffer_.bindAsDispatchIndirect();
                glDispatchComputeIndirect(static_cast<GLintptr>(offsetof(Status, pairedLightGroups)));
            } else {
                dispatchComputeInRows(groupsFor(lightCount));
            }
        });
        passes.run(indirectPass, [&] {
            bindAll();
            const gl::Program& wide = pairProgram(true, run, gridTexels);
            wide.set(locations::CLUSTER_PAIR_CAPACITY_LOCATION, capacity_);
            wide.set(locations::LIGHT_TILE_ROWS_PER_BAND_LOCATION, rowsPerBand);
            if (run == PairRun::Mask)
                wide.set(locations::CLUSTER_MASK_WORDS_LOCATION, maskWords);
            wide.use();
            statusBuffer_.bindAsDispatchIndirect();
            glDispatchComputeIndirect(static_cast<GLintptr>(offsetof(Status, wideLightGroups)));
        });
    };

    passes.run(listPass("cluster pairs"), [&] {
        Status reset;
        reset.wideLightGroups[1] = bands;
        statusBuffer_.update(0, sizeof(Status), &reset);
        if (!masked_) {  // the lights' slots: a masked frame's pairs have none
            lightPairOffsets_.clearToZero(bytesOf(std::max(lightCount, 1u)));
            lightPairCursors_.clearToZero(bytesOf(std::max(lightCount, 1u)));
        }
        clusterCounts_.clearToZero(bytesOf(clusters));
        ensureMasks(clusters, maskWords);
    });
    const auto pairsNeeded = std::pair{&statusBuffer_, static_cast<std::uint32_t>(offsetof(Status, pairsNeeded) / 4)};
    if (masked_) {
        // The counting run sets the narrow lights' bits; the wide lights' run after it.
        runPairs(PairRun::Mask);
    } else if (lightCount > 0) {
        runPairs(PairRun::Count);
        scan_.run(passes, "cluster pairs", lightPairOffsets_, lightCount, pairsNeeded);
        runPairs(PairRun::Write);
    }
    // Also without lights: it writes the list's length, which the lighting reads.
    if (globalListPlanned_)
        passes.run(listPass("cluster pairs"), [&] {
            bindAll();
            bindGlobalLights();
            globalLightOrder_.use();
            glDispatchCompute(groupsFor(kGlobalLightCapacity), 1, 1);
        });
    globalListOfBuild_ = globalListPlanned_;
    passes.run(listPass("cluster lists"), [&] {
        bindAll();
        longLists_.use();
        glDispatchCompute(groupsFor(tiles), 1, 1);
    });
    // The long-lists pass has read the counts; they become the firsts by a scan of a copy.
    passes.run({.name = "cluster lists",
                .storage = Resource::LightGrid,
                .transfers = Resource::LightGrid,
                .writes = Resource::LightGrid},
               [&] { clusterCounts_.copyTo(clusterFirsts_, bytesOf(clusters)); });
    // Where the pairs were bits, their total is the lists' (no scan of the lights' counts gave it).
    scan_.run(passes, "cluster lists", clusterFirsts_, clusters, masked_ ? std::optional(pairsNeeded) : std::nullopt);
    sorted_ = 0;
    if (masked_)
        listMasks(passes, clusters, maskWords);
    else if (lightCount > 0)
        sortPairs(passes, clusters);
    built_ = true;
}

void ClusterLists::listMasks(FramePasses& passes, std::uint32_t clusterCount, std::uint32_t words)
{
    passes.run(listPass("mask lists"), [&] {
        masks_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIGHT_MASKS_BUFFER_BINDING);
        maskSummaries_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_MASK_SUMMARIES_BUFFER_BINDING);
        clusterFirsts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_FIRSTS_BUFFER_BINDING);
        clusterCounts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_COUNTS_BUFFER_BINDING);
        lights_[0].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_LIGHTS_BUFFER_BINDING);
        spheres_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_SPHERES_BUFFER_BINDING);
        maskLists_.set(locations::CLUSTER_MASK_WORDS_LOCATION, words);
        maskLists_.set(locations::CLUSTER_MASK_CLUSTERS_LOCATION, clusterCount);
        maskLists_.set(locations::CLUSTER_PAIR_CAPACITY_LOCATION, capacity_);
        maskLists_.use();
        dispatchComputeInRows(groupsFor(clusterCount));
    });
}

void ClusterLists::sortPairs(FramePasses& passes, std::uint32_t clusterCount)
{
    const std::uint32_t chunks = (capacity_ + kSortChunk - 1) / kSortChunk;
    const int keyBits = std::max(1, static_cast<int>(std::bit_width(std::max(clusterCount, 2u) - 1)));
    for (int shift = 0; shift < keyBits; shift += kSortRadixBits) {
        const int from = sorted_;
        const int to = 1 - sorted_;
        const auto bindPairs = [&] {
            statusBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
            histogram_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SCAN_DATA_BUFFER_BINDING);
            keys_[from].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::PAIR_KEYS_IN_BUFFER_BINDING);
            lights_[from].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_LIGHTS_BUFFER_BINDING);
            keys_[to].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::PAIR_KEYS_OUT_BUFFER_BINDING);
            lights_[to].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::PAIR_LIGHTS_OUT_BUFFER_BINDING);
            spheres_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_SPHERES_BUFFER_BINDING);
        };
        const auto dispatch = [&](const gl::Program& program) {
            bindPairs();
            program.set(locations::PAIR_SORT_SHIFT_LOCATION, static_cast<unsigned>(shift));
            program.set(locations::PAIR_SORT_CHUNKS_LOCATION, chunks);
            program.set(locations::PAIR_SORT_CAPACITY_LOCATION, capacity_);
            program.use();
            glDispatchCompute(groupsFor(chunks), 1, 1);
        };
        passes.run(listPass("pair sort"), [&] { dispatch(sortCount_); });
        scan_.run(passes, "pair sort", histogram_, chunks << kSortRadixBits);
        const bool lastDigit = shift + kSortRadixBits >= keyBits;
        passes.run(listPass("pair sort"), [&] { dispatch(lastDigit ? sortScatterGather_ : sortScatter_); });
        sorted_ = to;
    }
}

void ClusterLists::bindGlobalLights() const
{
    globalLights_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHTS_BUFFER_BINDING);
    globalLightRecords_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHT_RECORDS_BUFFER_BINDING);
}

void ClusterLists::bind() const
{
    bindGlobalLights();
    statusBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
    clusterCounts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_COUNTS_BUFFER_BINDING);
    clusterFirsts_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_FIRSTS_BUFFER_BINDING);
    lights_[sorted_].bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_LIGHTS_BUFFER_BINDING);
    spheres_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_SPHERES_BUFFER_BINDING);
    if (readsTexels()) {
        lightTexels_[sorted_].bindUnit(bindings::CLUSTER_LIST_TEXELS_UNIT);
        sphereTexels_.bindUnit(bindings::CLUSTER_LIST_SPHERES_UNIT);
        globalLightTexels_.bindUnit(bindings::GLOBAL_LIGHT_TEXELS_UNIT);
        globalLightRecordTexels_.bindUnit(bindings::GLOBAL_LIGHT_RECORDS_UNIT);
    }
    longListTiles_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LONG_TILES_BUFFER_BINDING);
}

void ClusterLists::dispatchOverLongListTiles() const
{
    statusBuffer_.bindAsDispatchIndirect();
    glDispatchComputeIndirect(static_cast<GLintptr>(offsetof(Status, longTileGroups)));
}

void ClusterLists::frameIssued()
{
    if (!built_)
        return;
    built_ = false;
    // The lighting's atomics (listVisits) and the build's are shader writes, which the ring's
    // copy waits for.
    statusCopies_.push(statusBuffer_,
                       {.capacity = capacity_, .laterParts = laterParts_, .globalList = globalListOfBuild_});
}

bool ClusterLists::oldestFrameFitted()
{
    if (statusCopies_.pending() == 0)
        return true;
    const Plan built = statusCopies_.readOldest(status_);
    const std::uint32_t builtCapacity = built.capacity;
    const std::uint32_t builtLaterParts = built.laterParts;
    const bool builtWithGlobalList = built.globalList;

    const std::uint32_t candidates = status_.globalLightCandidates;
    const bool listHeldThem = candidates <= kGlobalLightCapacity;
    globalLightsOfFrame_ = builtWithGlobalList && listHeldThem ? candidates : 0;
    globalListPlanned_ = candidates > 0 && listHeldThem;
    // Against the plan the frame was built with: later frames may have been built with a
    // larger one since.
    const bool pairsFit = status_.pairsNeeded <= builtCapacity;
    const std::uint32_t partsNeeded =
        status_.longestList == 0 ? 0 : (status_.longestList - 1) / kClusterListPart;  // after the first
    const bool partsFit = partsNeeded <= builtLaterParts;
    laterParts_ = partsNeeded;
    plan(status_.pairsNeeded);
    if (pairsFit && partsFit)
        return true;
    ++rebuilds_;
    return false;
}

std::size_t ClusterLists::memoryBytes() const
{
    std::size_t bytes = scan_.memoryBytes() + statusBuffer_.size();
    for (const gl::Buffer* buffer :
         {&masks_, &maskSummaries_, &lightPairOffsets_, &lightPairCursors_, &wideLights_, &pairedLights_,
          &lightTileRecords_, &keys_[0], &keys_[1], &lights_[0], &lights_[1], &spheres_, &clusterCounts_,
          &clusterFirsts_, &longListTiles_, &histogram_, &globalLightCandidates_, &globalLights_, &globalLightRecords_})
        bytes += buffer->size();
    return bytes;
}

std::vector<TechniqueCounter> ClusterLists::counters(const ClusterGrid& grid) const
{
    return {{"clusters", static_cast<double>(grid.clusterCount())},
            {"cluster_pairs", static_cast<double>(status_.pairsNeeded)},
            {"longest_cluster_list", static_cast<double>(status_.longestList)},
            {"global_lights", static_cast<double>(globalLights())},
            {"cluster_list_visits", static_cast<double>(status_.listVisits)},
            {"cluster_rebuilds", static_cast<double>(rebuilds_)},
            {"cluster_lists_from_masks", masked_ ? 1.0 : 0.0},
            {"gpu_memory_bytes", static_cast<double>(lightMemoryBytes_ + memoryBytes() + grid.memoryBytes())}};
}

void buildListsOverSurfaces(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, ClusterGrid& grid,
                            ClusterLists& lists)
{
    targets.gbuffer.fill(passes);
    passes.run(ClusterGrid::fitPass(), [&] {
        grid.resize(targets.width, targets.height, 0);
        grid.fitToSurfaces();
    });
    lists.build(scene, passes, grid);
}

}  // namespace manylights
