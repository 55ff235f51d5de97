// Lighting programs specialised for the kinds of light a scene has and its materials'
// shininesses.
//
// On llvmpipe a shader runs 8 or 16 pixels in lock step and executes both sides of every
// branch under a lane mask, so code for a kind of light the scene lacks still costs every
// (pixel, light) pair: a spot factor's pow, the other falloff. Each lighting program is
// therefore compiled per LightingFeatures, on first use, with the #defines of
// shaders/lib/lighting.glsl that leave out what the scene cannot need, and with its few
// integer shininesses as constants, whose powers are cheaper as multiplications than as pow()
// (docs/performance.md). The general program (LightingFeatures{}) handles every scene.
// The same variants also choose where the lights are read from (LightSource), and they carry
// what a technique's programs are all made for (TechniqueVariant): every dimension is one
// field of one typed key, ShaderVariant, whose one toDefines() gives the program's #defines.
#pragma once

#include <bit>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/Program.h"
#include "render/driver/DriverProfile.h"
#include "render/programs/GBufferLayout.h"
#include "render/programs/ProgramVariants.h"
#include "scene/Scene.h"

namespace manylights {

// The largest shininess, and the most distinct ones in a scene, that the lighting function
// raises to by multiplications (shaders/lib/specular_power.glsl; as large as any material's,
// kMaxShininess of scene/Shininess.h), and the most multiplications all of a scene's
// together may take: on llvmpipe one pow() costs about as much as 50 (docs/performance.md).
inline constexpr std::uint16_t kMaxSpecularExponent = 2048;
inline constexpr std::size_t kMaxSpecularExponents = 6;
inline constexpr int kSpecularMultiplicationBudget = 32;
// Distinct integer shininesses, ascending; empty where the lighting function takes pow().
using SpecularExponents = std::vector<std::uint16_t>;

// The multiplications x^n takes by squaring, n ≥ 1 (shaders/lib/specular_power.glsl
// integerPower): one per bit below n's highest, one more per set bit after the first.
constexpr int integerPowerMultiplications(std::uint16_t n) { return std::bit_width(n) - 1 + std::popcount(n) - 1; }

// What the scene holds that a lighting program may leave out: facts about the scene's lights,
// surfaces and frame, the same on every driver.
struct SceneFeatures {
    bool spotLights = true;
    bool classicFalloff = true;
    bool rangeFalloff = true;
    bool directionalLight = true;
    // What the frame's shadowing reads (GpuScene::setFrameShadowing): the directional light's
    // shadow map, the SSAO factor. Without them their factors are 1 and their lookups are left
    // out: on llvmpipe the switched-off lookups cost about a tenth of clustered's lighting
    // pass on the courtyard (docs/performance.md).
    bool directionalShadow = true;
    bool ambientOcclusion = true;
    // The shininesses of every surface the scene draws with a specular term where few enough
    // integers to raise N·H to by multiplications (specularExponentsOf), else empty. Whether
    // the programs multiply is the driver's policy (ShaderPolicy::multipliedSpecularPowers).
    SpecularExponents specularExponents{};
    // The reflection models the drawn surfaces use (DrawList::shadingModels): a program for one
    // of them leaves the other out (NO_BLINN_PHONG, NO_METALLIC_ROUGHNESS), so that a scene of
    // one model pays nothing for the other's code (llvmpipe runs both sides of a select).
    bool blinnPhong = true;
    bool metallicRoughness = true;
    // Whether the scene has an environment (render/environment/EnvironmentLight.h): a program
    // without leaves its code out (NO_ENVIRONMENT), so that a scene without one renders as it
    // did before environments, to the bit, and pays nothing for them.
    bool environment = true;

    auto operator<=>(const SceneFeatures&) const = default;
};

// How the driver profile wants the lighting code written (render/driver/DriverProfile.h):
// the same image either way, at different costs on different drivers.
struct ShaderPolicy {
    // The scene's integer shininesses raised by multiplications (SPECULAR_EXPONENTS; pow()
    // costs a quarter of a lighting pass on llvmpipe, docs/performance.md) rather than pow():
    // DriverChoices::multipliedSpecularPowers.
    bool multipliedSpecularPowers = true;
    // The light loops branch on a light's reach (BRANCH_ON_REACH) instead of testing first
    // and selecting: DriverChoices::branchOnLightReach.
    bool branchOnReach = false;

    auto operator<=>(const ShaderPolicy&) const = default;
};
ShaderPolicy shaderPolicyOf(const DriverChoices& driver);

// What a lighting program is specialised for: the scene's features under the driver's policy.
// `{}` is the general program, which handles every scene.
struct LightingFeatures {
    SceneFeatures scene{};
    ShaderPolicy policy{};

