#include "render/shadows/ShadowPool.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "core/Error.h"
#include "gl/CallTally.h"
#include "render/programs/Bindings.h"
#include "render/programs/Locations.h"
#include "render/shadows/ShadowPageLayout.h"
#include "scene/Falloff.h"
#include "scene/ShadowSelection.h"

namespace manylights {

using namespace shadowpages;

namespace {

constexpr std::uint32_t kNoLight = 0xffffffffu;  // writeTables: before the first light with faces
constexpr std::size_t kPageBytes = std::size_t{SHADOW_PAGE_TEXELS} * SHADOW_PAGE_TEXELS * sizeof(float);
constexpr int kRootTexels = PageAllocator::kRootPages * SHADOW_PAGE_TEXELS;
constexpr std::size_t kRootBytes = std::size_t{kRootTexels} * kRootTexels * sizeof(float);
static_assert(kRootBytes == std::size_t{kShadowPoolGrainMiB} << 20, "a root is the pool's grain");

// std430 layout of shaders/shadow_page.vert: FaceDraw.
struct GpuFaceDraw {
    glm::mat4 viewProjection;
    glm::vec4 toAtlas;
    glm::vec4 square;
};

bool sameLight(const GpuLight& a, const GpuLight& b)
{
    return a.positionRadius == b.positionRadius && a.intensityExponent == b.intensityExponent &&
           a.attenuation == b.attenuation && a.spotAxisCosCutoff == b.spotAxisCosCutoff;
}

// The far plane of a light's faces: its reach, or where the scene ends first (a little beyond,
// so nothing is clipped).
float faceFar(const GpuLight& light, const Bounds& sceneBounds)
{
    const glm::vec3 p(light.positionRadius);
    const glm::vec3 farthest = glm::max(glm::abs(sceneBounds.min - p), glm::abs(sceneBounds.max - p));
    return std::min(light.positionRadius.w, 1.01f * glm::length(farthest) + 1e-3f);
}

float brightest(const GpuLight& light)
{
    return std::max({light.intensityExponent.r, light.intensityExponent.g, light.intensityExponent.b});
}

}  // namespace

ShadowPool::ShadowPool() = default;
ShadowPool::~ShadowPool() = default;

void ShadowPool::configure(int lightCap, int poolMiB, bool rebuildEveryFrame)
{
    const int mib = poolMiB == 0 ? kDefaultShadowPoolMiB : poolMiB;
    ML_ASSERT(lightCap >= 0 && mib >= kMinShadowPoolMiB && mib <= kMaxShadowPoolMiB && mib % kShadowPoolGrainMiB == 0);
    if (lightCap != lightCap_ || mib != poolMiB_)
        markedFor_.reset();
    lightCap_ = lightCap;
    poolMiB_ = mib;
    rebuildEveryFrame_ = rebuildEveryFrame;
}

void ShadowPool::invalidate()
{
    markedFor_.reset();
    for (auto& [key, face] : faces_)
        face.drawn = false;
}

void ShadowPool::ensureAtlas()
{
    if (atlas_ && atlasMiB_ == poolMiB_)
        return;
    faces_.clear();
    tablesCurrent_ = false;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const int largest = std::min({maxSize, viewport[0], viewport[1]});
    const int roots = poolMiB_ / kShadowPoolGrainMiB;
    const int rootsAcross = std::clamp(largest / kRootTexels, 1, roots);
    allocator_ = std::make_unique<PageAllocator>(roots, rootsAcross);
    const int width = allocator_->pagesAcross() * SHADOW_PAGE_TEXELS;
    const int height = allocator_->pagesDown() * SHADOW_PAGE_TEXELS;
    if (height > largest)
        throw Error("the shadow pool of " + std::to_string(poolMiB_) + " MiB needs a " + std::to_string(width) + "x" +
                    std::to_string(height) + " depth atlas, larger than this driver's " + std::to_string(largest) +
                    " texels: use a smaller --shadow-pool-mib");
    atlas_ = gl::Texture2D("shadow page atlas", GL_DEPTH_COMPONENT32F, width, height);
    atlas_.setLinearFiltering();
    atlas_.compareDepth(GL_LEQUAL);
    atlas_.setWrap(GL_CLAMP_TO_EDGE);
    atlasFramebuffer_ = gl::Framebuffer("shadow page atlas", {}, &atlas_);
    atlasMiB_ = poolMiB_;
}

void ShadowPool::ensureMarking(const TechniqueOptions& options)
{
    // The marking walks the lists as the lighting does, without counting or looking pages up.
    TechniqueOptions wanted = options;
    wanted.shaders.countWork = false;
    wanted.shaders.localShadows = false;
    wanted.shaders.markShadowPages = true;
    // Its lists always sort their pairs (never bit masks, which the technique's lists use below
    // kMaskedListLights): one sequence of GL calls at every light count, so that the shadow
    // work's calls do not change with it (shadow_gl_calls).
    wanted.culling.maskedListLights = 0;
    if (marking_ && marking_->madeFor(wanted))
        return;
    marking_ = std::make_unique<SurfaceListWalk>("shadow pool's marking", wanted);
    transparentMarking_ = std::make_unique<TransparencyPass>(wanted.shaders);
    markedFor_.reset();
}

void ShadowPool::chooseLights(const GpuScene& scene)
{
    const std::size_t count = scene.lightCount();
    if (optedOut_.size() != count) {
        optedOut_.assign(count, false);
        anyOptedOut_ = false;
        for (std::size_t i = 0; i < count; ++i)
            if (!scene.light(i).castsShadows) {
                optedOut_[i] = true;
                anyOptedOut_ = true;
            }
    }
    chosen_.assign(count, lightCap_ == kAllShadowLights);
    if (lightCap_ == kAllShadowLights) {
        for (std::size_t i = 0; i < count; ++i)
            chosen_[i] = !optedOut_[i];
        return;
    }
    // The cap's lights: ranked by screen coverage × brightness; an opted-out light has no
    // brightness to the ranking, so it is never chosen.
    const std::vector<GpuLight>& lights = scene.packedLights();
    std::vector<ShadowCandidate> candidates;
    candidates.reserve(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
        candidates.push_back({glm::vec3(lights[i].positionRadius), lights[i].positionRadius.w,
                              optedOut_[i] ? 0.0f : brightest(lights[i])});
    for (std::size_t light : selectShadowLights(candidates, scene.frameUniforms().viewProjection, lightCap_))
        chosen_[light] = true;
}

std::vector<std::uint32_t> ShadowPool::mark(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    const std::size_t words = scene.lightCount() * SHADOW_CUBE_FACES;
    if (marksWords_ != words) {
        marksBuffer_ = gl::Buffer("shadow page marks", words * sizeof(std::uint32_t), nullptr);
        marksWords_ = words;
    }
    // Every light that casts no shadow starts with all its bits set, so the pass marks nothing
    // of it (it sets only bits that are clear).
    const bool all = std::find(chosen_.begin(), chosen_.end(), false) == chosen_.end();
    std::vector<std::uint32_t> initial;
    if (!all) {
        initial.assign(words, 0u);
        for (std::size_t light = 0; light < chosen_.size(); ++light)
            if (!chosen_[light])
                std::fill_n(initial.begin() + static_cast<std::ptrdiff_t>(light * SHADOW_CUBE_FACES), SHADOW_CUBE_FACES,
                            ~0u);
    }
    const Pass startPass{.name = "shadow marks", .storage = Resource::ShadowPages, .writes = Resource::ShadowPages};
    marking_->run(scene, targets, passes, Resource::ShadowPages, [&] {
        passes.run(startPass, [&] {
            if (all)
                marksBuffer_.clearToZero(words * sizeof(std::uint32_t));
            else
                marksBuffer_.update(0, words * sizeof(std::uint32_t), initial.data());
        });
        marksBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SHADOW_PAGE_MARKS_BUFFER_BINDING);
    });
    // The transparent surfaces' receivers, over the transparency pass's own grid (its colour
    // goes to the lit image, which the frame clears after the shadows: nothing of it is seen).
    // The readback's barrier, after the opaque marking's writes, covers its writes too.
    if (scene.hasTransparentObjects()) {
        marksBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SHADOW_PAGE_MARKS_BUFFER_BINDING);
        transparentMarking_->run(scene, targets, passes, false);
    }
    std::vector<std::uint32_t> marks(words);
    passes.run({.name = "shadow marks", .transfers = Resource::ShadowPages},
               [&] { marksBuffer_.read(0, words * sizeof(std::uint32_t), marks.data()); });
    ++markingsTotal_;
    frame_.marked = true;
    return marks;
}

