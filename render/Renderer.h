// Renders frames of one scene at one size with any technique and any view, and reads the
// result back. The CLI, the tests and the viewer all drive this one class.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "gl/Program.h"
#include "render/DefaultImageSize.h"
#include "render/Views.h"
#include "render/driver/DriverProfile.h"
#include "render/effects/DisplayPass.h"
#include "render/effects/ShadowMaps.h"
#include "render/effects/Ssao.h"
#include "render/effects/TransparencyPass.h"
#include "render/frame/PassProfiler.h"
#include "render/output/Image.h"
#include "render/scene/GpuScene.h"
#include "render/scene/TextureCache.h"
#include "render/shadows/ShadowPool.h"
#include "render/shadows/ShadowResolutionView.h"
#include "render/techniques/Technique.h"
#include "render/volumes/VolumeDrawer.h"

namespace manylights {

// Deterministic work of one frame (docs/cli.md --count-work).
struct WorkCounts {
    std::uint64_t lightEvaluations = 0;             // (pixel, light) pairs the technique evaluated on opaque surfaces
    std::uint64_t transparentLightEvaluations = 0;  // ... on transparent ones (render/effects/TransparencyPass.h)
    std::uint64_t inRangePairs = 0;                 // (pixel, light) pairs with A·S > 0: the least possible
};

// Everything a Renderer is made with, and the one way its settings change (Renderer::apply).
// Written with designated initialisers; a zero number means the default, so `{}` renders the
// contract's default image.
struct RendererDesc {
    int width = 0;   // 0: kDefaultImageWidth
    int height = 0;  // 0: kDefaultImageHeight
    GBufferLayout gbufferLayout = kDefaultGBufferLayout;
    // Each frame also counts its work (lastWorkCounts); techniques are then made in their
    // counting variants (TechniqueVariant::countWork), so their timings are not their own.
    bool countWork = false;
    // in_range_pairs counted over every light instead of the lights a per-tile cull keeps
    // (shaders/in_range.comp): the reference the tests check the culled count against.
    bool inRangeBruteForce = false;
    // --shadow-lights: how many local lights cast shadows, the ones ranked highest each frame
    // (kAllShadowLights: every light that does not opt out); above 0, techniques are made in
    // their variants that look the shadow pages up (TechniqueVariant::localShadows).
    int shadowLights = 0;
    // --shadow-pool-mib: the shadow-page pool's size, a multiple of kShadowPoolGrainMiB from
    // kMinShadowPoolMiB to kMaxShadowPoolMiB (scene/ShadowSelection.h); 0: kDefaultShadowPoolMiB.
    int shadowPoolMiB = 0;
    bool directionalShadows = true;         // the viewer's switch (ShadowMaps::setDirectionalShadows)
    bool rebuildShadowsEveryFrame = false;  // --rebuild-shadows
    // The scene's `ssao` settings when not set (the viewer edits them).
    // ({} on the optionals: GCC asks for it of members a designated initialiser leaves out.)
    std::optional<AmbientOcclusion> ambientOcclusion{};
    // --anisotropy: 0 (kAutoAnisotropy) or 1 to kMaxRequestedAnisotropy.
    int anisotropy = kAutoAnisotropy;
    // The scene's environment's intensity, rotation and background when not set (the viewer
    // edits them); nothing without an environment.
    std::optional<EnvironmentLook> environmentLook{};
    // The viewer's switches for the ambient, diffuse and specular terms (1 on, 0 off).
    glm::vec3 lightingTerms{1.0f, 1.0f, 1.0f};
    // The display pass (render/effects/DisplayPass.h): when set, every frame of the Final and Volumes
    // views ends with it, timed as its own passes. `supersample` (0: 1) must divide the size;
    // the displayed picture is the size divided by it.
    std::optional<DisplaySettings> display{};
    int supersample = 0;
    // Lighting passes read the lights through the light texels where the driver has them and
    // they are the faster source (render/programs/LightBatches.h, GpuScene::readsLightWindows); false:
    // through the uniform windows or the storage buffer, as on a driver without them (the
    // tests compare the sources).
    bool lightTexels = true;
    // The viewer's wireframe: the final view's lit-image passes draw their polygons as edges
    // (FramePasses::setLitImagePolygonMode; the viewer draws it with forward, whose are meshes).
    bool wireframe = false;
    // --driver-profile, --pass-timing and --lighting-stage: what is asked of the driver seam
    // (render/driver/DriverProfile.h). Resolved when the Renderer is made (driverChoices());
    // apply() keeps it.
    DriverOverrides driver{};
    // The culling's tuning, for measuring and testing (render/frame/TechniqueOptions.h): the
    // techniques are made for it, as for the other options.
    CullingTuning culling{};
    // Called between passes and every few milliseconds while the renderer waits for the GPU
    // (PassProfiler::setWaitHook): the viewer reads its input there. It must not issue GL
    // commands. Empty: none.
    std::function<void()> waitHook{};
};

class Renderer {
public:
    // Throws manylights::Error when the size exceeds what the GL implementation supports, or a
    // material's texture cannot be loaded.
    Renderer(const Scene& scene, const std::vector<Light>& lights, const RendererDesc& desc = {});

