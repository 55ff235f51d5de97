// The specialisation of the lighting programs (render/LightingPrograms.h): which features a
// scene's lights have, which #defines they give, and one compiled variant per feature set.
// That each variant shades correctly is the image tests' work: every technique against
// forward and the analytic scenes, over scenes of points only (ONLY_RANGE_FALLOFF,
// NO_DIRECTIONAL_LIGHT), spots with classic falloff, and spots_and_points, whose spots, both
// falloffs and directional light need the general program (also a golden image).
#include <gtest/gtest.h>

#include <algorithm>

#include "GlContextTest.h"
#include "core/Error.h"
#include "render/LightBatches.h"
#include "render/LightingPrograms.h"
#include "render/Technique.h"

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
    const LightingFeatures points = lightingFeaturesOf({lightOf(LightType::Point, Falloff::Classic)}, std::nullopt);
    EXPECT_FALSE(points.spotLights);
    EXPECT_TRUE(points.classicFalloff);
    EXPECT_FALSE(points.rangeFalloff);
    EXPECT_FALSE(points.directionalLight);

    const LightingFeatures mixed = lightingFeaturesOf(
        {lightOf(LightType::Point, Falloff::Classic), lightOf(LightType::Spot, Falloff::Range)}, DirectionalLight{});
    EXPECT_TRUE(mixed.spotLights);
    EXPECT_TRUE(mixed.classicFalloff);
    EXPECT_TRUE(mixed.rangeFalloff);
    EXPECT_TRUE(mixed.directionalLight);
}

TEST(LightingFeatures, DefinesLeaveOutOnlyWhatIsAbsent)
{
    const gl::Defines general = lightingFeatureDefines(LightingFeatures{}, {});
    EXPECT_TRUE(general.empty());

    const gl::Defines points =
        lightingFeatureDefines(lightingFeaturesOf({lightOf(LightType::Point, Falloff::Classic)}, std::nullopt), {});
    EXPECT_TRUE(hasDefine(points, "NO_SPOT_LIGHTS"));
    EXPECT_TRUE(hasDefine(points, "ONLY_CLASSIC_FALLOFF"));
    EXPECT_FALSE(hasDefine(points, "ONLY_RANGE_FALLOFF"));
    EXPECT_TRUE(hasDefine(points, "NO_DIRECTIONAL_LIGHT"));

    const gl::Defines spots =
        lightingFeatureDefines(lightingFeaturesOf({lightOf(LightType::Spot, Falloff::Range)}, DirectionalLight{}), {});
    EXPECT_FALSE(hasDefine(spots, "NO_SPOT_LIGHTS"));
    EXPECT_TRUE(hasDefine(spots, "ONLY_RANGE_FALLOFF"));
    EXPECT_FALSE(hasDefine(spots, "ONLY_CLASSIC_FALLOFF"));
    EXPECT_FALSE(hasDefine(spots, "NO_DIRECTIONAL_LIGHT"));
}

class LightingProgramTest : public GlContextTest {};

TEST_F(LightingProgramTest, EachFeatureSetCompilesOnceToItsOwnProgram)
{
    const LightingProgram program("deferred lighting",
                                  {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred.frag"}},
                                  shaderDefines({}));
    const LightingFeatures points{
        .spotLights = false, .classicFalloff = true, .rangeFalloff = false, .directionalLight = false};
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

TEST_F(LightingProgramTest, MeshProgramsCompileOncePerSetOfMaterialMaps)
{
    const LightingProgram program("geometry pass",
                                  {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}}, {});
    const gl::Program& plain = program.variant(LightingFeatures{}, LightSource::StorageBuffer, MaterialVariant{0});
    const gl::Program& textured = program.variant(LightingFeatures{}, LightSource::StorageBuffer,
                                                  MaterialVariant{kDiffuseMapBit | kSpecularMapBit});
    EXPECT_NE(plain.id(), textured.id());
    EXPECT_EQ(&program.variant(LightingFeatures{}, LightSource::StorageBuffer, MaterialVariant{0}), &plain);
    // The normal map's scale is a uniform only of the programs that sample a normal map
    // (render/GpuScene.cpp sets it only for them).
    EXPECT_EQ(glGetUniformLocation(textured.id(), "materialNormalScale"), -1);
    const gl::Program& normalMapped = program.variant(LightingFeatures{}, LightSource::StorageBuffer, kNormalMapBit);
    EXPECT_NE(glGetUniformLocation(normalMapped.id(), "materialNormalScale"), -1);
    // A mesh program must say which maps it samples.
    const std::vector<gl::ShaderStage> stages = {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}};
    EXPECT_THROW(gl::Program("no maps given", stages), Error);
}

}  // namespace
}  // namespace manylights