void ShadowPool::place(const GpuScene& scene, const std::vector<std::uint32_t>& marks)
{
    const std::vector<GpuLight>& lights = scene.packedLights();
    struct Wanted {
        std::uint64_t key;
        double priority;
        std::uint32_t cells;
        ShadowFaceRegion region;
    };
    std::vector<Wanted> wanted;
    for (std::size_t light = 0; light < lights.size(); ++light) {
        if (!chosen_[light])
            continue;
        const int faceCount = shadowFaceCount(lights[light]);
        for (int face = 0; face < faceCount; ++face) {
            const std::uint32_t mark = marks[light * SHADOW_CUBE_FACES + static_cast<std::size_t>(face)];
            const int level = markedLevel(mark);
            if (level < 0)
                continue;
            const std::uint32_t cells = markedCells(mark);
            wanted.push_back({light * SHADOW_CUBE_FACES + static_cast<std::uint64_t>(face),
                              static_cast<double>(std::popcount(cells)) * brightest(lights[light]), cells,
                              shadowFaceRegion(cells, level)});
        }
    }

    // The page tables count in the pool: a word per light, its marks' words, a record per face
    // of every light with faces (ShadowPool::writeTables).
    std::size_t lightsWithFaces = 0;
    for (std::size_t i = 0; i < wanted.size(); ++i)
        if (i == 0 || wanted[i].key / SHADOW_CUBE_FACES != wanted[i - 1].key / SHADOW_CUBE_FACES)
            ++lightsWithFaces;
    tableBytes_ = lights.size() * sizeof(std::uint32_t) * (1 + SHADOW_CUBE_FACES) +
                  lightsWithFaces * SHADOW_CUBE_FACES * sizeof(GpuShadowFace);
    frame_.tablePages = (tableBytes_ + kPageBytes - 1) / kPageBytes;
    frame_.levelsLowered = 0;
    frame_.facesDropped = 0;
    const std::size_t capacity =
        allocator_->capacityPages() > frame_.tablePages ? allocator_->capacityPages() - frame_.tablePages : 0;
    std::size_t needed = 0;
    for (const Wanted& w : wanted)
        needed += shadowFacePages(w.region);

    // Short: the faces of least priority lose a level first, a level at a time.
    if (needed > capacity) {
        std::vector<std::size_t> order(wanted.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return wanted[a].priority < wanted[b].priority; });
        bool lowered = true;
        while (needed > capacity && lowered) {
            lowered = false;
            for (std::size_t i : order) {
                Wanted& w = wanted[i];
                if (w.region.level == 0)
                    continue;
                const ShadowFaceRegion lower = shadowFaceRegion(w.cells, w.region.level - 1);
                needed = needed - shadowFacePages(w.region) + shadowFacePages(lower);
                w.region = lower;
                ++frame_.levelsLowered;
                lowered = true;
                if (needed <= capacity)
                    break;
            }
        }
        // Not even a page a face: the least bright go without, said once per shortfall.
        if (needed > capacity) {
            const std::size_t neededPages = needed + frame_.tablePages;
            const std::size_t neededMiB = (neededPages * kPageBytes + (std::size_t{1} << 20) - 1) >> 20;
            const std::string line = "manylights: warning: the shadow pool of " + std::to_string(poolMiB_) +
                                     " MiB cannot give each of this frame's " + std::to_string(wanted.size()) +
                                     " shadow faces a page: it needs " + std::to_string(neededMiB) +
                                     " MiB (--shadow-pool-mib); the least bright lights' faces go unshadowed";
            if (line != lastShortage_) {
                std::fprintf(stderr, "%s\n", line.c_str());
                lastShortage_ = line;
            }
            std::vector<bool> dropped(wanted.size(), false);
            for (std::size_t i : order) {
                if (needed <= capacity)
                    break;
                needed -= shadowFacePages(wanted[i].region);
                dropped[i] = true;
                ++frame_.facesDropped;
            }
            std::vector<Wanted> kept;
            for (std::size_t i = 0; i < wanted.size(); ++i)
                if (!dropped[i])
                    kept.push_back(wanted[i]);
            wanted = std::move(kept);
        }
    }

    // Faces that keep their light and part keep their pages (and, drawn, their depth).
    std::map<std::uint64_t, Face> placed;
    const Bounds sceneBounds = scene.objectsWorldBounds();
    for (const Wanted& w : wanted) {
        const auto light = static_cast<std::uint32_t>(w.key / SHADOW_CUBE_FACES);
        const GpuLight& record = lights[light];
        auto old = faces_.find(w.key);
        if (old != faces_.end() && old->second.region == w.region && sameLight(old->second.drawnFor, record)) {
            placed.emplace(w.key, old->second);
            faces_.erase(old);
            continue;
        }
        if (old != faces_.end()) {
            releaseFace(old->second);
            faces_.erase(old);
        }
        Face face;
        face.light = light;
        face.face = static_cast<int>(w.key % SHADOW_CUBE_FACES);
        face.region = w.region;
        face.drawnFor = record;
        face.far = faceFar(record, sceneBounds);
        face.near = SHADOW_NEAR_FRACTION * face.far;
        face.frame = shadowFaceFrame(record, face.face);
        face.position = glm::vec3(record.positionRadius);
        placed.emplace(w.key, face);
    }
    for (auto& [key, face] : faces_)
        releaseFace(face);
    faces_ = std::move(placed);

    // New faces take pages, the largest squares first: the buddy allocator then packs them
    // without gaps. Where the pool's free pages are cut up by the faces that stayed, every face
    // is placed again (and drawn again).
    const auto placeAll = [&](bool everyFace) {
        std::vector<Face*> waiting;
        for (auto& [key, face] : faces_)
            if (everyFace || !face.fine)
                waiting.push_back(&face);
        std::stable_sort(waiting.begin(), waiting.end(),
                         [](const Face* a, const Face* b) { return a->region.pages > b->region.pages; });
        for (Face* face : waiting) {
            face->fine = allocator_->allocate(face->region.pages);
            if (!face->fine)
                return false;
            face->drawn = false;
        }
        for (Face* face : waiting)
            if (!face->region.whole) {
                face->coarse = allocator_->allocate(1);
                if (!face->coarse)
                    return false;
            }
        return true;
    };
    if (!placeAll(false)) {
        allocator_->clear();
        for (auto& [key, face] : faces_) {
            face.fine.reset();
            face.coarse.reset();
        }
        const bool fits = placeAll(true);
        ML_ASSERT(fits);  // squares of powers of two, largest first, fill roots without gaps
    }
    tablesCurrent_ = false;
}

