#include "render/effects/ShadowMaps.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "gl/Debug.h"
#include "render/frame/FramePasses.h"
#include "render/programs/Locations.h"
#include "render/scene/GpuScene.h"
#include "scene/Falloff.h"
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
      uniformBuffer_("shadowing uniforms", sizeof(ShadowingUniforms), nullptr)
{
    // A 1x1 map until the directional light needs a real one: the shaders' sampler must
    // always see a depth texture with comparison on, even when shadows are off. The local
    // lights' arrays start with one layer for the same reason.
    directionalMap_ = makeShadowTexture("directional shadow map (unused, 1x1)", 1);
    directionalMap_.clearDepth(1.0f);
    ensureArrays(0, 0);
    localFramebuffer_ = gl::Framebuffer("local shadow maps");
}

void ShadowMaps::invalidate()
{
    directionalValid_ = false;
    for (LocalSlot& slot : slots_)
        slot.valid = false;
}

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
    updateLocal(passes);
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
    drawDepthPass(passes, "shadow directional", directionalFramebuffer_, directionalMapSize_, lightViewProjection,
                  [](const Bounds&) { return true; });
    directionalValid_ = true;
    directionalRenderedMatrix_ = lightViewProjection;
    directionalRenderedVersion_ = scene.transformsVersion();
}

namespace {

bool sameLight(const GpuLight& a, const GpuLight& b)
{
    return a.positionRadius == b.positionRadius && a.intensityExponent == b.intensityExponent &&
           a.attenuation == b.attenuation && a.spotAxisCosCutoff == b.spotAxisCosCutoff;
}

// A wide spot's map would be a stretched perspective: it gets a cube map as a point light does.
bool needsCube(const Light& light)
{
    return light.type != LightType::Spot || light.cutoffDegrees > kMaxSpotMapCutoffDegrees;
}

// The far plane of a local light's map: its radius, or for a light that reaches farther than
// the scene, the scene's farthest corner (a little beyond, so it is not clipped).
float shadowFar(const Light& light, const GpuScene& scene)
{
    const Bounds bounds = scene.objectsWorldBounds();
    const glm::vec3 p = light.position;
    const glm::vec3 farthest = glm::max(glm::abs(bounds.min - p), glm::abs(bounds.max - p));
    return std::min(lightRadius(light, scene.scene().attenuationThreshold), 1.01f * glm::length(farthest) + 1e-3f);
}
// The near plane: objects closer to the light than this do not cast. A thousandth of the far
// plane keeps the 24-bit depth's resolution near the far plane at about far / 16000.
constexpr float kNearFraction = 1e-3f;
// The spot map's field of view beyond the cone: room for the filter's taps at the cone's edge.
constexpr float kSpotFovMarginDegrees = 2.0f;

}  // namespace

void ShadowMaps::ensureArrays(int spotLayers, int cubes)
{
    // With no slot of a kind, its array is a 1x1 stand-in that keeps the sampler complete; it
    // grows (and loses its maps) when more layers are needed than it has.
    if (!spotArray_ || (spotLayers > 0 && (spotArraySize_ != sizes_.spot || spotLayers > spotLayers_))) {
        spotArraySize_ = spotLayers > 0 ? sizes_.spot : 1;
        spotLayers_ = std::max(spotLayers, 1);
        spotArray_ = gl::DepthTextureArray(GL_TEXTURE_2D_ARRAY, "spot shadow maps", spotArraySize_, spotLayers_);
        for (LocalSlot& slot : slots_)
            if (!slot.cube)
                slot.valid = false;
    }
    if (!cubeArray_ || (cubes > 0 && (cubeArraySize_ != sizes_.cubeFace || cubes > cubes_))) {
        cubeArraySize_ = cubes > 0 ? sizes_.cubeFace : 1;
        cubes_ = std::max(cubes, 1);
        cubeArray_ = gl::DepthTextureArray(GL_TEXTURE_CUBE_MAP_ARRAY, "point shadow maps", cubeArraySize_, 6 * cubes_);
        for (LocalSlot& slot : slots_)
            if (slot.cube)
                slot.valid = false;
    }
}

