// Shadow maps rendered before the technique (docs/shadows.md), and the "Shadowing" uniform
// block that shaders/lib/shadows.glsl reads: every technique gets shadows through the one
// lighting function, with no change of its own.
//
// The directional light has one map fitted tightly to what the camera can see (not cascades:
// the scenes this renderer draws span tens of units, where one 2048² map fitted to the
// visible part of the scene gives texels of a few centimetres; docs/shadows.md says why).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "scene/Scene.h"

namespace manylights {

class GpuScene;
class PassProfiler;

// std140 layout of the Shadowing block in shaders/lib/shadows.glsl.
struct ShadowingUniforms {
    glm::mat4 directionalShadowMatrix{1.0f};
    glm::vec4 directionalShadowParams{0.0f};  // x: on; y: 1 / map size
    glm::vec4 occlusionParams{0.0f};          // x: ambient occlusion on
};

// Texture units and binding points shared with shaders/lib/shadows.glsl.
inline constexpr GLuint kDirectionalShadowUnit = 9;
inline constexpr GLuint kShadowingUniformBinding = 1;

// The world → shadow-map transform (uv in xy, depth in z, all in [0, 1]) of a directional
// light travelling along `direction`, fitted to the part of `sceneBounds` inside the camera's
// frustum (`cameraViewProjection`), padded by `padTexels` texels of a `mapSize` map so the
// filter's taps at the edge of the view stay inside. Depth covers all of `sceneBounds`, so
// casters outside the view still cast into it.
glm::mat4 fitDirectionalShadow(const glm::vec3& direction, const Bounds& sceneBounds,
                               const glm::mat4& cameraViewProjection, int mapSize, float padTexels);

class ShadowMaps {
public:
    explicit ShadowMaps(int directionalMapSize = 2048);

    // The viewer's switch: whether a directional light that asks for shadows ("shadows":
    // true in the scene) gets them. On by default.
    void setDirectionalShadows(bool on) { directionalEnabled_ = on; }
    bool directionalShadows() const { return directionalEnabled_; }

    // Renders each map whose inputs changed since it was last rendered (the light, the view it
    // is fitted to, the scene's transforms), as profiled passes, and uploads the uniform block.
    void update(const GpuScene& scene, PassProfiler& profiler);
    // Forgets every cached map: the next update renders all of them.
    void invalidate();
    // Binds the maps and the uniform block for the lighting shaders. `ambientOcclusion`: whether
    // the SSAO texture (unit 13, bound by Ssao) multiplies the ambient term.
    void bind(bool ambientOcclusion);

    // Shadow-map passes rendered since construction: deterministic, so tests can check that an
    // unchanged frame renders none.
    std::uint64_t passesRendered() const { return passesRendered_; }
    // Whether the last update applied directional shadows.
    bool directionalActive() const { return uniforms_.directionalShadowParams.x != 0.0f; }

private:
    void renderDirectional(const GpuScene& scene, const glm::mat4& lightViewProjection, PassProfiler& profiler);

    int directionalMapSize_;
    bool directionalEnabled_ = true;
    gl::Texture2D directionalMap_;
    gl::Framebuffer directionalFramebuffer_;
    gl::Program depthProgram_;
    gl::Buffer uniformBuffer_;
    ShadowingUniforms uniforms_;

    // What the directional map was last rendered for.
    bool directionalValid_ = false;
    glm::mat4 directionalRenderedMatrix_{0.0f};
    std::uint64_t directionalRenderedVersion_ = 0;

    std::uint64_t passesRendered_ = 0;
};

}  // namespace manylights