    // Changes the settings to `desc`: a new size or G-buffer layout rebuilds the size-dependent
    // targets (the passes and programs stay); the rest takes effect from the next frame.
    void apply(const RendererDesc& desc);
    const RendererDesc& desc() const { return desc_; }

    // The technique `name` (techniqueNames()) in the variant the settings ask for, made on
    // first use and kept: switching between techniques and back compiles nothing again.
    // Throws manylights::Error for an unknown name or a shader that does not compile.
    Technique& technique(std::string_view name);

    // Poses the animated scene at time t in seconds (GpuScene::setTime); 0 until called.
    void setTime(double t) { gpuScene_.setTime(t); }
    // The camera frames are rendered from; the scene's own until set.
    void setCamera(const Camera& camera) { gpuScene_.setCamera(camera); }
    // The anisotropy the textures got from desc().anisotropy.
    float anisotropy() const { return gpuScene_.textures().anisotropy(); }
    // desc().driver resolved on the context when the Renderer was made.
    const DriverChoices& driverChoices() const { return driver_; }
    // The lit image and the G-buffer of the last frame (the viewer shows the lit image).
    const FrameTargets& targets() const { return *targets_; }

    // One frame: views Final, LightCount and Volumes run the technique (LightCount needs
    // counting on); the G-buffer views run the geometry pass and show that quantity (the
    // same for every technique; ShadowResolution's is drawn by ShadowResolutionView). Waits for the GPU, and renders
    // the frame again where the technique's storage could not hold it (render/culling/ClusterLists.h).
    FrameSample renderFrame(Technique& technique, ViewMode view);
    FrameSample renderFrame(std::string_view techniqueName, ViewMode view)
    {
        return renderFrame(technique(techniqueName), view);
    }

    // Frames issued and not finished that queueFrame allows: as many as a double-buffered
    // swap chain, the GPU running one frame while the CPU issues the next.
    static constexpr std::size_t kFramesInFlight = 2;
    // One frame issued as an application's loop issues it: nothing waits for the GPU (under
    // PassTiming::Gpu and Frame), but for the oldest frame when kFramesInFlight are unfinished.
    // Its sample comes out of finishedFrames(). Not while counting work, whose counts are read
    // back at once.
    void queueFrame(Technique& technique, ViewMode view);
    struct FinishedFrame {
        FrameSample sample;
        // false: the technique's storage, planned from a frame before, could not hold this
        // frame's work, so its image lacks some light; the technique has planned anew (counted
        // as cluster_rebuilds), and frames issued from then on fit.
        bool fitted = true;
    };
    // The queued frames the GPU has finished, oldest first; with `wait`, every queued frame.
    std::vector<FinishedFrame> finishedFrames(bool wait);
    std::size_t framesInFlight() const { return inFlight_.size(); }
    // How the frames are timed (driverChoices().passTiming).
    PassTiming passTiming() const { return profiler_.timing(); }
    const WorkCounts& lastWorkCounts() const { return workCounts_; }

    // The last frame's colour as linear floats, rows top to bottom; for the LightCount view,
    // the light evaluations of each pixel in all three channels; for the ShadowResolution view,
    // the shadow texels per pixel (ShadowResolutionView::texelsPerPixel; 0 where none).
    Image readColour() const;
    // Which pixels of the last frame hold a surface.
    std::vector<bool> readCoverage() const;