void ShadowPool::releaseFace(Face& face)
{
    if (face.fine)
        allocator_->free(*face.fine);
    if (face.coarse)
        allocator_->free(*face.coarse);
    face.fine.reset();
    face.coarse.reset();
}

void ShadowPool::noteMovedCasters(const std::vector<DrawList::Caster>& casters)
{
    // A caster whose bounds changed redraws the faces its old or its new bounds meet.
    std::map<std::size_t, Bounds> now;
    std::vector<Bounds> moved;
    for (const DrawList::Caster& caster : casters) {
        now.emplace(caster.identity, caster.worldBounds);
        const auto before = casterBounds_.find(caster.identity);
        if (before == casterBounds_.end()) {
            moved.push_back(caster.worldBounds);
        } else if (before->second.min != caster.worldBounds.min || before->second.max != caster.worldBounds.max) {
            moved.push_back(before->second);
            moved.push_back(caster.worldBounds);
        }
    }
    casterBounds_ = std::move(now);
    if (moved.empty())
        return;
    for (auto& [key, face] : faces_) {
        if (!face.drawn)
            continue;
        for (const Bounds& bounds : moved)
            if (casterMayMeetFace(bounds, face.position, face.near, face.far, face.frame, face.region) ||
                (face.coarse &&
                 casterMayMeetFace(bounds, face.position, face.near, face.far, face.frame, coarseShadowFaceRegion()))) {
                face.drawn = false;
                break;
            }
    }
}

