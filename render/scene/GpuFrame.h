// The per-frame uniform buffer (shaders/lib/frame.glsl): the camera, the viewport, the scene
// time, the lighting terms switched on, and what the frame's shadowing reads.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "scene/Scene.h"

namespace manylights {

// std140 layout of shaders/lib/frame.glsl: Frame.
struct FrameUniforms {
    glm::mat4 viewProjection;
    glm::mat4 view;
    glm::vec4 eye;
    glm::vec4 viewAxis;
    glm::vec4 ambient;
    glm::vec4 directionalToLight;
    glm::vec4 directionalIntensity;
    glm::vec4 background;
    glm::uvec4 counts;
    glm::vec4 projection;  // tan(fovX / 2), tan(fovY / 2), near, far
    glm::vec4 viewport;    // width, height, 1 / width, 1 / height
    glm::vec4 time;        // x: the scene time in seconds (GpuFrame::setTime)
    glm::vec4 terms;       // 1 or 0: ambient, diffuse, specular (the viewer's toggles), w unused
};

// The camera matrices for an image of the given size.
FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, int width, int height,
                                std::uint32_t lightCount);

class GpuFrame {
public:
    // The frame of `scene` (its ambient, directional light and background; its camera until
    // setCamera) with `lightCount` local lights, at time 0, in a 1x1 viewport. `scene` must
    // outlive the frame.
    GpuFrame(const Scene& scene, std::size_t lightCount);

    // Binds the uniform buffer at lib/frame.glsl's binding.
    void bind() const;
    void setViewport(int width, int height);
    // Returns whether the camera changed (the viewer sets its camera every frame).
    bool setCamera(const Camera& camera);
    void setTime(double t);
    // Switches the ambient, diffuse and specular terms of the lighting on (1) or off (0).
    void setLightingTerms(const glm::vec3& terms);
    // Whether this frame reads a directional shadow map and the SSAO factor.
    void setShadowing(bool directionalShadow, bool ambientOcclusion)
    {
        directionalShadow_ = directionalShadow;
        ambientOcclusion_ = ambientOcclusion;
    }
    bool directionalShadow() const { return directionalShadow_; }
    bool ambientOcclusion() const { return ambientOcclusion_; }

    const Camera& camera() const { return camera_; }
    double time() const { return time_; }
    const FrameUniforms& uniforms() const { return frame_; }

private:
    // The frame uniforms of this camera and viewport, with terms_ and time_.
    void update();
    void upload();

    const Scene& scene_;
    std::uint32_t lightCount_;
    Camera camera_;
    int viewportWidth_ = 1;
    int viewportHeight_ = 1;
    double time_ = 0.0;
    glm::vec4 terms_{1.0f, 1.0f, 1.0f, 0.0f};
    bool directionalShadow_ = true;
    bool ambientOcclusion_ = true;
    FrameUniforms frame_{};
    gl::Buffer buffer_;
};

}  // namespace manylights
