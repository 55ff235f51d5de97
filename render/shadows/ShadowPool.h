// Every local light may cast a shadow (issue 47, docs/shadows.md): the shadow-page pool. Each
// shadowed light's faces (one for a spot light of cutoff up to 75 degrees, six for a point
// light or a wider spot: render/shadows/ShadowFaces.h) are drawn into pages of one depth atlas,
// and only the parts its visible receivers need, at the resolution they need.
//
// A frame's pool, before the technique renders:
// 1. Marking (only when the camera, the lights, the scene or the choice of lights changed):
//    one pass that does not depend on the technique marks, for every (visible pixel, shadowed
//    light) pair the lighting will shade, the cell of the light's face the pixel falls in and
//    the level whose texel is about the pixel's size (shaders/lib/shadow_pages.glsl). It is the
//    clustered lists' walk (render/techniques/ListLighting.h, built with SHADOW_PAGE_MARKING)
//    over the G-buffer, so it tests each pair exactly as the lighting does, and every
//    technique then reads the same pages; the transparent surfaces' receivers are marked the
//    same way by the transparency pass built to mark. The marks are read back.
// 2. Placing: each marked face gets the smallest square of pages around its marked cells at
//    its level (and the whole face at level 0, one page, beside a part), in priority order
//    (marked cells × brightest channel) lowered a level at a time while the pool is short. The
//    page tables (a word per light, a record per face) are counted in the pool. A face keeps
//    its pages (render/shadows/PageAllocator.h) while its light, level and part stay.
// 3. Drawing: the faces placed anew, whose light changed, or that a moved caster's old or new
//    bounds meet are cleared (one instanced draw) and drawn (one instanced draw per batch of
//    the scene's items, an instance per (caster, face part) pair the CPU keeps: the casters
//    whose bounds meet the part's frustum inside the light's sphere). The GL calls do not
//    grow with the light count.
// The lighting then looks a light's page up with one bilinear comparison tap, no loop.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/effects/TransparencyPass.h"
#include "render/frame/FramePasses.h"
#include "render/frame/FrameTargets.h"
#include "render/frame/TechniqueOptions.h"
#include "render/programs/ProgramVariants.h"
#include "render/scene/GpuScene.h"
#include "render/shadows/PageAllocator.h"
#include "render/shadows/ShadowFaces.h"
#include "render/shadows/SurfaceListWalk.h"

namespace manylights {

// A face's record in the page tables (shaders/lib/shadow_pages.glsl: shadowTables), one
// RGBA32UI texel.
using GpuShadowFace = glm::uvec4;
static_assert(sizeof(GpuShadowFace) == 16);

// What the pool did in its last update (--stats: ShadowPool::counters).
struct ShadowPoolFrame {
    bool marked = false;             // the marking pass ran
    std::size_t shadowedLights = 0;  // lights with at least one face
    std::size_t faces = 0;           // faces with pages
    std::size_t pagesUsed = 0;       // pages held by faces
    std::size_t tablePages = 0;      // pages' worth of the pool the page tables take
    std::size_t facesDrawn = 0;      // faces (parts and coarse pages) drawn this frame
    std::size_t pagesDrawn = 0;
    std::size_t casterInstances = 0;   // (caster, face part) pairs drawn
    std::size_t casterTriangles = 0;   // the triangles they drew
    std::size_t levelsLowered = 0;     // levels the pool's shortage took from faces
    std::size_t facesDropped = 0;      // faces left without pages: the pool cannot hold even one each
    std::uint64_t glCalls = 0;         // GL calls of the update (gl/CallTally.h)
    std::uint64_t glCallsDrawing = 0;  // of them, the clears' and the casters' (drawFaces)
};

class ShadowPool {
public:
    ShadowPool();
    ~ShadowPool();
    ShadowPool(const ShadowPool&) = delete;
    ShadowPool& operator=(const ShadowPool&) = delete;

    // RendererDesc's settings: the lights that cast shadows (--shadow-lights: a cap, or
    // kAllShadowLights), the pool's size (--shadow-pool-mib, 0: the default) and whether every
    // face is drawn every frame (--rebuild-shadows).
    void configure(int lightCap, int poolMiB, bool rebuildEveryFrame);
    int poolMiB() const { return poolMiB_; }

    // The frame's pages, before the technique renders (see above). `options`: the renderer's
    // technique options, whose G-buffer layout and culling tuning the marking is built for.
    void update(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, const TechniqueOptions& options);
    // Binds the page tables and the atlas for the lighting programs.
    void bind() const;
    // The Shadowing block's localShadowParams (shaders/lib/shadows.glsl): x 1 where some
    // light has faces; y, z: 1 / the atlas' width and height; w: the tables' first face texel.
    glm::vec4 lookupParams() const;
    // Forgets every drawn page: the next update marks and draws them all.
    void invalidate();