void ShadowMaps::updateLocal(FramePasses& passes)
{
    const GpuScene& scene = passes.scene();
    lightCount_ = scene.lightCount();
    shadowedLights_.clear();
    // The posed lights are asked for only where some may cast shadows: a frame without shadow
    // lights does not pose a million moving lights on the CPU (render/scene/SceneLights.h).
    if (localBudget_ > 0) {
        // As the shaders get them: posed, with the radius lightRadius gave them.
        const std::vector<GpuLight>& lights = scene.packedLights();
        std::vector<ShadowCandidate> candidates;
        candidates.reserve(lights.size());
        for (const GpuLight& light : lights)
            candidates.push_back(
                {glm::vec3(light.positionRadius), light.positionRadius.w,
                 std::max({light.intensityExponent.r, light.intensityExponent.g, light.intensityExponent.b})});
        shadowedLights_ = selectShadowLights(candidates, scene.frameUniforms().viewProjection, localBudget_);
    }

    // A light that stays chosen keeps its slot (and its cached map); new ones take free layers.
    std::vector<LocalSlot> kept;
    std::vector<std::size_t> fresh;
    for (std::size_t light : shadowedLights_) {
        const bool cube = needsCube(scene.light(light));
        const auto old = std::find_if(slots_.begin(), slots_.end(),
                                      [&](const LocalSlot& s) { return s.light == light && s.cube == cube; });
        if (old != slots_.end())
            kept.push_back(*old);
        else
            fresh.push_back(light);
    }
    for (std::size_t light : fresh) {
        LocalSlot slot;
        slot.light = light;
        slot.cube = needsCube(scene.light(light));
        slot.layer = 0;
        while (std::any_of(kept.begin(), kept.end(),
                           [&](const LocalSlot& s) { return s.cube == slot.cube && s.layer == slot.layer; }))
            ++slot.layer;
        kept.push_back(slot);
    }
    slots_ = std::move(kept);
    int spotLayers = 0;
    int cubes = 0;
    for (const LocalSlot& slot : slots_) {
        int& layers = slot.cube ? cubes : spotLayers;
        layers = std::max(layers, slot.layer + 1);
    }
    ensureArrays(spotLayers, cubes);

    for (LocalSlot& slot : slots_) {
        // The packed light is the cache key: what the shaders see of it.
        const GpuLight& packed = scene.packedLights()[slot.light];
        if (slot.valid && sameLight(slot.renderedFor, packed) && slot.renderedVersion == scene.transformsVersion())
            continue;
        slot.cube ? renderCube(passes, slot) : renderSpot(passes, slot);
        slot.renderedFor = packed;
        slot.renderedVersion = scene.transformsVersion();
        slot.valid = true;
    }
    uniforms_.localShadowParams = glm::vec4(slots_.empty() ? 0.0f : 1.0f, 1.0f / static_cast<float>(sizes_.spot),
                                            1.0f / static_cast<float>(sizes_.cubeFace), 0.0f);
}

void ShadowMaps::renderSpot(FramePasses& passes, LocalSlot& slot)
{
    const GpuScene& scene = passes.scene();
    const Light light = scene.light(slot.light);
    const glm::vec3 position = light.position;
    const glm::vec3 axis = glm::normalize(light.direction);
    const float cutoff = light.cutoffDegrees;
    const float far = shadowFar(light, scene);
    const glm::vec3 up = std::abs(axis.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::mat4 viewProjection =
        glm::perspective(glm::radians(2.0f * cutoff + kSpotFovMarginDegrees), 1.0f, kNearFraction * far, far) *
        glm::lookAt(position, position + axis, up);
    renderDepth(passes, "shadow spot", spotArray_, slot.layer, sizes_.spot, viewProjection,
                [&](const Bounds& box) { return boxMayIntersectCone(box, position, axis, cutoff, far); });
    slot.gpu.viewProjection = viewProjection;
    slot.gpu.params = glm::vec4(1.0f, static_cast<float>(slot.layer), kNearFraction * far, far);
}

void ShadowMaps::renderCube(FramePasses& passes, LocalSlot& slot)
{
    const GpuScene& scene = passes.scene();
    const Light light = scene.light(slot.light);
    const glm::vec3 position = light.position;
    const float far = shadowFar(light, scene);
    const float near = kNearFraction * far;
    // The faces in GL's order (+X, −X, +Y, −Y, +Z, −Z) with the up vectors that make a 90°
    // perspective view of each match the cube map's texture coordinates.
    const std::array<std::pair<glm::vec3, glm::vec3>, 6> faces = {{
        {{1, 0, 0}, {0, -1, 0}},
        {{-1, 0, 0}, {0, -1, 0}},
        {{0, 1, 0}, {0, 0, 1}},
        {{0, -1, 0}, {0, 0, -1}},
        {{0, 0, 1}, {0, -1, 0}},
        {{0, 0, -1}, {0, -1, 0}},
    }};
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, near, far);
    const auto inRange = [&](const Bounds& box) { return boxIntersectsSphere(box, position, far); };
    for (int face = 0; face < 6; ++face)
        renderDepth(passes, "shadow point", cubeArray_, slot.layer * 6 + face, sizes_.cubeFace,
                    projection * glm::lookAt(position, position + faces[face].first, faces[face].second), inRange);
    slot.gpu.viewProjection = glm::mat4(1.0f);
    slot.gpu.params = glm::vec4(2.0f, static_cast<float>(slot.layer), near, far);
}

