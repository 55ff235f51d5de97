// The specialisation of the lighting programs (render/programs/LightingPrograms.h): which features a
// scene's lights have, which #defines they give, and one compiled variant per feature set.
// That each variant shades correctly is the image tests' work: every technique against
// forward and the analytic scenes, over scenes of points only (ONLY_RANGE_FALLOFF,
// NO_DIRECTIONAL_LIGHT), spots with classic falloff, and spots_and_points, whose spots, both
// falloffs and directional light need the general program (also a golden image).
#include <gtest/gtest.h>

#include <algorithm>

#include "GlContextTest.h"
#include "core/Error.h"
#include "render/programs/LightBatches.h"
#include "render/programs/LightingPrograms.h"
#include "render/scene/GpuScene.h"
#include "render/techniques/Technique.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

Light lightOf(LightType type, Falloff falloff)
{
    Light light;
    light.type = type;
    light.falloff = falloff;
    return light;
}

bool hasDefine(const gl::Defines& defines, const std::string& name)
{
    return std::any_of(defines.begin(), defines.end(), [&](const auto& define) { return define.first == name; });
}

TEST(LightingFeatures, ComeFromTheKindsOfLightPresent)
{
    const SceneFeatures points = sceneFeaturesOf({lightOf(LightType::Point, Falloff::Classic)}, std::nullopt);
    EXPECT_FALSE(points.spotLights);
    EXPECT_TRUE(points.classicFalloff);
    EXPECT_FALSE(points.rangeFalloff);
    EXPECT_FALSE(points.directionalLight);

    const SceneFeatures mixed = sceneFeaturesOf(
        {lightOf(LightType::Point, Falloff::Classic), lightOf(LightType::Spot, Falloff::Range)}, DirectionalLight{});
    EXPECT_TRUE(mixed.spotLights);
    EXPECT_TRUE(mixed.classicFalloff);
    EXPECT_TRUE(mixed.rangeFalloff);
    EXPECT_TRUE(mixed.directionalLight);
}

// The features' defines, without the technique's (the seed layout, which adds none).
gl::Defines featureDefines(const LightingFeatures& features)
{
    return ShaderVariant{.technique = {.gbufferLayout = GBufferLayout::Seed}, .lighting = features}.toDefines({});
}

TEST(LightingFeatures, DefinesLeaveOutOnlyWhatIsAbsent)
{
    const gl::Defines general = featureDefines(LightingFeatures{});
    EXPECT_TRUE(general.empty());

    const gl::Defines points =
        featureDefines({.scene = sceneFeaturesOf({lightOf(LightType::Point, Falloff::Classic)}, std::nullopt)});
    EXPECT_TRUE(hasDefine(points, "NO_SPOT_LIGHTS"));
    EXPECT_TRUE(hasDefine(points, "ONLY_CLASSIC_FALLOFF"));
    EXPECT_FALSE(hasDefine(points, "ONLY_RANGE_FALLOFF"));
    EXPECT_TRUE(hasDefine(points, "NO_DIRECTIONAL_LIGHT"));

    const gl::Defines spots =
        featureDefines({.scene = sceneFeaturesOf({lightOf(LightType::Spot, Falloff::Range)}, DirectionalLight{})});
    EXPECT_FALSE(hasDefine(spots, "NO_SPOT_LIGHTS"));
    EXPECT_TRUE(hasDefine(spots, "ONLY_RANGE_FALLOFF"));
    EXPECT_FALSE(hasDefine(spots, "ONLY_CLASSIC_FALLOFF"));
    EXPECT_FALSE(hasDefine(spots, "NO_DIRECTIONAL_LIGHT"));
}