    // The last frame's displayed picture (display-encoded, rows top to bottom; 8-bit values
    // as v / 255 after a display pass, the lit image itself where the settings are the
    // identity); needs desc().display and a Final or Volumes frame.
    Image readDisplayed() const;
    // The log-average luminance of the last frame's surfaces (DisplayPass::logAverageLuminance),
    // for auto-exposure.
    float logAverageLuminance() { return displayPass_.logAverageLuminance(targets_->lit, targets_->depthStencil); }
    // The displayed picture as a framebuffer, for the viewer to blit; null before the first
    // displayed frame.
    const gl::Framebuffer* displayedFramebuffer() const;

    // The directional light's shadow map and the local lights' shadow-page pool as the
    // settings made them (what they drew, which lights have faces).
    const ShadowMaps& shadowMaps() const { return shadowMaps_; }
    const ShadowPool& shadowPool() const { return shadowPool_; }
    // Renders every shadow map and page again in the next frame, as after a change to the scene.
    void invalidateShadowMaps()
    {
        shadowMaps_.invalidate();
        shadowPool_.invalidate();
    }
    // The ambient occlusion frames use: desc().ambientOcclusion, or the scene's.
    const AmbientOcclusion& ambientOcclusion() const
    {
        return desc_.ambientOcclusion ? *desc_.ambientOcclusion : sceneAmbientOcclusion_;
    }

    const GpuScene& gpuScene() const { return gpuScene_; }
    int width() const { return targets_->width; }
    int height() const { return targets_->height; }

private:
    // Issues one frame's commands (the profiler's frame ended, its sample to come).
    void issueFrame(Technique& technique, ViewMode view);
    // Moves the oldest frame in flight to finished_ once the GPU has run it (with `wait`, after
    // waiting for it); false where none is in flight or, without `wait`, it is not done.
    bool finishOldestFrame(bool wait);
    // What the settings ask of the techniques' shaders.
    TechniqueOptions techniqueOptions() const;
    // The targets for desc_'s size and layout, and what was made for the old layout dropped.
    void makeTargets();
    void prepareShadowing(ViewMode view, FramePasses& passes);
    // The transparency pass for techniques whose programs are made for `technique` (made on
    // first use).
    TransparencyPass& transparencyPassFor(const TechniqueVariant& technique);
    // The program of a G-buffer, shadow or ssao view (made on first use).
    const gl::Program& gbufferViewProgram(ViewMode view);
    void countWork();
    // The environment where no surface is (EnvironmentLight::showsBackground).
    void drawEnvironmentBackground(FramePasses& passes);
    // Each light's volume over the lit image: its edges, or with `cornersOnly` its corners.
    void drawVolumeOverlay(FramePasses& passes, bool cornersOnly);

    const DriverChoices driver_;  // before gpuScene_, which is made with it
    GpuScene gpuScene_;
    const AmbientOcclusion sceneAmbientOcclusion_;
    RendererDesc desc_;
    std::unique_ptr<FrameTargets> targets_;
    // Every technique variant made so far (technique()); the programs stay compiled.
    std::vector<std::unique_ptr<Technique>> techniques_;
    // One per technique variant it has followed (made when the scene has transparent objects):
    // switching techniques keeps their programs. transparency_ is the last one run.
    std::vector<std::unique_ptr<TransparencyPass>> transparencyPasses_;
    TransparencyPass* transparency_ = nullptr;
    PassProfiler profiler_;
    ShadowMaps shadowMaps_;
    ShadowPool shadowPool_;
    ShadowResolutionView shadowResolutionView_;  // its walk is made on first use
    DisplayPass displayPass_;

    // The debug and counting programs are made on first use: most runs render the final image
    // only and need not compile them. Those that read the G-buffer are made again after a
    // change of layout.
    gl::Program viewProgram_;
    gl::Program shadowingViewProgram_;  // the shadow and ssao views
    gl::Program inRangeProgram_;        // work counting
    std::unique_ptr<Ssao> ssao_;
    std::unique_ptr<VolumeDrawer> overlayDrawer_;  // the volumes view
    gl::Program overlayProgram_;
    gl::Program environmentBackgroundProgram_;

    // The frames issued and not yet finished, oldest first: the technique each ran, whose
    // storage check it is (null for the G-buffer views, which run none).
    std::deque<Technique*> inFlight_;
    std::vector<FinishedFrame> finished_;  // finished, not yet taken by finishedFrames
    WorkCounts workCounts_;
    ViewMode lastView_ = ViewMode::Final;
    bool displayed_ = false;       // the last frame has a displayed picture
    bool displayPassRan_ = false;  // ... made by the display pass (not the identity)
};

}  // namespace manylights