    auto operator<=>(const LightingFeatures&) const = default;
};

// What `lights` and the scene's directional light use. Animation moves lights but never
// changes their kind, so this holds for every frame of a scene.
SceneFeatures sceneFeaturesOf(const std::vector<Light>& lights, const std::optional<DirectionalLight>& directional);

// The distinct shininesses of the materials in `materials` with a specular term, ascending,
// when there are at most kMaxSpecularExponents, each is an integer in [1, kMaxSpecularExponent]
// and their integerPowerMultiplications sum to at most kSpecularMultiplicationBudget; else none.
// A material without a specular term (its specular colour and tint zero, as a light
// marker's) is shaded the same by any exponent and does not count; one with a
// metallic-roughness map has a shininess per texel and rules them out. Metallic-roughness
// materials (ShadingModel::MetallicRoughness) have no shininess and do not count.
SpecularExponents specularExponentsOf(const std::vector<const Material*>& materials);

// Where a lighting program reads the lights (shaders/lib/lights.glsl).
enum class LightSource : std::uint8_t {
    StorageBuffer,  // the whole light buffer, any light by index
    UniformWindow,  // the batch's window (render/programs/LightBatches.h: light windows); the caller
                    // binds it with GpuScene::bindLightWindow
    TexelBuffer,    // the whole light buffer as texels (render/programs/LightBatches.h: light texels),
                    // which GpuScene::bind binds
};

// The batch size of a pass that walks its lights from `source`: a window's worth from a
// uniform window, else kLightsPerBatch (render/programs/LightBatches.h).
std::uint32_t lightsPerBatch(LightSource source);

// What a mesh program (shaders/mesh.vert with a fragment shader calling lib/material.glsl's
// meshSurface()) reads for a material, one bit each: its texture maps, its alpha mask, its mesh's
// vertex colours. A mesh program is compiled per variant, with the bits as the constant
// MATERIAL_VARIANT: llvmpipe runs both sides of a branch, so a branch on a uniform would pay
// every map's lookups for every fragment (docs/performance.md), a `discard` that may run
// keeps the depth test from running before the fragment shader, and every varying a material
// might need costs every fragment of every material (about 10% of the G-buffer pass for the
// tint, coverage and back-face inputs together), so those are bits too.
using MaterialVariant = std::uint16_t;
inline constexpr MaterialVariant kDiffuseMapBit = 1;
inline constexpr MaterialVariant kSpecularMapBit = 2;
inline constexpr MaterialVariant kNormalMapBit = 4;
inline constexpr MaterialVariant kEmissiveMapBit = 8;
inline constexpr MaterialVariant kMetallicRoughnessMapBit = 16;  // in the specular map's unit
inline constexpr MaterialVariant kAlphaMaskBit = 32;
inline constexpr MaterialVariant kVertexColoursBit = 64;
inline constexpr MaterialVariant kSpecularTintBit = 128;             // Material::specularTint not zero
inline constexpr MaterialVariant kFlipBackFacesBit = 256;            // Sides::BothFlipped
inline constexpr MaterialVariant kBlendBit = 512;                    // AlphaMode::Blend: the coverage is the opacity
inline constexpr MaterialVariant kOpacityMapBit = 1024;              // Material::opacityMap
inline constexpr MaterialVariant kUvTransformsBit = 2048;            // a Material::uvTransforms other than the identity
inline constexpr MaterialVariant kMetallicRoughnessModelBit = 4096;  // ShadingModel::MetallicRoughness
inline constexpr MaterialVariant kOcclusionMapBit = 8192;            // Material::occlusionMap
// The bits that mean a texture is bound per draw (such draws are not instanced).
inline constexpr MaterialVariant kTextureBits = kDiffuseMapBit | kSpecularMapBit | kNormalMapBit | kEmissiveMapBit |
                                                kMetallicRoughnessMapBit | kOpacityMapBit | kOcclusionMapBit;
// What a depth-only pass (shaders/shadow_depth.*) needs of a variant: a masked surface's coverage.
inline constexpr MaterialVariant depthOnlyVariant(MaterialVariant variant)
{
    return (variant & kAlphaMaskBit) != 0 ? variant & (kAlphaMaskBit | kDiffuseMapBit | kVertexColoursBit) : 0;
}

// `defines` plus MATERIAL_VARIANT = `variant`: ShaderVariant{.material = variant}'s own, for a
// depth-only program that takes no other dimension of the key.
gl::Defines materialVariantDefines(MaterialVariant variant, gl::Defines defines);

// The key of a depth-only program (shaders/shadow_depth.frag behind the shadow map's or the
// shadow pages' vertex shader): its depth-only material variant alone, for ProgramVariants.
struct DepthOnlyVariant {
    MaterialVariant material = 0;
    gl::Defines toDefines(gl::Defines defines) const { return materialVariantDefines(material, std::move(defines)); }
    auto operator<=>(const DepthOnlyVariant&) const = default;
};

// What every program of a technique is made for (TechniqueOptions::shaders): the same for all
// of its draws and frames.
struct TechniqueVariant {
    // Count the (pixel, light) pairs evaluated into FrameTargets::lightEvaluations (COUNT_WORK;
    // --count-work, --view light-count). Costs an atomic per fragment, so timings taken with
    // it are not the technique's own.
    bool countWork = false;
    // The G-buffer the programs read (GBUFFER_COMPACT for the compact layout); must be the
    // layout of the FrameTargets the technique renders into (Renderer's).
    GBufferLayout gbufferLayout = kDefaultGBufferLayout;
    // Look up local lights' shadow maps (LOCAL_SHADOWS). Needed when the Renderer's shadows
    // have a local-light budget above 0; without it those lights shade unshadowed. A dimension
    // of its own because on llvmpipe the lookup code costs every (pixel, light) pair even when
    // no light has a map (it runs masked, not skipped): 5x the deferred lighting pass.
    bool localShadows = false;
    // The light lists' walk marks the shadow pages its pairs would read instead of shading
    // them (SHADOW_PAGE_MARKING: the shadow-page pool's marking pass, render/shadows/ShadowPool.h).
    bool markShadowPages = false;
    // The light lists' walk adds up, for each pair it would shade, the shadow texels per pixel
    // of the page its lookup reads instead of shading it (SHADOW_RESOLUTION_VIEW: --view
    // shadow-resolution, render/shadows/ShadowResolutionView.h).
    bool showShadowResolution = false;

