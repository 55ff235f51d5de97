// Renders frames of one scene at one size with any technique and any view, and reads the
// result back. The CLI, the tests and the viewer all drive this one class.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gl/Program.h"
#include "render/DisplayPass.h"
#include "render/GpuScene.h"
#include "render/Image.h"
#include "render/PassProfiler.h"
#include "render/ShadowMaps.h"
#include "render/Ssao.h"
#include "render/Technique.h"
#include "render/TransparencyPass.h"
#include "render/Views.h"
#include "render/VolumeDrawer.h"

namespace manylights {

// Deterministic work of one frame (docs/cli.md --count-work).
struct WorkCounts {
    std::uint64_t lightEvaluations = 0;             // (pixel, light) pairs the technique evaluated on opaque surfaces
    std::uint64_t transparentLightEvaluations = 0;  // ... on transparent ones (render/TransparencyPass.h)
    std::uint64_t inRangePairs = 0;                 // (pixel, light) pairs with A·S > 0: the least possible
};

class Renderer {
public:
    // Throws manylights::Error when the size exceeds what the GL implementation supports, or a
    // material's texture cannot be loaded. Techniques rendered with it must have been made with
    // the same TechniqueOptions::gbufferLayout.
    Renderer(const Scene& scene, const std::vector<Light>& lights, int width, int height,
             GBufferLayout gbufferLayout = kDefaultGBufferLayout);

    // Rebuilds every size-dependent resource (the passes and programs stay).
    void resize(int width, int height);
    // Poses the animated scene at time t in seconds (GpuScene::setTime); 0 until called.
    void setTime(double t) { gpuScene_.setTime(t); }
    // Recomputes the camera matrices after the scene's camera changed (the viewer moves it).
    void refreshCamera() { gpuScene_.setViewport(width(), height()); }
    void setLightingTerms(const glm::vec3& terms) { gpuScene_.setLightingTerms(terms); }
    // --anisotropy: kAutoAnisotropy (the renderer's default) or 1 to kMaxRequestedAnisotropy.
    void setAnisotropy(int requested) { gpuScene_.setAnisotropy(requested); }
    float anisotropy() const { return gpuScene_.textures().anisotropy(); }
    // The lit image and the G-buffer of the last frame (the viewer shows the lit image).
    const FrameTargets& targets() const { return *targets_; }

    // With counting on, each frame also counts its work (lastWorkCounts). The technique must
    // have been made with TechniqueOptions::countWork as this says, and with this renderer's
    // G-buffer layout (renderFrame asserts both).
    void setCountWork(bool count) { countWork_ = count; }
    // in_range_pairs is counted per pixel over the lights that a per-tile cull keeps
    // (shaders/in_range.comp); with this on, over every light instead: the reference the
    // tests check the culled count against.
    void setInRangeBruteForce(bool bruteForce)
    {
        inRangeBruteForce_ = bruteForce;
        inRangeProgram_ = gl::Program();
    }

    // One frame: views Final, LightCount and Volumes run the technique (LightCount needs
    // counting on); the G-buffer views run the geometry pass and show that quantity (the
    // same for every technique). Waits for the GPU.
    FrameSample renderFrame(Technique& technique, ViewMode view);
    const WorkCounts& lastWorkCounts() const { return workCounts_; }

    // The last frame's colour as linear floats, rows top to bottom; for the LightCount view,
    // the light evaluations of each pixel in all three channels.
    Image readColour() const;
    // Which pixels of the last frame hold a surface.
    std::vector<bool> readCoverage() const;

    // The display pass (render/DisplayPass.h): once set, every frame of the Final and Volumes
    // views ends with it, timed as its own passes. `supersample` must divide the size; the
    // displayed picture is the size divided by it.
    void setDisplay(const DisplaySettings& settings, int supersample = 1);
    // The last frame's displayed picture (display-encoded, rows top to bottom; 8-bit values
    // as v / 255 after a display pass, the lit image itself where the settings are the
    // identity); needs setDisplay and a Final or Volumes frame.
    Image readDisplayed() const;
    // The log-average luminance of the last frame's surfaces (DisplayPass::logAverageLuminance),
    // for auto-exposure.
    float logAverageLuminance() { return displayPass_.logAverageLuminance(targets_->lit, targets_->depthStencil); }
    // The displayed picture as a framebuffer, for the viewer to blit; null before the first
    // displayed frame.
    const gl::Framebuffer* displayedFramebuffer() const;

    // Shadows (the viewer's switches and the --shadow-lights budget) and ambient occlusion
    // (on when the scene enables it; the viewer may change any setting).
    ShadowMaps& shadowMaps() { return shadowMaps_; }
    AmbientOcclusion& ambientOcclusion() { return ambientOcclusion_; }

    const GpuScene& gpuScene() const { return gpuScene_; }
    int width() const { return targets_->width; }
    int height() const { return targets_->height; }

private:
    GpuScene gpuScene_;
    GBufferLayout gbufferLayout_;
    std::unique_ptr<FrameTargets> targets_;
    void countWork();
    void drawVolumeOverlay();

    // The debug and counting programs are made on first use: most runs render the final image
    // only and need not compile them.
    gl::Program viewProgram_;
    gl::Program inRangeProgram_;                   // made on first use of work counting
    std::unique_ptr<VolumeDrawer> overlayDrawer_;  // made on first use of the volumes view
    gl::Program overlayProgram_;
    PassProfiler profiler_;
    ShadowMaps shadowMaps_;
    AmbientOcclusion ambientOcclusion_;
    std::unique_ptr<Ssao> ssao_;  // made on first use
    // One per set of technique options it has followed (made when the scene has transparent
    // objects): switching techniques keeps their programs. transparency_ is the last one run.
    std::vector<std::unique_ptr<TransparencyPass>> transparencyPasses_;
    TransparencyPass* transparency_ = nullptr;
    gl::Program shadowingViewProgram_;  // made on first use of the shadow and ssao views
    void prepareShadowing(ViewMode view);
    bool countWork_ = false;
    bool inRangeBruteForce_ = false;
    WorkCounts workCounts_;
    ViewMode lastView_ = ViewMode::Final;
    std::optional<DisplaySettings> display_;
    int supersample_ = 1;
    DisplayPass displayPass_;
    bool displayed_ = false;       // the last frame has a displayed picture
    bool displayPassRan_ = false;  // ... made by the display pass (not the identity)
};

}  // namespace manylights