namespace {

// Two signed texel coordinates as one word of 16-bit halves biased by 32768
// (shaders/lib/shadow_pages.glsl: shadowTableHalves).
std::uint32_t halves(int x, int y)
{
    ML_ASSERT(x >= -32768 && x < 32768 && y >= -32768 && y < 32768);
    return static_cast<std::uint32_t>(x + 32768) | (static_cast<std::uint32_t>(y + 32768) << 16);
}

}  // namespace

void ShadowPool::writeTables(std::size_t lightCount)
{
    // Each light's first face record plus 1 (0: none): four lights a texel.
    facesBase_ = (lightCount + 3) / 4;
    std::vector<glm::uvec4> table(facesBase_, glm::uvec4(0u));
    std::uint32_t currentLight = kNoLight;
    std::size_t firstOfLight = 0;
    std::vector<GpuShadowFace> faces;
    for (const auto& [key, face] : faces_) {
        if (face.light != currentLight) {
            currentLight = face.light;
            firstOfLight = faces.size();
            table[face.light / 4][static_cast<int>(face.light % 4)] = static_cast<std::uint32_t>(firstOfLight + 1);
            faces.resize(faces.size() + static_cast<std::size_t>(shadowFaceCount(face.drawnFor)), GpuShadowFace(0u));
        }
        const int pageTexels = SHADOW_PAGE_TEXELS;
        const int guard = SHADOW_GUARD_TEXELS;
        std::uint32_t layout =
            static_cast<std::uint32_t>(face.region.level) | (static_cast<std::uint32_t>(face.region.pages) << 3);
        if (face.coarse) {
            ML_ASSERT(face.coarse->x < 1024 && face.coarse->y < 1024);
            layout |= 1u << 10 | static_cast<std::uint32_t>(face.coarse->x) << 11 |
                      static_cast<std::uint32_t>(face.coarse->y) << 21;
        }
        faces[firstOfLight + static_cast<std::size_t>(face.face)] = GpuShadowFace(
            halves(face.fine->x * pageTexels - face.region.x0, face.fine->y * pageTexels - face.region.y0),
            halves(face.region.x0 + guard, face.region.y0 + guard), layout, std::bit_cast<std::uint32_t>(face.far));
    }
    table.insert(table.end(), faces.begin(), faces.end());
    // Whole rows; the texture grows, and is rewritten whole, when the tables change.
    const std::size_t rows = std::max<std::size_t>((table.size() + SHADOW_TABLE_WIDTH - 1) / SHADOW_TABLE_WIDTH, 1);
    table.resize(rows * SHADOW_TABLE_WIDTH, glm::uvec4(0u));
    if (!tables_ || static_cast<std::size_t>(tables_.height()) != rows)
        tables_ = gl::Texture2D("shadow page tables", GL_RGBA32UI, SHADOW_TABLE_WIDTH, static_cast<int>(rows));
    tables_.write(GL_RGBA_INTEGER, GL_UNSIGNED_INT, table.data());
    tablesCurrent_ = true;
}

