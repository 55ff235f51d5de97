#include "render/Renderer.h"

#include <algorithm>
#include <string>

#include "render/DeferredTechnique.h"
#include "core/Error.h"

namespace manylights {

namespace {

void checkSize(int width, int height)
{
    GLint maxTexture = 0;
    GLint maxFramebufferWidth = 0;
    GLint maxFramebufferHeight = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxFramebufferWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxFramebufferHeight);
    const int maxWidth = std::min(maxTexture, maxFramebufferWidth);
    const int maxHeight = std::min(maxTexture, maxFramebufferHeight);
    if (width < 1 || height < 1 || width > maxWidth || height > maxHeight)
        throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside what this OpenGL implementation supports (1x1 to " + std::to_string(maxWidth) +
                    "x" + std::to_string(maxHeight) + ")");
}

}  // namespace

Renderer::Renderer(const Scene& scene, const std::vector<Light>& lights, int width, int height)
    : gpuScene_(scene, lights),
      viewProgram_("gbuffer view", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "gbuffer_view.frag"}})
{
    resize(width, height);
}

void Renderer::resize(int width, int height)
{
    checkSize(width, height);
    targets_.reset();  // free the old targets before allocating the new ones
    targets_ = std::make_unique<FrameTargets>(width, height);
    gpuScene_.setViewport(width, height);
}

FrameSample Renderer::renderFrame(Technique& technique, ViewMode view)
{
    glViewport(0, 0, targets_->width, targets_->height);
    glDisable(GL_CULL_FACE);  // scene meshes are not guaranteed closed or consistently wound
    ML_ASSERT(countWork_ || view != ViewMode::LightCount);
    lastView_ = view;
    if (countWork_) {
        const GLuint zero = 0;
        glClearTexImage(targets_->lightEvaluations.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glBindImageTexture(0, targets_->lightEvaluations.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    }
    profiler_.beginFrame();
    if (!isGBufferView(view)) {
        targets_->litFramebuffer.clearColour(0, &gpuScene_.frameUniforms().background.x);
        technique.render(gpuScene_, *targets_, profiler_);
        if (view == ViewMode::Volumes)
            drawVolumeOverlay();
    } else {
        targets_->gbuffer.fill(gpuScene_, profiler_);
        auto pass = profiler_.pass("view");
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        targets_->litFramebuffer.clearColour(0, black);
        targets_->litFramebuffer.bind();
        gpuScene_.bind();
        targets_->gbuffer.bindForReading();
        viewProgram_.set(0, static_cast<int>(view));
        drawCoveredPixels(viewProgram_);
    }
    FrameSample sample = profiler_.endFrame();
    if (countWork_)
        countWork();
    return sample;
}

namespace {
std::uint64_t sumOfTexels(const gl::Texture2D& texture)
{
    std::vector<std::uint32_t> values(static_cast<std::size_t>(texture.width()) * texture.height());
    glGetTextureImage(texture.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      static_cast<GLsizei>(values.size() * sizeof(std::uint32_t)), values.data());
    std::uint64_t sum = 0;
    for (std::uint32_t value : values)
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
    targets_->depthStencil.bindUnit(5);
    glBindImageTexture(1, targets_->inRangeCounts.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    if (!inRangeProgram_)
        inRangeProgram_ = gl::Program("in-range pairs", {{GL_COMPUTE_SHADER, "in_range.comp"}});
    inRangeProgram_.use();
    constexpr int kGroupSize = 8;  // local_size of shaders/in_range.comp
    glDispatchCompute(static_cast<GLuint>((width() + kGroupSize - 1) / kGroupSize),
                      static_cast<GLuint>((height() + kGroupSize - 1) / kGroupSize), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    workCounts_.lightEvaluations = sumOfTexels(targets_->lightEvaluations);
    workCounts_.inRangePairs = sumOfTexels(targets_->inRangeCounts);
}

void Renderer::drawVolumeOverlay()
{
    if (!overlayDrawer_) {
        overlayDrawer_ = std::make_unique<VolumeDrawer>();
        overlayProgram_ = gl::Program("volume wireframes",
                                      {{GL_VERTEX_SHADER, "volume.vert"}, {GL_FRAGMENT_SHADER, "volume_wire.frag"}});
    }
    VolumeDrawer& drawer = *overlayDrawer_;
    drawer.prepare(gpuScene_);
    targets_->litFramebuffer.bind();
    gpuScene_.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    drawer.drawVolumes(VolumeShape::Sphere, 0, drawer.groups().spheres.size(), overlayProgram_);
    drawer.drawVolumes(VolumeShape::Cone, 0, drawer.groups().cones.size(), overlayProgram_);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_DEPTH_TEST);
}

Image Renderer::readColour() const
{
    const int width = targets_->width;
    const int height = targets_->height;
    if (lastView_ == ViewMode::LightCount) {
        std::vector<std::uint32_t> counts(static_cast<std::size_t>(width) * height);
        glGetTextureImage(targets_->lightEvaluations.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                          static_cast<GLsizei>(counts.size() * sizeof(std::uint32_t)), counts.data());
        Image image;
        image.width = width;
        image.height = height;
        image.rgb.resize(counts.size() * 3);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const auto count = static_cast<float>(counts[static_cast<std::size_t>(height - 1 - y) * width + x]);
                std::fill(image.pixel(x, y), image.pixel(x, y) + 3, count);
            }
        return image;
    }
    std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4);
    glGetTextureImage(targets_->lit.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                      rgba.data());
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
    // GL's rows run bottom to top; Image's top to bottom.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* source = &rgba[(static_cast<std::size_t>(height - 1 - y) * width + x) * 4];
            std::copy(source, source + 3, image.pixel(x, y));
        }
    return image;
}

std::vector<bool> Renderer::readCoverage() const
{
    const int width = targets_->width;
    const int height = targets_->height;
    std::vector<float> depth(static_cast<std::size_t>(width) * height);
    glGetTextureImage(targets_->depthStencil.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    std::vector<bool> covered(depth.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            covered[static_cast<std::size_t>(y) * width + x] = depth[static_cast<std::size_t>(height - 1 - y) * width + x] < 1.0f;
    return covered;
}

}  // namespace manylights