void ShadowMaps::renderDepth(FramePasses& passes, std::string_view name, const gl::DepthTextureArray& texture,
                             int layer, int size, const glm::mat4& viewProjection,
                             const std::function<bool(const Bounds&)>& keep)
{
    localFramebuffer_.attachDepthLayer(texture, layer);
    drawDepthPass(passes, name, localFramebuffer_, size, viewProjection, keep);
}

void ShadowMaps::drawDepthPass(FramePasses& passes, std::string_view name, const gl::Framebuffer& framebuffer, int size,
                               const glm::mat4& viewProjection, const std::function<bool(const Bounds&)>& keep)
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
                const gl::Program& program = depthProgram(variant);
                program.set(kLightViewProjectionLocation, viewProjection);
                return program;
            },
            keep);
    });
    ++passesRendered_;
}

const gl::Program& ShadowMaps::depthProgram(MaterialVariant variant)
{
    auto found = depthPrograms_.find(variant);
    if (found == depthPrograms_.end())
        found = depthPrograms_
                    .emplace(variant, gl::Program("shadow depth",
                                                  {{GL_VERTEX_SHADER, "shadow_depth.vert"},
                                                   {GL_FRAGMENT_SHADER, "shadow_depth.frag"}},
                                                  materialVariantDefines(variant, {})))
                    .first;
    return found->second;
}

void ShadowMaps::bind(bool ambientOcclusion)
{
    uniforms_.occlusionParams = glm::vec4(ambientOcclusion ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    uniformBuffer_.update(0, sizeof(ShadowingUniforms), &uniforms_);
    uniformBuffer_.bindBase(GL_UNIFORM_BUFFER, kShadowingUniformBinding);
    directionalMap_.bindUnit(kDirectionalShadowUnit);
    spotArray_.bindUnit(kSpotShadowUnit);
    cubeArray_.bindUnit(kPointShadowUnit);

    // Which slot each light has: rewritten only when the chosen lights change (it holds an
    // entry for every light, which may be a million). Never empty: a buffer bound to a storage
    // block must have storage.
    std::vector<std::size_t> slotLights;
    for (const LocalSlot& slot : slots_)
        slotLights.push_back(slot.light);
    const std::size_t lightCount = std::max<std::size_t>(lightCount_, 1);
    if (slotOfLightCapacity_ != lightCount || slotLights != uploadedSlotLights_) {
        std::vector<std::int32_t> slotOfLight(lightCount, -1);
        for (std::size_t i = 0; i < slotLights.size(); ++i)
            slotOfLight[slotLights[i]] = static_cast<std::int32_t>(i);
        slotOfLightBuffer_ =
            gl::Buffer("shadow slot of each light", slotOfLight.size() * sizeof(std::int32_t), slotOfLight.data(), 0);
        slotOfLightCapacity_ = lightCount;
        uploadedSlotLights_ = std::move(slotLights);
    }
    // The slots themselves: a few dozen bytes each, every frame.
    std::vector<GpuShadowSlot> slots(std::max<std::size_t>(slots_.size(), 1));
    for (std::size_t i = 0; i < slots_.size(); ++i)
        slots[i] = slots_[i].gpu;
    if (slotsCapacity_ < slots.size()) {
        slotsBuffer_ = gl::Buffer("shadow slots", slots.size() * sizeof(GpuShadowSlot), nullptr);
        slotsCapacity_ = slots.size();
    }
    slotsBuffer_.update(0, slots.size() * sizeof(GpuShadowSlot), slots.data());
    slotOfLightBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kShadowSlotOfLightBinding);
    slotsBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kShadowSlotsBinding);
}

}  // namespace manylights