void ShadowPool::drawFaces(const GpuScene& scene, FramePasses& passes, const std::vector<DrawList::Caster>& casters)
{
    const auto width = static_cast<float>(atlas_.width());
    const auto height = static_cast<float>(atlas_.height());
    std::vector<GpuFaceDraw> draws;
    std::vector<glm::vec4> squares;
    // The parts to draw: each face's resident part, and its coarse page beside a part.
    struct Part {
        const Face* face;
        ShadowFaceRegion region;
    };
    std::vector<Part> parts;
    const auto addPart = [&](const Face& face, const ShadowFaceRegion& region, const PageBlock& block) {
        const auto resolution = static_cast<float>(shadowFaceResolution(region.level));
        const glm::vec2 atlasOrigin(static_cast<float>(block.x * SHADOW_PAGE_TEXELS),
                                    static_cast<float>(block.y * SHADOW_PAGE_TEXELS));
        const glm::vec2 offset = atlasOrigin - glm::vec2(static_cast<float>(region.x0), static_cast<float>(region.y0));
        const glm::vec2 size(width, height);
        // Face NDC x → face texel (x + 1) R / 2 → atlas texel + offset → atlas NDC.
        const glm::vec2 scale = glm::vec2(resolution) / size;
        const glm::vec2 shift = scale + 2.0f * offset / size - 1.0f;
        const auto texels = static_cast<float>(block.side * SHADOW_PAGE_TEXELS);
        const glm::vec2 low = 2.0f * atlasOrigin / size - 1.0f;
        const glm::vec2 high = 2.0f * (atlasOrigin + texels) / size - 1.0f;
        draws.push_back({shadowFaceViewProjection(face.position, face.frame, face.near, face.far),
                         glm::vec4(scale, shift), glm::vec4(low, high)});
        squares.emplace_back(low, high);
        parts.push_back({&face, region});
        frame_.pagesDrawn += static_cast<std::size_t>(block.side) * static_cast<std::size_t>(block.side);
    };
    for (auto& [key, face] : faces_) {
        if (face.drawn)
            continue;
        addPart(face, face.region, *face.fine);
        if (face.coarse)
            addPart(face, coarseShadowFaceRegion(), *face.coarse);
        face.drawn = true;
    }
    frame_.facesDrawn = parts.size();
    facesDrawnTotal_ += parts.size();
    if (parts.empty())
        return;

    // The (caster, part) pairs, batch by batch: a caster draws into the parts its bounds may meet.
    std::vector<std::vector<glm::uvec2>> pairsOfBatch(scene.batches().size());
    for (const DrawList::Caster& caster : casters)
        for (std::size_t p = 0; p < parts.size(); ++p) {
            const Face& face = *parts[p].face;
            if (casterMayMeetFace(caster.worldBounds, face.position, face.near, face.far, face.frame, parts[p].region))
                pairsOfBatch[caster.batch].emplace_back(static_cast<std::uint32_t>(caster.item),
                                                        static_cast<std::uint32_t>(p));
        }
    std::vector<glm::uvec2> pairs;
    std::vector<DrawList::CasterRun> runs;
    for (std::size_t batch = 0; batch < pairsOfBatch.size(); ++batch) {
        if (pairsOfBatch[batch].empty())
            continue;
        runs.push_back({batch, pairs.size(), pairsOfBatch[batch].size()});
        frame_.casterTriangles += pairsOfBatch[batch].size() * scene.batchTriangles(batch);
        pairs.insert(pairs.end(), pairsOfBatch[batch].begin(), pairsOfBatch[batch].end());
    }
    frame_.casterInstances = pairs.size();

    const PixelRect whole{0, 0, atlas_.width(), atlas_.height()};
    // Where most of the pool is drawn again (the first frame, --rebuild-shadows, everything
    // moved), one clear of the whole atlas costs less than a quad per part.
    const bool clearWhole = frame_.pagesDrawn * 2 > allocator_->capacityPages();
    passes.run({.name = "shadow clears",
                .framebuffer = &atlasFramebuffer_,
                .state = {.depthTest = DepthTest::Off, .maskColour = true, .viewport = whole}},
               [&] {
                   if (clearWhole) {
                       atlasFramebuffer_.clearDepth(1.0f);
                       return;
                   }
                   if (!clearProgram_)
                       clearProgram_ =
                           gl::Program("shadow page clear", {{GL_VERTEX_SHADER, "shadow_page_clear.vert"},
                                                             {GL_FRAGMENT_SHADER, "shadow_page_clear.frag"}});
                   gl::uploadGrowing(clearRectsBuffer_, "shadow page clears", std::span<const glm::vec4>(squares));
                   clearRectsBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SHADOW_CLEAR_RECTS_BUFFER_BINDING);
                   clearProgram_.use();
                   gl::counted(glDrawArraysInstanced, GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(squares.size()));
               });
    if (runs.empty())
        return;
    passes.run(
        {.name = "shadow pages",
         .framebuffer = &atlasFramebuffer_,
         .state = {.clampDepth = true, .maskColour = true, .viewport = whole}},
        [&] {
            gl::uploadGrowing(casterFacesBuffer_, "shadow caster faces", std::span<const glm::uvec2>(pairs));
            gl::uploadGrowing(faceDrawsBuffer_, "shadow face draws", std::span<const GpuFaceDraw>(draws));
            casterFacesBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SHADOW_CASTER_FACES_BUFFER_BINDING);
            faceDrawsBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SHADOW_FACE_DRAWS_BUFFER_BINDING);
            for (GLenum plane = GL_CLIP_DISTANCE0; plane <= GL_CLIP_DISTANCE3; ++plane)
                gl::counted(glEnable, plane);
            scene.drawCasterRuns(
                [&](MaterialVariant variant) -> const gl::Program& { return casterPrograms_.variant({variant}); }, runs,
                locations::SHADOW_CASTER_FACE_BASE_LOCATION);
            for (GLenum plane = GL_CLIP_DISTANCE0; plane <= GL_CLIP_DISTANCE3; ++plane)
                gl::counted(glDisable, plane);
        });
}

