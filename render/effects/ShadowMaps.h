// The directional light's shadow map, rendered before the technique (docs/shadows.md), and the
// "Shadowing" uniform block that shaders/lib/shadows.glsl reads: every technique gets shadows
// through the one lighting function, with no change of its own. The local lights' shadows are
// the shadow-page pool's (render/shadows/ShadowPool.h), whose lookup parameters bind() takes.
//
// The directional light has one map fitted tightly to what the camera can see (not cascades:
// the scenes this renderer draws span tens of units, where one 2048² map fitted to the
// visible part of the scene gives texels of a few centimetres; docs/shadows.md says why).
#pragma once

#include <cstdint>
#include <map>
#include <string_view>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/programs/Bindings.h"
#include "render/programs/LightingPrograms.h"
#include "render/programs/ProgramVariants.h"
#include "render/scene/GpuScene.h"
#include "scene/Scene.h"

namespace manylights {

class GpuScene;
class FramePasses;

// std140 layout of the Shadowing block in shaders/lib/shadows.glsl.
struct ShadowingUniforms {
    glm::mat4 directionalShadowMatrix{1.0f};
    glm::vec4 directionalShadowParams{0.0f};  // x: on; y: 1 / map size
    glm::vec4 occlusionParams{0.0f};          // x: ambient occlusion on
    glm::vec4 localShadowParams{0.0f};        // ShadowPool::lookupParams
};

// Texture units and binding points shared with shaders/lib/shadows.glsl.
inline constexpr GLuint kDirectionalShadowUnit = bindings::DIRECTIONAL_SHADOW_UNIT;
inline constexpr GLuint kShadowingUniformBinding = bindings::SHADOWING_BLOCK_BINDING;

// The world → shadow-map transform (uv in xy, depth in z, all in [0, 1]) of a directional
// light travelling along `direction`, fitted to the part of `sceneBounds` inside the camera's
// frustum (`cameraViewProjection`), padded by `padTexels` texels of a `mapSize` map so the
// filter's taps at the edge of the view stay inside. Depth covers all of `sceneBounds`, so
// casters outside the view still cast into it.
glm::mat4 fitDirectionalShadow(const glm::vec3& direction, const Bounds& sceneBounds,
                               const glm::mat4& cameraViewProjection, int mapSize, float padTexels);

// Sizes of the maps, in texels per side.
struct ShadowMapSizes {
    int directional = 2048;
};

class ShadowMaps {
public:
    explicit ShadowMaps(const ShadowMapSizes& sizes = {});

    // The viewer's switch: whether a directional light that asks for shadows ("shadows":
    // true in the scene) gets them. On by default.
    void setDirectionalShadows(bool on) { directionalEnabled_ = on; }
    bool directionalShadows() const { return directionalEnabled_; }

    // Renders the map where its inputs changed since it was last rendered (the light, the view
    // it is fitted to, the scene's transforms), as a pass of the frame (of `passes`' scene).
    void update(FramePasses& passes);
    // Forgets every cached map: the next update renders all of them.
    void invalidate();
    // Renders every map every frame, as when everything moves (for measuring the cost of
    // building the maps; --rebuild-shadows).
    void setRebuildEveryFrame(bool rebuild) { rebuildEveryFrame_ = rebuild; }
    // Binds the map and the uniform block for the lighting shaders. `ambientOcclusion`: whether
    // the SSAO texture (unit 13, bound by Ssao) multiplies the ambient term; `localShadowParams`:
    // the shadow-page pool's (ShadowPool::lookupParams).
    void bind(bool ambientOcclusion, const glm::vec4& localShadowParams);

    // Shadow-map passes rendered since construction: deterministic, so tests can check that an
    // unchanged frame renders none.
    std::uint64_t passesRendered() const { return passesRendered_; }
    // Whether the last update applied directional shadows.
    bool directionalActive() const { return uniforms_.directionalShadowParams.x != 0.0f; }

private:
    void renderDirectional(FramePasses& passes, const glm::mat4& lightViewProjection);
    // One pass named `name`: clears `framebuffer`'s depth (`size` square) and draws the
    // casters into it, with the slope-scaled bias.
    void drawDepthPass(FramePasses& passes, std::string_view name, const gl::Framebuffer& framebuffer, int size,
                       const glm::mat4& viewProjection);

    ShadowMapSizes sizes_;
    int directionalMapSize_;
    bool rebuildEveryFrame_ = false;
    bool directionalEnabled_ = true;
    gl::Texture2D directionalMap_;
    gl::Framebuffer directionalFramebuffer_;
    // The depth pass's programs per depth-only material variant (render/programs/LightingPrograms.h:
    // depthOnlyVariant; 0 for every caster without an alpha mask), compiled on first use.
    ProgramVariants<DepthOnlyVariant> depthPrograms_;
    gl::Buffer uniformBuffer_;
    ShadowingUniforms uniforms_;

    // What the directional map was last rendered for.
    bool directionalValid_ = false;
    glm::mat4 directionalRenderedMatrix_{0.0f};
    std::uint64_t directionalRenderedVersion_ = 0;

    std::uint64_t passesRendered_ = 0;
};

}  // namespace manylights
