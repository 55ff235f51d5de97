#include "render/scene/GpuFrame.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/programs/Bindings.h"

namespace manylights {

namespace {
// Binding point shared with the shaders (lib/frame.glsl).
constexpr GLuint kFrameBinding = bindings::FRAME_BLOCK_BINDING;
}  // namespace

FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, int width, int height,
                                std::uint32_t lightCount)
{
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    FrameUniforms frame{};
    frame.view = glm::lookAt(camera.eye, camera.lookAt, camera.up);
    const glm::mat4 projection =
        glm::perspective(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane, camera.farPlane);
    frame.viewProjection = projection * frame.view;
    frame.eye = glm::vec4(camera.eye, 1.0f);
    frame.viewAxis = glm::vec4(glm::normalize(camera.lookAt - camera.eye), 0.0f);
    frame.ambient = glm::vec4(scene.ambient, 0.0f);
    if (scene.directional) {
        frame.directionalToLight = glm::vec4(-glm::normalize(scene.directional->direction), 0.0f);
        frame.directionalIntensity = glm::vec4(scene.directional->intensity, 0.0f);
    }
    frame.background = glm::vec4(scene.background, 1.0f);
    frame.counts = glm::uvec4(lightCount, 0u, 0u, 0u);
    const float tanHalfFovY = std::tan(glm::radians(camera.fovYDegrees) / 2.0f);
    frame.projection = glm::vec4(tanHalfFovY * aspect, tanHalfFovY, camera.nearPlane, camera.farPlane);
    frame.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height), 1.0f / static_cast<float>(width),
                               1.0f / static_cast<float>(height));
    frame.terms = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
    return frame;
}

GpuFrame::GpuFrame(const Scene& scene, std::size_t lightCount)
    : scene_(scene),
      lightCount_(static_cast<std::uint32_t>(lightCount)),
      camera_(scene.camera),
      buffer_("frame uniforms", sizeof(FrameUniforms), nullptr)
{
    update();
}

void GpuFrame::bind() const { buffer_.bindBase(GL_UNIFORM_BUFFER, kFrameBinding); }

void GpuFrame::setViewport(int width, int height)
{
    viewportWidth_ = width;
    viewportHeight_ = height;
    update();
}

bool GpuFrame::setCamera(const Camera& camera)
{
    if (camera == camera_)
        return false;
    camera_ = camera;
    update();
    return true;
}

void GpuFrame::setTime(double t)
{
    time_ = t;
    frame_.time = glm::vec4(static_cast<float>(t), 0.0f, 0.0f, 0.0f);
    upload();
}

void GpuFrame::setLightingTerms(const glm::vec3& terms)
{
    terms_ = glm::vec4(terms, 0.0f);
    frame_.terms = terms_;
    upload();
}

void GpuFrame::update()
{
    frame_ = makeFrameUniforms(scene_, camera_, viewportWidth_, viewportHeight_, lightCount_);
    frame_.time = glm::vec4(static_cast<float>(time_), 0.0f, 0.0f, 0.0f);
    frame_.terms = terms_;
    upload();
}

void GpuFrame::upload() { buffer_.update(0, sizeof(FrameUniforms), &frame_); }

}  // namespace manylights