void ShadowPool::update(const GpuScene& scene, FrameTargets& targets, FramePasses& passes,
                        const TechniqueOptions& options)
{
    // What the last placement found stays until the next; the rest is this frame's.
    frame_ = {
        .tablePages = frame_.tablePages, .levelsLowered = frame_.levelsLowered, .facesDropped = frame_.facesDropped};
    const std::uint64_t callsBefore = gl::callTally();
    if (lightCap_ == 0 || scene.lightCount() == 0) {
        if (!faces_.empty()) {
            for (auto& [key, face] : faces_)
                releaseFace(face);
            faces_.clear();
            tablesCurrent_ = false;
        }
        markedFor_.reset();
        return;
    }
    ensureAtlas();
    ensureMarking(options);
    const FrameUniforms& uniforms = scene.frameUniforms();
    const MarkInputs inputs{.viewProjection = uniforms.viewProjection,
                            .width = targets.width,
                            .height = targets.height,
                            .transformsVersion = scene.transformsVersion(),
                            .lightTime = scene.hasAnimatedLights() ? scene.time() : 0.0,
                            .lightCap = lightCap_,
                            .gbufferLayout = options.shaders.gbufferLayout,
                            .lightCount = scene.lightCount()};
    const std::vector<DrawList::Caster> casters = scene.casters();
    if (rebuildEveryFrame_)
        invalidate();
    if (!markedFor_ || *markedFor_ != inputs) {
        chooseLights(scene);
        place(scene, mark(scene, targets, passes));
        markedFor_ = inputs;
    }
    noteMovedCasters(casters);
    if (!tablesCurrent_)
        writeTables(scene.lightCount());
    const std::uint64_t callsBeforeDrawing = gl::callTally();
    drawFaces(scene, passes, casters);
    frame_.glCallsDrawing = gl::callTally() - callsBeforeDrawing;
    frame_.faces = faces_.size();
    frame_.shadowedLights = shadowedLights().size();
    for (const auto& [key, face] : faces_)
        frame_.pagesUsed += shadowFacePages(face.region);
    frame_.glCalls = gl::callTally() - callsBefore;
}

