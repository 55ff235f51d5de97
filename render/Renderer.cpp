#include "render/Renderer.h"
#include "render/Techniques.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/Error.h"
#include "gl/Driver.h"
#include "render/frame/ScreenPasses.h"
#include "render/programs/LightBatches.h"

namespace manylights {

namespace {

void checkSize(int width, int height)
{
    const int maxTexture = gl::queryInteger(GL_MAX_TEXTURE_SIZE);
    const int maxWidth = std::min(maxTexture, gl::queryInteger(GL_MAX_FRAMEBUFFER_WIDTH));
    const int maxHeight = std::min(maxTexture, gl::queryInteger(GL_MAX_FRAMEBUFFER_HEIGHT));
    if (width < 1 || height < 1 || width > maxWidth || height > maxHeight)
        throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside what this OpenGL implementation supports (1x1 to " + std::to_string(maxWidth) + "x" +
                    std::to_string(maxHeight) + ")");
}

// The desc with its zeros replaced by what they stand for.
RendererDesc withDefaultsFilledIn(RendererDesc desc)
{
    desc.width = desc.width == 0 ? kDefaultImageWidth : desc.width;
    desc.height = desc.height == 0 ? kDefaultImageHeight : desc.height;
    desc.supersample = std::max(desc.supersample, 1);
    return desc;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const std::vector<Light>& lights, const RendererDesc& desc)
    : driver_(resolveDriverChoices(desc.driver)),
      gpuScene_(scene, lights, driver_),
      sceneAmbientOcclusion_(scene.ssao),
      profiler_(driver_.passTiming)
{
    apply(desc);
}

void Renderer::apply(const RendererDesc& requested)
{
    RendererDesc desc = withDefaultsFilledIn(requested);
    // The driver's choices are made once, with the scene's programs and textures.
    if (targets_)
        desc.driver = desc_.driver;
    checkSize(desc.width, desc.height);
    ML_ASSERT(desc.width % desc.supersample == 0 && desc.height % desc.supersample == 0);
    const bool first = targets_ == nullptr;
    const RendererDesc old = std::exchange(desc_, desc);
    if (first || desc.width != old.width || desc.height != old.height || desc.gbufferLayout != old.gbufferLayout)
        makeTargets();
    if (desc.gbufferLayout != old.gbufferLayout || desc.inRangeBruteForce != old.inRangeBruteForce)
        inRangeProgram_ = gl::Program();
    if (first || desc.anisotropy != old.anisotropy)
        gpuScene_.setAnisotropy(desc.anisotropy);
    if (first || desc.lightingTerms != old.lightingTerms)
        gpuScene_.setLightingTerms(desc.lightingTerms);
    if (first || desc.lightTexels != old.lightTexels)
        gpuScene_.setLightTexels(desc.lightTexels);
    if (const auto& scene = gpuScene_.scene().environment;
        scene && (first || desc.environmentLook != old.environmentLook))
        gpuScene_.setEnvironmentLook(desc.environmentLook.value_or(scene->look));
    profiler_.setWaitHook(desc.waitHook);
    shadowPool_.configure(desc.shadowLights, desc.shadowPoolMiB, desc.rebuildShadowsEveryFrame);
    shadowMaps_.setDirectionalShadows(desc.directionalShadows);
    shadowMaps_.setRebuildEveryFrame(desc.rebuildShadowsEveryFrame);
}

void Renderer::makeTargets()
{
    const bool newLayout = targets_ && targets_->gbuffer.layout() != desc_.gbufferLayout;
    targets_.reset();  // free the old targets before allocating the new ones
    targets_ = std::make_unique<FrameTargets>(desc_.width, desc_.height, desc_.gbufferLayout);
    gpuScene_.setViewport(desc_.width, desc_.height);
    if (newLayout) {
        viewProgram_ = gl::Program();
        shadowingViewProgram_ = gl::Program();
        ssao_.reset();
    }
}

TechniqueOptions Renderer::techniqueOptions() const
{
    return {.shaders = {.countWork = desc_.countWork,
                        .gbufferLayout = desc_.gbufferLayout,
                        .localShadows = desc_.shadowLights > 0},
            .lightingStage = driver_.lightingStage,
            .culling = desc_.culling};
}

Technique& Renderer::technique(std::string_view name)
{
    const TechniqueOptions options = techniqueOptions();
    const auto made = std::find_if(techniques_.begin(), techniques_.end(), [&](const auto& technique) {
        return technique->name() == name && technique->options() == options;
    });
    if (made != techniques_.end())
        return **made;
    std::unique_ptr<Technique> technique = makeTechnique(name, options);
    if (!technique)
        throw Error("unknown technique '" + std::string(name) + "'");
    techniques_.push_back(std::move(technique));
    return *techniques_.back();
}

FrameSample Renderer::renderFrame(Technique& technique, ViewMode view)
{
    // The frames queued before are finished first; their samples stay for finishedFrames.
    while (finishOldestFrame(true)) {
    }
    // A technique whose storage, planned from the frame before, was too small for this one has
    // planned anew, and the frame is rendered again (render/culling/ClusterLists.h). Twice at most: a
    // frame whose lists overflowed their storage may have hidden how long the longest is.
    constexpr int kAttempts = 3;
    for (int attempt = 1;; ++attempt) {
        issueFrame(technique, view);
        finishOldestFrame(true);
        const FinishedFrame frame = std::move(finished_.back());
        finished_.pop_back();
        if (desc_.countWork)
            countWork();
        if (frame.fitted)
            return frame.sample;
        if (attempt == kAttempts)
            throw Error("the " + std::string(technique.name()) + " technique's storage cannot hold this frame's work");
    }
}

void Renderer::queueFrame(Technique& technique, ViewMode view)
{
    ML_ASSERT(!desc_.countWork);
    while (inFlight_.size() >= kFramesInFlight)
        finishOldestFrame(true);
    issueFrame(technique, view);
}

bool Renderer::finishOldestFrame(bool wait)
{
    if (inFlight_.empty())
        return false;
    std::optional<FrameSample> sample = profiler_.takeOldestFrame(wait);
    if (!sample)
        return false;
    Technique* technique = inFlight_.front();
    inFlight_.pop_front();
    // The GPU has run the frame (its last timestamp is there), so the status it copied is too.
    const bool fitted = technique ? technique->oldestFrameFitted() : true;
    finished_.push_back({std::move(*sample), fitted});
    return true;
}

std::vector<Renderer::FinishedFrame> Renderer::finishedFrames(bool wait)
{
    while (finishOldestFrame(wait)) {
    }
    return std::exchange(finished_, {});
}

void Renderer::issueFrame(Technique& technique, ViewMode view)
{
    ML_ASSERT(desc_.countWork || view != ViewMode::LightCount);
    // The technique's shaders read this renderer's G-buffer and, when counting, write the
    // counting images: they must have been made for both (technique() makes them so).
    ML_ASSERT(technique.options() == techniqueOptions());
    lastView_ = view;
    if (desc_.countWork) {
        targets_->lightEvaluations.clearToZero();
        targets_->lightEvaluations.bindImage(bindings::LIGHT_EVALUATIONS_IMAGE_UNIT, GL_READ_WRITE);
    }
    profiler_.beginFrame();
    targets_->gbuffer.invalidate();
    FramePasses passes(gpuScene_, *targets_, profiler_);
    if (gpuScene_.lightPosePending())
        passes.run({.name = "pose lights"}, [&] { gpuScene_.applyLightPose(); });
    if (desc_.wireframe && view == ViewMode::Final)
        passes.setLitImagePolygonMode(PolygonMode::Lines);
    prepareShadowing(view, passes);
    if (!isGBufferView(view)) {
        targets_->litFramebuffer.clearColour(0, &gpuScene_.frameUniforms().background.x);
        technique.render(gpuScene_, *targets_, passes);
        if (gpuScene_.environment().showsBackground())
            drawEnvironmentBackground(passes);
        if (gpuScene_.hasTransparentObjects())
            transparencyPassFor(technique.options().shaders).run(gpuScene_, *targets_, passes, technique.isReference());
        if (view == ViewMode::Volumes || view == ViewMode::VolumeCorners)
            drawVolumeOverlay(passes, view == ViewMode::VolumeCorners);
    } else {
        targets_->gbuffer.fill(passes);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        targets_->litFramebuffer.clearColour(0, black);
        if (view == ViewMode::ShadowResolution) {
            shadowResolutionView_.draw(gpuScene_, *targets_, passes, techniqueOptions());
        } else {
            const gl::Program& program = gbufferViewProgram(view);
            passes.run(
                {.name = "view", .target = Resource::LitImage, .state = kCoveredPixels, .sampled = Resource::GBuffer},
                [&] {
                    program.set(0, static_cast<int>(view));
                    drawCoveredPixels(program);
                });
        }
    }
    displayed_ = desc_.display && showsFinalImage(view);
    // The identity needs no pass: the lit image is then the picture (and a PNG of it is
    // round(255 · clamp(colour, 0, 1)) exactly, as the contract's default look).
    displayPassRan_ = displayed_ && (!desc_.display->isIdentity() || desc_.supersample > 1);
    if (displayPassRan_)
        displayPass_.run(passes, *desc_.display, desc_.supersample);
    passes.finish();
    const bool ranTechnique = !isGBufferView(view);
    if (ranTechnique)
        technique.frameIssued();
    profiler_.endFrameQueued();
    inFlight_.push_back(ranTechnique ? &technique : nullptr);
}

TransparencyPass& Renderer::transparencyPassFor(const TechniqueVariant& technique)
{
    const auto made = std::find_if(transparencyPasses_.begin(), transparencyPasses_.end(),
                                   [&](const auto& pass) { return pass->technique() == technique; });
    if (made != transparencyPasses_.end()) {
        transparency_ = made->get();
    } else {
        transparencyPasses_.push_back(std::make_unique<TransparencyPass>(technique));
        transparency_ = transparencyPasses_.back().get();
    }
    return *transparency_;
}

const gl::Program& Renderer::gbufferViewProgram(ViewMode view)
{
    // The shadow and ssao views show the shadowing terms; the others a G-buffer quantity.
    const bool shadowing = view == ViewMode::Shadow || view == ViewMode::Ssao;
    gl::Program& program = shadowing ? shadowingViewProgram_ : viewProgram_;
    if (!program)
        program = gl::Program(shadowing ? "shadowing view" : "gbuffer view",
                              {{GL_VERTEX_SHADER, "fullscreen.vert"},
                               {GL_FRAGMENT_SHADER, shadowing ? "shadowing_view.frag" : "gbuffer_view.frag"}},
                              ShaderVariant{.technique = {.gbufferLayout = desc_.gbufferLayout}}.toDefines({}));
    return program;
}

void Renderer::prepareShadowing(ViewMode view, FramePasses& passes)
{
    shadowMaps_.update(passes);
    shadowPool_.update(gpuScene_, *targets_, passes, techniqueOptions());
    // The ssao view shows the occlusion the scene's settings would give, even where the scene
    // leaves it off.
    const AmbientOcclusion& occlusion = ambientOcclusion();
    if (occlusion.enabled || view == ViewMode::Ssao) {
        if (!ssao_)
            ssao_ = std::make_unique<Ssao>(desc_.gbufferLayout);
        ssao_->run(occlusion, passes);
    }
    shadowPool_.bind();
    shadowMaps_.bind(occlusion.enabled, shadowPool_.lookupParams());
    gpuScene_.setFrameShadowing(shadowMaps_.directionalActive(), occlusion.enabled);
}

namespace {
// Every texel of `texture`, `components` values of T each, rows top to bottom like Image's
// (GL's run bottom to top).
template <typename T>
std::vector<T> readTopDown(const gl::Texture2D& texture, GLenum format, GLenum type, int components)
{
    const std::size_t row = static_cast<std::size_t>(texture.width()) * components;
    const auto height = static_cast<std::size_t>(texture.height());
    std::vector<T> bottomUp(row * height);
    texture.read(format, type, bottomUp.size() * sizeof(T), bottomUp.data());
    std::vector<T> topDown(bottomUp.size());
    for (std::size_t y = 0; y < height; ++y)
        std::copy_n(&bottomUp[row * (height - 1 - y)], row, &topDown[row * y]);
    return topDown;
}

// The RGB of an RGBA32F texture as an Image.
Image readRgb(const gl::Texture2D& texture)
{
    Image image;
    image.width = texture.width();
    image.height = texture.height();
    image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    const std::vector<float> rgba = readTopDown<float>(texture, GL_RGBA, GL_FLOAT, 4);
    for (std::size_t i = 0; i < rgba.size() / 4; ++i)
        std::copy_n(&rgba[i * 4], 3, &image.rgb[i * 3]);
    return image;
}

std::uint64_t sumOfTexels(const gl::Texture2D& texture)
{
    std::uint64_t sum = 0;
    for (std::uint32_t value : readTopDown<std::uint32_t>(texture, GL_RED_INTEGER, GL_UNSIGNED_INT, 1))
        sum += value;
    return sum;
}
}  // namespace

void Renderer::countWork()
{
    // Outside the timed frame. The G-buffer is filled again because forward never fills
    // it; the lit image is not touched.
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    targets_->gbuffer.fill(gpuScene_);
    gpuScene_.bind();
    targets_->gbuffer.bindForReading();
    targets_->depthStencil.bindUnit(bindings::SCENE_DEPTH_UNIT);
    targets_->inRangeCounts.bindImage(bindings::IN_RANGE_COUNTS_IMAGE_UNIT, GL_READ_WRITE);
    if (!inRangeProgram_) {
        gl::Defines defines = ShaderVariant{.technique = {.gbufferLayout = desc_.gbufferLayout}}.toDefines({});
        defines.emplace_back("LIGHTS_PER_BATCH", std::to_string(kLightsPerBatch) + "u");
        if (desc_.inRangeBruteForce)
            defines.emplace_back("BRUTE_FORCE", "1");
        inRangeProgram_ = gl::Program("in-range pairs", {{GL_COMPUTE_SHADER, "in_range.comp"}}, defines);
    }
    inRangeProgram_.use();
    constexpr int kGroupSize = 16;  // local_size of shaders/in_range.comp
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(gpuScene_.lightCount()))) {
        // Each batch after the first adds to the counts the one before it stored.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        setLightBatch(inRangeProgram_, batch);
        glDispatchCompute(static_cast<GLuint>((width() + kGroupSize - 1) / kGroupSize),
                          static_cast<GLuint>((height() + kGroupSize - 1) / kGroupSize), 1);
    }
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    // The image holds every pair, the transparent surfaces' too (the light-count view shows
    // both); the transparent ones are reported apart.
    workCounts_.transparentLightEvaluations = transparency_ ? transparency_->lastLightEvaluations() : 0;
    workCounts_.lightEvaluations = sumOfTexels(targets_->lightEvaluations) - workCounts_.transparentLightEvaluations;
    workCounts_.inRangePairs = sumOfTexels(targets_->inRangeCounts);
}

