#include "render/programs/LightingPrograms.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "render/programs/LightBatches.h"

namespace manylights {

SceneFeatures sceneFeaturesOf(const std::vector<Light>& lights, const std::optional<DirectionalLight>& directional)
{
    const auto any = [&](auto predicate) { return std::any_of(lights.begin(), lights.end(), predicate); };
    return {
        .spotLights = any([](const Light& light) { return light.type == LightType::Spot; }),
        .classicFalloff = any([](const Light& light) { return light.falloff == Falloff::Classic; }),
        .rangeFalloff = any([](const Light& light) { return light.falloff != Falloff::Classic; }),
        .directionalLight = directional.has_value(),
        .directionalShadow = directional.has_value() && directional->shadows,
    };
}

ShaderPolicy shaderPolicyOf(const DriverChoices& driver)
{
    return {.multipliedSpecularPowers = driver.multipliedSpecularPowers, .branchOnReach = driver.branchOnLightReach};
}

SpecularExponents specularExponentsOf(const std::vector<const Material*>& materials)
{
    std::set<float> shininesses;
    for (const Material* material : materials) {
        if (material->model == ShadingModel::MetallicRoughness)
            continue;
        if (!material->metallicRoughnessMap.empty())
            return {};
        if (material->specular != glm::vec3{0.0f} || material->specularTint != glm::vec3{0.0f})
            shininesses.insert(material->shininess);
    }
    if (shininesses.size() > kMaxSpecularExponents)
        return {};
    SpecularExponents exponents;
    int multiplications = 0;
    for (const float shininess : shininesses) {  // ascending
        if (shininess < 1.0f || shininess > kMaxSpecularExponent || std::floor(shininess) != shininess)
            return {};
        exponents.push_back(static_cast<std::uint16_t>(shininess));
        multiplications += integerPowerMultiplications(exponents.back());
    }
    return multiplications <= kSpecularMultiplicationBudget ? exponents : SpecularExponents{};
}

gl::Defines materialVariantDefines(MaterialVariant variant, gl::Defines defines)
{
    defines.emplace_back("MATERIAL_VARIANT", std::to_string(variant));
    return defines;
}

std::uint32_t lightsPerBatch(LightSource source)
{
    return source == LightSource::UniformWindow ? kLightsPerWindow : kLightsPerBatch;
}

gl::Defines ShaderVariant::toDefines(gl::Defines defines) const
{
    if (technique.gbufferLayout == GBufferLayout::Compact)
        defines.emplace_back("GBUFFER_COMPACT", "1");
    if (technique.countWork)
        defines.emplace_back("COUNT_WORK", "1");
    if (technique.localShadows)
        defines.emplace_back("LOCAL_SHADOWS", "1");
    if (technique.markShadowPages)
        defines.emplace_back("SHADOW_PAGE_MARKING", "1");
    if (technique.showShadowResolution)
        defines.emplace_back("SHADOW_RESOLUTION_VIEW", "1");

    const SceneFeatures& features = lighting.scene;
    if (!features.spotLights)
        defines.emplace_back("NO_SPOT_LIGHTS", "1");
    // A scene without local lights takes either; nothing is evaluated.
    if (!features.rangeFalloff)
        defines.emplace_back("ONLY_CLASSIC_FALLOFF", "1");
    else if (!features.classicFalloff)
        defines.emplace_back("ONLY_RANGE_FALLOFF", "1");
    if (!features.directionalLight)
        defines.emplace_back("NO_DIRECTIONAL_LIGHT", "1");
    if (!features.directionalShadow)
        defines.emplace_back("NO_DIRECTIONAL_SHADOW", "1");
    if (!features.ambientOcclusion)
        defines.emplace_back("NO_AMBIENT_OCCLUSION", "1");
    // A program for no surfaces at all (a scene without objects) keeps Blinn-Phong.
    if (!features.metallicRoughness)
        defines.emplace_back("NO_METALLIC_ROUGHNESS", "1");
    else if (!features.blinnPhong)
        defines.emplace_back("NO_BLINN_PHONG", "1");
    if (lighting.policy.branchOnReach)
        defines.emplace_back("BRANCH_ON_REACH", "1");
    if (!features.environment)
        defines.emplace_back("NO_ENVIRONMENT", "1");
    if (lighting.policy.multipliedSpecularPowers && !features.specularExponents.empty()) {
        std::string list;
        for (const std::uint16_t exponent : features.specularExponents)
            list += (list.empty() ? "" : ", ") + std::to_string(exponent) + "u";
        defines.emplace_back("SPECULAR_EXPONENT_COUNT", std::to_string(features.specularExponents.size()));
        defines.emplace_back("SPECULAR_EXPONENTS", list);
    }

    if (lights == LightSource::UniformWindow) {
        defines.emplace_back("LIGHT_WINDOW_BINDING", std::to_string(kLightWindowBinding));
        defines.emplace_back("LIGHTS_PER_WINDOW", std::to_string(kLightsPerWindow));
    }
    if (lights == LightSource::TexelBuffer)
        defines.emplace_back("LIGHT_TEXELS", "1");
    if (material)
        defines = materialVariantDefines(*material, std::move(defines));
    if (listTexels)
        defines.emplace_back("CLUSTER_LIST_TEXELS", "1");
    if (globalLightList)
        defines.emplace_back("GLOBAL_LIGHT_LIST", "1");
    if (depthPrepass)
        defines.emplace_back("DEPTH_PREPASS", "1");
    if (everyLight)
        defines.emplace_back("EVERY_LIGHT", "1");
    if (maxTileLights > 0)
        defines.emplace_back("MAX_TILE_LIGHTS", std::to_string(maxTileLights) + "u");
    return defines;
}

}  // namespace manylights