TEST(LightingFeatures, SpecularExponentsAreTheFewCheapIntegerShininessesOfTheSpecularMaterials)
{
    const auto materialOf = [](float shininess, glm::vec3 specular) {
        Material material;
        material.shininess = shininess;
        material.specular = specular;
        return material;
    };
    const SpecularExponents none{};
    const Material shiny16 = materialOf(16.0f, glm::vec3{0.5f});
    const Material alsoShiny16 = materialOf(16.0f, glm::vec3{0.1f, 0.0f, 0.0f});
    const Material matte = materialOf(5.0f, glm::vec3{0.0f});  // no specular term: any exponent shades it the same
    EXPECT_EQ(specularExponentsOf({&shiny16, &alsoShiny16, &matte}), (SpecularExponents{16}));
    EXPECT_EQ(specularExponentsOf({&matte}), none);  // nothing specular: nothing to raise
    EXPECT_EQ(specularExponentsOf({}), none);

    // Distinct ones ascending, up to kMaxSpecularExponents of them.
    const Material shiny64 = materialOf(64.0f, glm::vec3{0.5f});
    const Material shiny13 = materialOf(13.0f, glm::vec3{0.5f});
    const Material shiny48 = materialOf(48.0f, glm::vec3{0.5f});
    const Material shiny24 = materialOf(24.0f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&shiny64, &shiny16, &shiny13, &alsoShiny16, &shiny48}),
              (SpecularExponents{13, 16, 48, 64}));
    const Material shiny2 = materialOf(2.0f, glm::vec3{0.5f});
    const Material shiny3 = materialOf(3.0f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&shiny64, &shiny16, &shiny13, &shiny48, &shiny24, &shiny3}),
              (SpecularExponents{3, 13, 16, 24, 48, 64}));
    // Seven: pow(), though their multiplications (29) are within the budget.
    EXPECT_EQ(specularExponentsOf({&shiny64, &shiny16, &shiny13, &shiny48, &shiny24, &shiny3, &shiny2}), none);

    // Where their multiplications would cost more than pow(): 12 + 13 + 13 + 14 of them.
    const Material shiny127 = materialOf(127.0f, glm::vec3{0.5f});
    const Material shiny191 = materialOf(191.0f, glm::vec3{0.5f});
    const Material shiny223 = materialOf(223.0f, glm::vec3{0.5f});
    const Material shiny255 = materialOf(255.0f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&shiny127, &shiny191, &shiny223, &shiny255}), none);
    EXPECT_EQ(specularExponentsOf({&shiny255, &shiny16}), (SpecularExponents{16, 255}));
    EXPECT_EQ(integerPowerMultiplications(1), 0);
    EXPECT_EQ(integerPowerMultiplications(16), 4);     // four squarings
    EXPECT_EQ(integerPowerMultiplications(13), 5);     // 1101: three squarings, two products
    EXPECT_EQ(integerPowerMultiplications(2047), 20);  // the most one exponent takes
    EXPECT_LE(integerPowerMultiplications(2047), kSpecularMultiplicationBudget);

    const Material fractional = materialOf(12.5f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&shiny16, &fractional}), none);
    const Material below = materialOf(0.5f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&below}), none);
    const Material smallest = materialOf(1.0f, glm::vec3{0.5f});
    const Material largest = materialOf(kMaxSpecularExponent, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&largest, &smallest}), (SpecularExponents{1, kMaxSpecularExponent}));
    const Material tooLarge = materialOf(kMaxSpecularExponent + 1.0f, glm::vec3{0.5f});
    EXPECT_EQ(specularExponentsOf({&tooLarge}), none);

    // A metal's specular colour is its tint alone; a metallic-roughness map varies the exponent
    // per texel, even where the material's own specular is zero.
    Material metal = materialOf(16.0f, glm::vec3{0.0f});
    metal.specularTint = glm::vec3{0.9f};
    EXPECT_EQ(specularExponentsOf({&metal}), (SpecularExponents{16}));
    Material mapped = materialOf(16.0f, glm::vec3{0.0f});
    mapped.metallicRoughnessMap = "roughness.png";
    EXPECT_EQ(specularExponentsOf({&shiny16, &mapped}), none);

    LightingFeatures features;
    EXPECT_FALSE(hasDefine(featureDefines(features), "SPECULAR_EXPONENT_COUNT"));
    features.scene.specularExponents = {13, 40};
    const gl::Defines defines = featureDefines(features);
    const gl::Defines expected = {{"SPECULAR_EXPONENT_COUNT", "2"}, {"SPECULAR_EXPONENTS", "13u, 40u"}};
    EXPECT_EQ(defines, expected);
    // The same scene under a policy of pow() (the GPU profile's) gets none.
    features.policy.multipliedSpecularPowers = false;
    EXPECT_FALSE(hasDefine(featureDefines(features), "SPECULAR_EXPONENT_COUNT"));
}

class LightingProgramTest : public GlContextTest {};

TEST_F(LightingProgramTest, SceneTakesTheSpecularExponentsOfWhatItDraws)
{
    const auto exponentsOf = [](const std::string& materials, const std::string& objects,
                                DriverProfile profile = DriverProfile::Software) {
        const Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
            "light_markers": {"radius": 0.1}, "lights": [{"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 5}],
            "materials": )" + materials + R"(, "objects": )" +
                                           objects + "}",
                                       "<specular exponent test>", ".");
        const LightingFeatures features =
            GpuScene(scene, expandLights(scene, std::nullopt), resolveDriverChoices({.profile = profile}))
                .lightingFeatures();
        return features.policy.multipliedSpecularPowers ? features.scene.specularExponents : SpecularExponents{};
    };
    // Measured on llvmpipe only: the GPU profile's policy keeps pow() (DriverChoices).
    EXPECT_EQ(exponentsOf(R"({"a": {"specular": [0.5, 0.5, 0.5], "shininess": 16}})",
                          R"([{"mesh": {"primitive": "box", "size": [1, 1, 1]}, "material": "a"}])",
                          DriverProfile::Gpu),
              SpecularExponents{});
    const std::string materials = R"({"a": {"specular": [0.5, 0.5, 0.5], "shininess": 16},
                                      "b": {"specular": [0.5, 0.5, 0.5], "shininess": 40},
                                      "c": {"specular": [0.5, 0.5, 0.5], "shininess": 40.5}})";
    // The markers (no specular term) do not count, nor does a material no object uses.
    EXPECT_EQ(exponentsOf(materials, R"([{"mesh": {"primitive": "box", "size": [1, 1, 1]}, "material": "a"}])"),
              (SpecularExponents{16}));
    EXPECT_EQ(exponentsOf(materials, R"([{"mesh": {"primitive": "box", "size": [1, 1, 1]}, "material": "b"},
                                        {"mesh": {"primitive": "sphere", "radius": 1}, "material": "a"}])"),
              (SpecularExponents{16, 40}));
    EXPECT_EQ(exponentsOf(materials, R"([{"mesh": {"primitive": "box", "size": [1, 1, 1]}, "material": "c"}])"),
              SpecularExponents{});
}