void Renderer::drawEnvironmentBackground(FramePasses& passes)
{
    if (!environmentBackgroundProgram_)
        environmentBackgroundProgram_ =
            gl::Program("environment background",
                        {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "environment_background.frag"}});
    passes.run({.name = "environment background", .target = Resource::LitImage, .state = kUncoveredPixels},
               [&] { drawCoveredPixels(environmentBackgroundProgram_); });
}

void Renderer::drawVolumeOverlay(FramePasses& passes, bool cornersOnly)
{
    if (!overlayDrawer_) {
        overlayDrawer_ = std::make_unique<VolumeDrawer>(techniqueOptions().shaders);
        overlayProgram_ = gl::Program("volume wireframes",
                                      {{GL_VERTEX_SHADER, "volume.vert"}, {GL_FRAGMENT_SHADER, "volume_wire.frag"}});
    }
    VolumeDrawer& drawer = *overlayDrawer_;
    drawer.prepare(gpuScene_);
    // Every volume's edges, or its corners as points large enough to find, over the picture
    // whatever the depth.
    constexpr float kCornerPixels = 5.0f;
    const PipelineState overlay{.depthTest = DepthTest::Off,
                                .keepDepth = true,
                                .pointSize = cornersOnly ? kCornerPixels : 0.0f,
                                .polygonMode = cornersOnly ? PolygonMode::Points : PolygonMode::Lines};
    passes.run({.name = "volume overlay", .target = Resource::LitImage, .state = overlay}, [&] {
        drawer.drawVolumes(VolumeShape::Sphere, 0, drawer.groups().spheres.size(), overlayProgram_);
        drawer.drawVolumes(VolumeShape::Cone, 0, drawer.groups().cones.size(), overlayProgram_);
    });
}

