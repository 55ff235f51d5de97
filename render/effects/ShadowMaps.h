// Shadow maps rendered before the technique (docs/shadows.md), and the "Shadowing" uniform
// block that shaders/lib/shadows.glsl reads: every technique gets shadows through the one
// lighting function, with no change of its own.
//
// The directional light has one map fitted tightly to what the camera can see (not cascades:
// the scenes this renderer draws span tens of units, where one 2048² map fitted to the
// visible part of the scene gives texels of a few centimetres; docs/shadows.md says why).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/programs/Bindings.h"
#include "render/programs/LoopBudget.h"
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
    glm::vec4 localShadowParams{0.0f};        // x: some local light shadowed; y: 1 / spot size; z: 1 / cube size
};

// std430 layout of ShadowSlot in shaders/lib/shadows.glsl.
struct GpuShadowSlot {
    glm::mat4 viewProjection{1.0f};
    glm::vec4 params{0.0f};  // x: 1 spot, 2 cube; y: layer; z: near; w: far
};

// Texture units and binding points shared with shaders/lib/shadows.glsl.
inline constexpr GLuint kDirectionalShadowUnit = bindings::DIRECTIONAL_SHADOW_UNIT;
inline constexpr GLuint kSpotShadowUnit = bindings::SPOT_SHADOWS_UNIT;
inline constexpr GLuint kPointShadowUnit = bindings::POINT_SHADOWS_UNIT;
inline constexpr GLuint kShadowingUniformBinding = bindings::SHADOWING_BLOCK_BINDING;
inline constexpr GLuint kShadowSlotOfLightBinding = bindings::SHADOW_SLOT_OF_LIGHT_BUFFER_BINDING;
inline constexpr GLuint kShadowSlotsBinding = bindings::SHADOW_SLOTS_BUFFER_BINDING;

// Spot lights up to this cutoff get one perspective map; wider ones (whose map would need a
// field of view near or beyond 180°) get a cube map like a point light.
inline constexpr float kMaxSpotMapCutoffDegrees = 75.0f;

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
    int spot = 1024;
    int cubeFace = 512;
};

class ShadowMaps {
public:
    explicit ShadowMaps(const ShadowMapSizes& sizes = {});

    // How many local lights get shadow maps (--shadow-lights; 0 by default: only the
    // directional light casts shadows). Chosen each frame by selectShadowLights.
    void setLocalLightBudget(int budget) { localBudget_ = budget; }
    int localLightBudget() const { return localBudget_; }

    // The viewer's switch: whether a directional light that asks for shadows ("shadows":
    // true in the scene) gets them. On by default.
    void setDirectionalShadows(bool on) { directionalEnabled_ = on; }
    bool directionalShadows() const { return directionalEnabled_; }

    // Renders each map whose inputs changed since it was last rendered (the light, the view it
    // is fitted to, the scene's transforms), as passes of the frame (of `passes`' scene).
    void update(FramePasses& passes);
    // Forgets every cached map: the next update renders all of them.
    void invalidate();
    // Renders every map every frame, as when everything moves (for measuring the cost of
    // building the maps; --rebuild-shadows).
    void setRebuildEveryFrame(bool rebuild) { rebuildEveryFrame_ = rebuild; }
    // Binds the maps and the uniform block for the lighting shaders. `ambientOcclusion`: whether
    // the SSAO texture (unit 13, bound by Ssao) multiplies the ambient term.
    void bind(bool ambientOcclusion);

    // Shadow-map passes rendered since construction: deterministic, so tests can check that an
    // unchanged frame renders none.
    std::uint64_t passesRendered() const { return passesRendered_; }
    // Whether the last update applied directional shadows.
    bool directionalActive() const { return uniforms_.directionalShadowParams.x != 0.0f; }

    // The local lights that had shadow maps in the last update (indices into the lights).
    const std::vector<std::size_t>& shadowedLights() const { return shadowedLights_; }

private:
    // A local light's map: what it was rendered for, so an unchanged light is not redrawn.
    struct LocalSlot {
        std::size_t light = 0;
        bool cube = false;
        int layer = 0;  // layer of the spot array, or cube index of the cube array
        GpuLight renderedFor{};
        std::uint64_t renderedVersion = 0;
        bool valid = false;
        GpuShadowSlot gpu;
    };

    void renderDirectional(FramePasses& passes, const glm::mat4& lightViewProjection);
    void updateLocal(FramePasses& passes);
    void ensureArrays(int spotLayers, int cubes);
    void renderSpot(FramePasses& passes, LocalSlot& slot);
    void renderCube(FramePasses& passes, LocalSlot& slot);
    // One pass named `name`: clears `framebuffer`'s depth (`size` square) and draws the
    // casters `keep` accepts into it, with the slope-scaled bias.
    void drawDepthPass(FramePasses& passes, std::string_view name, const gl::Framebuffer& framebuffer, int size,
                       const glm::mat4& viewProjection, const std::function<bool(const Bounds&)>& keep);
    // The same into one layer of `texture`.
    void renderDepth(FramePasses& passes, std::string_view name, const gl::DepthTextureArray& texture, int layer,
                     int size, const glm::mat4& viewProjection, const std::function<bool(const Bounds&)>& keep);

    ShadowMapSizes sizes_;
    int directionalMapSize_;
    int localBudget_ = 0;
    bool rebuildEveryFrame_ = false;
    bool directionalEnabled_ = true;
    gl::Texture2D directionalMap_;
    gl::Framebuffer directionalFramebuffer_;
    // The depth pass's programs per depth-only material variant (render/programs/LightingPrograms.h:
    // depthOnlyVariant; 0 for every caster without an alpha mask), compiled on first use.
    const gl::Program& depthProgram(MaterialVariant variant);
    std::map<MaterialVariant, gl::Program> depthPrograms_;
    gl::Buffer uniformBuffer_;
    ShadowingUniforms uniforms_;

    // What the directional map was last rendered for.
    bool directionalValid_ = false;
    glm::mat4 directionalRenderedMatrix_{0.0f};
    std::uint64_t directionalRenderedVersion_ = 0;

    std::uint64_t passesRendered_ = 0;

    // Local lights: spot maps in one 2D array (unit 10), cube maps in one cube-map array (unit
    // 11), both depth textures with comparison; slots keep their light while it stays chosen.
    std::vector<LocalSlot> slots_;
    std::vector<std::size_t> shadowedLights_;
    gl::DepthTextureArray spotArray_;
    gl::DepthTextureArray cubeArray_;
    int spotLayers_ = 0;
    int cubes_ = 0;
    int spotArraySize_ = 0;
    int cubeArraySize_ = 0;
    std::size_t lightCount_ = 0;
    gl::Framebuffer localFramebuffer_;  // one layer attached at a time
    gl::Buffer slotOfLightBuffer_;
    gl::Buffer slotsBuffer_;
    std::size_t slotOfLightCapacity_ = 0;          // entries in slotOfLightBuffer_
    std::vector<std::size_t> uploadedSlotLights_;  // the lights of the slots it was written for
    std::size_t slotsCapacity_ = 0;
};

}  // namespace manylights
