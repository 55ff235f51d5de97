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
    gpuScene_.setAspect(static_cast<float>(width) / static_cast<float>(height));
}

FrameSample Renderer::renderFrame(Technique& technique, ViewMode view)
{
    glViewport(0, 0, targets_->width, targets_->height);
    glDisable(GL_CULL_FACE);  // scene meshes are not guaranteed closed or consistently wound
    profiler_.beginFrame();
    if (view == ViewMode::Final) {
        targets_->litFramebuffer.clearColour(0, &gpuScene_.frameUniforms().background.x);
        technique.render(gpuScene_, *targets_, profiler_);
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
    return profiler_.endFrame();
}

Image Renderer::readColour() const
{
    const int width = targets_->width;
    const int height = targets_->height;
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