    const ShadowPoolFrame& lastFrame() const { return frame_; }
    // Faces drawn since construction: deterministic, so tests can check that a still frame draws none.
    std::uint64_t facesDrawnTotal() const { return facesDrawnTotal_; }
    // Marking passes run since construction.
    std::uint64_t markingsTotal() const { return markingsTotal_; }
    // The lights with faces in the last update, in order.
    std::vector<std::size_t> shadowedLights() const;
    // A face with pages in the last update, for tests that bound what a lookup may read: its
    // light (an index into the scene's lights as the renderer orders them), its face (0 for a
    // spot's one, 0-5 for a cube's) and its resident part (whose level sets the texel size;
    // outside a part that is not the whole face, the coarse page at level 0 is read).
    struct ResidentFace {
        std::size_t light = 0;
        int face = 0;
        ShadowFaceRegion region;
    };
    std::vector<ResidentFace> residentFaces() const
    {
        std::vector<ResidentFace> resident;
        resident.reserve(faces_.size());
        for (const auto& [key, face] : faces_)
            resident.push_back({face.light, face.face, face.region});
        return resident;
    }
    // The --stats counters of the last update: shadow_pool_bytes, shadow_pages_capacity,
    // shadow_pages_used, shadow_faces, shadow_lights_with_faces, shadow_faces_drawn,
    // shadow_pages_drawn, shadow_caster_instances, shadow_caster_triangles, shadow_levels_lowered,
    // shadow_faces_dropped, shadow_marked, shadow_gl_calls and shadow_gl_calls_drawing.
    std::vector<TechniqueCounter> counters() const;

private:
    // A face with pages: what it was placed and drawn for.
    struct Face {
        std::uint32_t light = 0;
        int face = 0;
        ShadowFaceRegion region;
        std::optional<PageBlock> fine;
        std::optional<PageBlock> coarse;  // beside a part: the whole face at level 0
        GpuLight drawnFor{};
        bool drawn = false;
        float near = 0.0f;
        float far = 0.0f;
        ShadowFaceFrame frame;
        glm::vec3 position{0.0f};
    };
    // What a marking was made for: none of it changed, the marks would be the same.
    struct MarkInputs {
        glm::mat4 viewProjection{0.0f};
        int width = 0;
        int height = 0;
        std::uint64_t transformsVersion = 0;
        double lightTime = 0.0;  // the scene's time where lights move, else 0
        int lightCap = 0;
        GBufferLayout gbufferLayout = kDefaultGBufferLayout;
        std::size_t lightCount = 0;
        friend bool operator==(const MarkInputs&, const MarkInputs&) = default;
    };

    void ensureAtlas();
    void ensureMarking(const TechniqueOptions& options);
    void chooseLights(const GpuScene& scene);
    std::vector<std::uint32_t> mark(const GpuScene& scene, FrameTargets& targets, FramePasses& passes);
    void place(const GpuScene& scene, const std::vector<std::uint32_t>& marks);
    void noteMovedCasters(const std::vector<DrawList::Caster>& casters);
    void writeTables(std::size_t lightCount);
    void drawFaces(const GpuScene& scene, FramePasses& passes, const std::vector<DrawList::Caster>& casters);
    void releaseFace(Face& face);

    int lightCap_ = 0;
    int poolMiB_ = 0;
    bool rebuildEveryFrame_ = false;

    // The atlas: a grid of the allocator's roots, each 1024² texels of 32-bit depth.
    std::unique_ptr<PageAllocator> allocator_;
    gl::Texture2D atlas_;
    gl::Framebuffer atlasFramebuffer_;
    int atlasMiB_ = 0;  // the pool size the atlas was made for

    // The marking: its own grid and lists over the G-buffer, and the walk built to mark.
    std::unique_ptr<SurfaceListWalk> marking_;
    // The transparent surfaces' receivers: the transparency pass over its own grid of the
    // transparent objects' depths, built to mark (every technique's transparency pass then
    // reads the same pages).
    std::unique_ptr<TransparencyPass> transparentMarking_;
    gl::Buffer marksBuffer_;
    std::size_t marksWords_ = 0;
    std::optional<MarkInputs> markedFor_;

    // Which lights cast shadows: all those that do not opt out, or the cap's chosen ones.
    std::vector<bool> optedOut_;
    bool anyOptedOut_ = false;
    std::vector<bool> chosen_;

    std::map<std::uint64_t, Face> faces_;         // by light · 6 + face: in the lights' order
    std::map<std::size_t, Bounds> casterBounds_;  // by caster identity: where each was drawn last
    bool tablesCurrent_ = false;
    gl::Texture2D tables_;
    std::size_t facesBase_ = 0;  // the tables' first face texel
    std::size_t tableBytes_ = 0;
    gl::Buffer casterFacesBuffer_;
    gl::Buffer faceDrawsBuffer_;
    gl::Buffer clearRectsBuffer_;
    gl::Program clearProgram_;
    ProgramVariants<DepthOnlyVariant> casterPrograms_{
        "shadow page casters", {{GL_VERTEX_SHADER, "shadow_page.vert"}, {GL_FRAGMENT_SHADER, "shadow_depth.frag"}}};
    std::string lastShortage_;  // the pool-short line printed last, so it is printed once

    ShadowPoolFrame frame_;
    std::uint64_t facesDrawnTotal_ = 0;
    std::uint64_t markingsTotal_ = 0;
};

}  // namespace manylights
