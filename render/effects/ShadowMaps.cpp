#include "render/effects/ShadowMaps.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "gl/Debug.h"
#include "render/frame/FramePasses.h"
#include "render/programs/Locations.h"
#include "render/scene/GpuScene.h"
#include "scene/ShadowSelection.h"

namespace manylights {

namespace {

// Slope-scaled depth bias of the map (glPolygonOffset): the 3x3 filter of
// shaders/lib/shadows.glsl, with bilinear taps, compares a receiver's depth with map texels
// up to 2 texels away, where a surface tilted to the light is deeper by up to 2 × its depth
// slope per texel; a factor of 3 covers that with a texel to spare. The constant part (in
// units of the 24-bit depth's resolution, 2^-24 of the map's depth range) covers the float
// rounding of the two depth computations (caster raster, receiver transform), a few 1e-7.
constexpr float kSlopeScaledBias = 3.0f;
constexpr float kConstantBiasUnits = 16.0f;
// The filter's reach beyond a visible surface's texel (3x3 taps, each bilinear).
constexpr float kFilterReachTexels = 2.0f;
// Location of the light's view-projection in shaders/shadow_depth.vert.
constexpr GLint kLightViewProjectionLocation = locations::LIGHT_VIEW_PROJECTION_LOCATION;

// A depth texture read with hardware comparison and bilinear percentage-closer filtering;
// outside the map it compares as lit (border depth 1).
gl::Texture2D makeShadowTexture(std::string_view label, int size)
{
    gl::Texture2D texture(label, GL_DEPTH_COMPONENT24, size, size);
    texture.setLinearFiltering();
    texture.compareDepth(GL_LEQUAL);
    texture.setWrap(GL_CLAMP_TO_BORDER);
    texture.setBorderColour({1.0f, 1.0f, 1.0f, 1.0f});
    return texture;
}

// NDC [-1, 1]³ → [0, 1]³ (texture coordinates and window depth).
const glm::mat4 kNdcToUnit =
    glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

}  // namespace

glm::mat4 fitDirectionalShadow(const glm::vec3& direction, const Bounds& sceneBounds,
                               const glm::mat4& cameraViewProjection, int mapSize, float padTexels)
{
    const glm::vec3 forward = glm::normalize(direction);
    const glm::vec3 up = std::abs(forward.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::mat4 lightView = glm::lookAt(glm::vec3(0.0f), forward, up);
    const Bounds scene = transformedBounds(sceneBounds, lightView);
    // The camera's frustum in light space: its eight corners.
    const glm::mat4 cameraInverse = glm::inverse(cameraViewProjection);
    Bounds frustum;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 ndc((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f,
                            1.0f);
        const glm::vec4 world = cameraInverse * ndc;
        frustum.extend(glm::vec3(lightView * (world / world.w)));
    }
    // Across the light: only what the camera can see (and the scene holds). Along it: the
    // whole scene, so casters between the light and the view still cast.
    glm::vec2 low = glm::max(glm::vec2(scene.min), glm::vec2(frustum.min));
    glm::vec2 high = glm::min(glm::vec2(scene.max), glm::vec2(frustum.max));
    if (low.x >= high.x || low.y >= high.y) {
        low = glm::vec2(scene.min);
        high = glm::vec2(scene.max);
    }
    const glm::vec2 pad = (high - low) * padTexels / (static_cast<float>(mapSize) - 2.0f * padTexels);
    low -= pad;
    high += pad;
    // Surfaces exactly on the bounds must not be clipped by the near and far planes.
    const float depthPad = 0.01f * (scene.max.z - scene.min.z) + 1e-3f;
    const glm::mat4 projection =
        glm::ortho(low.x, high.x, low.y, high.y, -(scene.max.z + depthPad), -(scene.min.z - depthPad));
    return projection * lightView;
}

ShadowMaps::ShadowMaps(const ShadowMapSizes& sizes)
    : sizes_(sizes),
      directionalMapSize_(sizes.directional),
      depthPrograms_("shadow depth",
                     {{GL_VERTEX_SHADER, "shadow_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_depth.frag"}}),
      uniformBuffer_("shadowing uniforms", sizeof(ShadowingUniforms), nullptr)
{
    // A 1x1 map until the directional light needs a real one: the shaders' sampler must
    // always see a depth texture with comparison on, even when shadows are off. The local
    // lights' arrays start with one layer for the same reason.
    directionalMap_ = makeShadowTexture("directional shadow map (unused, 1x1)", 1);
    directionalMap_.clearDepth(1.0f);
}

void ShadowMaps::invalidate() { directionalValid_ = false; }

void ShadowMaps::update(FramePasses& passes)
{
    const GpuScene& scene = passes.scene();
    if (rebuildEveryFrame_)
        invalidate();
    const Scene& description = scene.scene();
    const bool directional = directionalEnabled_ && description.directional && description.directional->shadows;
    uniforms_.directionalShadowParams = glm::vec4(0.0f);
    if (directional) {
        const glm::mat4 lightViewProjection =
            fitDirectionalShadow(description.directional->direction, scene.objectsWorldBounds(),
                                 scene.frameUniforms().viewProjection, directionalMapSize_, kFilterReachTexels + 1.0f);
        if (!directionalValid_ || lightViewProjection != directionalRenderedMatrix_ ||
            scene.transformsVersion() != directionalRenderedVersion_)
            renderDirectional(passes, lightViewProjection);
        uniforms_.directionalShadowMatrix = kNdcToUnit * lightViewProjection;
        uniforms_.directionalShadowParams = glm::vec4(1.0f, 1.0f / static_cast<float>(directionalMapSize_), 0.0f, 0.0f);
    }
}

void ShadowMaps::renderDirectional(FramePasses& passes, const glm::mat4& lightViewProjection)
{
    const GpuScene& scene = passes.scene();
    if (directionalMap_.width() != directionalMapSize_) {
        directionalMap_ = makeShadowTexture("directional shadow map", directionalMapSize_);
        directionalFramebuffer_ = gl::Framebuffer("directional shadow map", {}, &directionalMap_);
    }
    // Every object: an orthographic light has no volume to cull against beyond the fitted
    // box, which the rasteriser clips.
    drawDepthPass(passes, "shadow directional", directionalFramebuffer_, directionalMapSize_, lightViewProjection);
    directionalValid_ = true;
    directionalRenderedMatrix_ = lightViewProjection;
    directionalRenderedVersion_ = scene.transformsVersion();
}

void ShadowMaps::drawDepthPass(FramePasses& passes, std::string_view name, const gl::Framebuffer& framebuffer, int size,
                               const glm::mat4& viewProjection)
{
    const Pass depthPass{
        .name = name,
        .framebuffer = &framebuffer,
        .state = {.depthBias = {kSlopeScaledBias, kConstantBiasUnits}, .viewport = {0, 0, size, size}}};
    // The pass's state writes depth, so the clear (which the depth mask would stop) clears.
    passes.run(depthPass, [&] {
        framebuffer.clearDepth(1.0f);
        passes.scene().drawObjectsDepthOnly(
            [&](MaterialVariant variant) -> const gl::Program& {
                const gl::Program& program = depthPrograms_.variant({variant});
                program.set(kLightViewProjectionLocation, viewProjection);
                return program;
            },
            [](const Bounds&) { return true; });
    });
    ++passesRendered_;
}

void ShadowMaps::bind(bool ambientOcclusion, const glm::vec4& localShadowParams)
{
    uniforms_.occlusionParams = glm::vec4(ambientOcclusion ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    uniforms_.localShadowParams = localShadowParams;
    uniformBuffer_.update(0, sizeof(ShadowingUniforms), &uniforms_);
    uniformBuffer_.bindBase(GL_UNIFORM_BUFFER, kShadowingUniformBinding);
    directionalMap_.bindUnit(kDirectionalShadowUnit);
}

}  // namespace manylights