TEST_F(LightingProgramTest, EachFeatureSetCompilesOnceToItsOwnProgram)
{
    const LightingProgram program("deferred lighting",
                                  {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred.frag"}},
                                  TechniqueVariant{});
    const LightingFeatures points{
        .scene = {.spotLights = false, .classicFalloff = true, .rangeFalloff = false, .directionalLight = false}};
    const gl::Program& general = program.variant(LightingFeatures{});
    const gl::Program& specialised = program.variant(points);
    EXPECT_NE(general.id(), 0u);
    EXPECT_NE(specialised.id(), general.id());
    EXPECT_EQ(&program.variant(points), &specialised);
    EXPECT_EQ(&program.variant(LightingFeatures{}), &general);
    // The light window is one more axis of the same cache.
    if (lightWindowsSupported()) {
        const gl::Program& windowed = program.variant(points, LightSource::UniformWindow);
        EXPECT_NE(windowed.id(), specialised.id());
        EXPECT_EQ(&program.variant(points, LightSource::UniformWindow), &windowed);
    }
}

TEST(ShaderVariantKey, TheTechniquesDimensionsAreItsDefines)
{
    // The seed layout and no counting or local shadows: nothing of the technique's.
    EXPECT_TRUE(ShaderVariant{.technique = {.gbufferLayout = GBufferLayout::Seed}}.toDefines({}).empty());
    const gl::Defines technique =
        ShaderVariant{.technique = {.countWork = true, .gbufferLayout = GBufferLayout::Compact, .localShadows = true}}
            .toDefines({});
    const gl::Defines expected = {{"GBUFFER_COMPACT", "1"}, {"COUNT_WORK", "1"}, {"LOCAL_SHADOWS", "1"}};
    EXPECT_EQ(technique, expected);
    // The passes that share a shader's files are dimensions of the same key.
    const gl::Defines passes =
        ShaderVariant{.technique = {.gbufferLayout = GBufferLayout::Seed}, .depthPrepass = true, .maxTileLights = 64}
            .toDefines({});
    const gl::Defines expectedPasses = {{"DEPTH_PREPASS", "1"}, {"MAX_TILE_LIGHTS", "64u"}};
    EXPECT_EQ(passes, expectedPasses);
}

TEST_F(LightingProgramTest, AProgramsVariantsAreAllOfTheTechniqueItWasMadeFor)
{
    const std::vector<gl::ShaderStage> stages = {{GL_VERTEX_SHADER, "fullscreen.vert"},
                                                 {GL_FRAGMENT_SHADER, "deferred.frag"}};
    const LightingProgram counting("deferred lighting", stages, TechniqueVariant{.countWork = true});
    const LightingProgram plain("deferred lighting", stages, TechniqueVariant{});
    // A key's technique is set to the program's: asking for another's gives the same program.
    const gl::Program& counted = counting.variant(ShaderVariant{});
    EXPECT_EQ(&counting.variant(ShaderVariant{.technique = {.countWork = false}}), &counted);
    EXPECT_EQ(&counting.variant(ShaderVariant{.technique = {.countWork = true}}), &counted);
    EXPECT_NE(plain.variant(ShaderVariant{}).id(), counted.id());
}

TEST_F(LightingProgramTest, MeshProgramsCompileOncePerSetOfMaterialMaps)
{
    const LightingProgram program("geometry pass",
                                  {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                                  TechniqueVariant{.gbufferLayout = GBufferLayout::Seed});
    const gl::Program& plain = program.variant(LightingFeatures{}, LightSource::StorageBuffer, MaterialVariant{0});
    const gl::Program& textured = program.variant(LightingFeatures{}, LightSource::StorageBuffer,
                                                  MaterialVariant{kDiffuseMapBit | kSpecularMapBit});
    EXPECT_NE(plain.id(), textured.id());
    EXPECT_EQ(&program.variant(LightingFeatures{}, LightSource::StorageBuffer, MaterialVariant{0}), &plain);
    // The normal map's scale is a uniform only of the programs that sample a normal map
    // (render/scene/DrawList.cpp sets it only for them).
    EXPECT_EQ(glGetUniformLocation(textured.id(), "materialNormalScale"), -1);
    const gl::Program& normalMapped = program.variant(LightingFeatures{}, LightSource::StorageBuffer, kNormalMapBit);
    EXPECT_NE(glGetUniformLocation(normalMapped.id(), "materialNormalScale"), -1);
    // A mesh program must say which maps it samples.
    const std::vector<gl::ShaderStage> stages = {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}};
    EXPECT_THROW(gl::Program("no maps given", stages), Error);
}

}  // namespace
}  // namespace manylights