Image Renderer::readColour() const
{
    if (lastView_ == ViewMode::ShadowResolution) {
        // The walk's sums (red: the pairs' log2 figures, green: the pairs) as the figure itself.
        Image image = readRgb(targets_->lit);
        for (std::size_t i = 0; i < image.rgb.size(); i += 3)
            std::fill_n(&image.rgb[i], 3, ShadowResolutionView::texelsPerPixel(image.rgb[i], image.rgb[i + 1]));
        return image;
    }
    if (lastView_ != ViewMode::LightCount)
        return readRgb(targets_->lit);
    Image image;
    image.width = targets_->width;
    image.height = targets_->height;
    image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    const std::vector<std::uint32_t> counts =
        readTopDown<std::uint32_t>(targets_->lightEvaluations, GL_RED_INTEGER, GL_UNSIGNED_INT, 1);
    for (std::size_t i = 0; i < counts.size(); ++i)
        std::fill_n(&image.rgb[i * 3], 3, static_cast<float>(counts[i]));
    return image;
}

Image Renderer::readDisplayed() const
{
    ML_ASSERT(displayed_);
    return readRgb(displayPassRan_ ? displayPass_.output() : targets_->lit);
}

const gl::Framebuffer* Renderer::displayedFramebuffer() const
{
    if (!displayed_)
        return nullptr;
    return displayPassRan_ ? &displayPass_.outputFramebuffer() : &targets_->litFramebuffer;
}

std::vector<bool> Renderer::readCoverage() const
{
    const std::vector<float> depth = readTopDown<float>(targets_->depthStencil, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
    std::vector<bool> covered(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
        covered[i] = depth[i] < 1.0f;
    return covered;
}

}  // namespace manylights