void ShadowPool::bind() const
{
    if (!tablesCurrent_)
        return;
    tables_.bindUnit(bindings::SHADOW_TABLES_UNIT);
    atlas_.bindUnit(bindings::SHADOW_ATLAS_UNIT);
}

glm::vec4 ShadowPool::lookupParams() const
{
    if (!tablesCurrent_ || faces_.empty())
        return glm::vec4(0.0f);
    return glm::vec4(1.0f, 1.0f / static_cast<float>(atlas_.width()), 1.0f / static_cast<float>(atlas_.height()),
                     static_cast<float>(facesBase_));
}

std::vector<std::size_t> ShadowPool::shadowedLights() const
{
    std::vector<std::size_t> lights;
    for (const auto& [key, face] : faces_)
        if (lights.empty() || lights.back() != face.light)
            lights.push_back(face.light);
    return lights;
}

std::vector<TechniqueCounter> ShadowPool::counters() const
{
    const auto number = [](auto value) { return static_cast<double>(value); };
    return {{"shadow_pool_bytes", number(allocator_ ? allocator_->capacityPages() * kPageBytes : 0)},
            {"shadow_pages_capacity", number(allocator_ ? allocator_->capacityPages() : 0)},
            {"shadow_pages_used", number(frame_.pagesUsed)},
            {"shadow_table_pages", number(frame_.tablePages)},
            {"shadow_faces", number(frame_.faces)},
            {"shadow_lights_with_faces", number(frame_.shadowedLights)},
            {"shadow_faces_drawn", number(frame_.facesDrawn)},
            {"shadow_pages_drawn", number(frame_.pagesDrawn)},
            {"shadow_caster_instances", number(frame_.casterInstances)},
            {"shadow_caster_triangles", number(frame_.casterTriangles)},
            {"shadow_levels_lowered", number(frame_.levelsLowered)},
            {"shadow_faces_dropped", number(frame_.facesDropped)},
            {"shadow_marked", frame_.marked ? 1.0 : 0.0},
            {"shadow_gl_calls", number(frame_.glCalls)},
            {"shadow_gl_calls_drawing", number(frame_.glCallsDrawing)}};
}

}  // namespace manylights