    auto operator<=>(const TechniqueVariant&) const = default;
};

// One typed key for what a lighting program varies in (issue 46): the technique it is made
// for, the scene's features under the driver's policy, where the lights are read from, the
// material of a mesh program, how the light lists are read, and the passes that share one
// shader's files. LightingProgram caches its programs by it and compiles each from its
// toDefines(); only what never varies for a program (a grid's shape, render/culling/
// CullingVariant.h) is the program's own defines.
struct ShaderVariant {
    // The technique's dimensions: LightingProgram sets them to those it was made for.
    TechniqueVariant technique{};
    LightingFeatures lighting{};
    LightSource lights = LightSource::StorageBuffer;
    // A mesh program's material (MATERIAL_VARIANT); none for the full-screen and compute passes.
    std::optional<MaterialVariant> material{};
    // The light lists as R32UI texels (CLUSTER_LIST_TEXELS, render/culling/ClusterLists.h
    // readsTexels), and part 0 walking the global list (GLOBAL_LIGHT_LIST, hasGlobalList).
    bool listTexels = false;
    bool globalLightList = false;
    // forward.frag's depth pre-pass, which evaluates no light (DEPTH_PREPASS).
    bool depthPrepass = false;
    // transparent.frag looping over every light, forward's reference, instead of reading the
    // light grid (EVERY_LIGHT).
    bool everyLight = false;
    // tiled_quads.frag's bound on a quad's lights (MAX_TILE_LIGHTS; render/techniques/
    // TiledQuadsTechnique.h kTileLightBounds); 0 for every other program.
    std::uint32_t maxTileLights = 0;

    auto operator<=>(const ShaderVariant&) const = default;

    // `defines` (the program's own) plus this variant's: the technique's (GBUFFER_COMPACT,
    // COUNT_WORK, LOCAL_SHADOWS, SHADOW_PAGE_MARKING, SHADOW_RESOLUTION_VIEW); as the features allow NO_SPOT_LIGHTS,
    // ONLY_CLASSIC_FALLOFF / ONLY_RANGE_FALLOFF, NO_DIRECTIONAL_LIGHT, NO_DIRECTIONAL_SHADOW, NO_AMBIENT_OCCLUSION,
    // NO_BLINN_PHONG, NO_METALLIC_ROUGHNESS, NO_ENVIRONMENT, and SPECULAR_EXPONENT_COUNT with
    // SPECULAR_EXPONENTS; BRANCH_ON_REACH as the policy asks; the light source's (light
    // windows or texels); MATERIAL_VARIANT; CLUSTER_LIST_TEXELS, GLOBAL_LIGHT_LIST,
    // DEPTH_PREPASS, EVERY_LIGHT and MAX_TILE_LIGHTS.
    gl::Defines toDefines(gl::Defines defines) const;
};

// The programs of one set of shader files for one technique, cached by ShaderVariant.
class LightingProgram {
public:
    // Programs of `stages` for a technique of `technique`, each with `defines` (a grid's shape,
    // which no draw varies) and its key's.
    LightingProgram(std::string label, std::vector<gl::ShaderStage> stages, const TechniqueVariant& technique,
                    gl::Defines defines = {})
        : technique_(technique), programs_(std::move(label), std::move(stages), std::move(defines))
    {
    }

    // The program of `key` with its technique set to this program's, compiled the first time it
    // is asked for (throws manylights::Error as gl::Program does).
    const gl::Program& variant(ShaderVariant key) const
    {
        key.technique = technique_;
        return programs_.variant(key);
    }
    // The same for the key of these parts.
    const gl::Program& variant(const LightingFeatures& features, LightSource source = LightSource::StorageBuffer,
                               std::optional<MaterialVariant> material = std::nullopt) const
    {
        return variant(ShaderVariant{.lighting = features, .lights = source, .material = material});
    }

private:
    TechniqueVariant technique_;
    ProgramVariants<ShaderVariant> programs_;
};

}  // namespace manylights
