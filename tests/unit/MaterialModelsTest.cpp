// The scene file's metallic-roughness materials (docs/scene-format.md, "Materials"): what they
// load as, and the exact message of each mistake (a key of the other model, a value out of
// range, a wrong type, a number that is not one); and the mapping of model files' materials to
// Blinn-Phong (scene/MaterialModels.h, `"model_materials"`).
#include <gtest/gtest.h>

#include <string>

#include "scene/MaterialModels.h"
#include "scene/SceneLoader.h"
#include "scene/Shininess.h"
#include "tests/unit/SceneFileTestSupport.h"

namespace manylights {
namespace {

using test::errorOf;
using test::parse;

TEST(MetallicRoughnessMaterials, KeysMakeAMetallicRoughnessMaterial)
{
    const Scene scene = parse(R"json({"materials": {
        "gold": {"base_color": [1, 0.8, 0.3], "metallic": 1, "roughness": 0.25, "emissive": [0.1, 0, 0]},
        "plastic": {"roughness": 0.5},
        "old": {"diffuse": [0.5, 0.5, 0.5]}}})json");
    ASSERT_EQ(scene.materials.size(), 3u);
    const Material& gold = scene.materials[0];
    EXPECT_EQ(gold.model, ShadingModel::MetallicRoughness);
    EXPECT_EQ(gold.baseColor, glm::vec3(1.0f, 0.8f, 0.3f));
    EXPECT_FLOAT_EQ(gold.metallicFactor, 1.0f);
    EXPECT_FLOAT_EQ(gold.roughnessFactor, 0.25f);
    EXPECT_EQ(gold.emissive, glm::vec3(0.1f, 0.0f, 0.0f));
    // The defaults of the other keys: a grey dielectric.
    const Material& plastic = scene.materials[1];
    EXPECT_EQ(plastic.model, ShadingModel::MetallicRoughness);
    EXPECT_EQ(plastic.baseColor, glm::vec3(0.8f));
    EXPECT_FLOAT_EQ(plastic.metallicFactor, 0.0f);
    EXPECT_FLOAT_EQ(plastic.roughnessFactor, 0.5f);
    EXPECT_EQ(scene.materials[2].model, ShadingModel::BlinnPhong);
}

TEST(MetallicRoughnessMaterials, MapsGoToTheirSlots)
{
    const Scene scene = parse(R"json({"materials": {"m": {"base_color_map": "textures/brick.png",
        "metallic_roughness_map": "textures/brick.png", "occlusion_map": "textures/brick.png",
        "normal_map": "textures/brick.png"}}})json");
    const Material& m = scene.materials.at(0);
    EXPECT_EQ(m.model, ShadingModel::MetallicRoughness);
    EXPECT_FALSE(m.diffuseMap.empty());
    EXPECT_FALSE(m.metallicRoughnessMap.empty());
    EXPECT_FALSE(m.occlusionMap.empty());
    EXPECT_FALSE(m.normalMap.empty());
    EXPECT_TRUE(m.specularMap.empty());
}

struct BadMaterial {
    const char* name;
    const char* json;
    const char* message;
};

class BadMetallicRoughness : public ::testing::TestWithParam<BadMaterial> {};

TEST_P(BadMetallicRoughness, IsAOneLineErrorNamingTheKey) { EXPECT_EQ(errorOf(GetParam().json), GetParam().message); }

constexpr const char* kMixing = "': a material is either Blinn-Phong (diffuse, specular, shininess) or "
                                "metallic-roughness (base_color, metallic, roughness)";

INSTANTIATE_TEST_SUITE_P(
    Cases, BadMetallicRoughness,
    ::testing::Values(
        BadMaterial{"MetallicAboveOne", R"json({"materials": {"m": {"metallic": 1.5}}})json",
                    "scene.json: /materials/m/metallic: must be in [0, 1], got 1.5"},
        BadMaterial{"RoughnessBelowZero", R"json({"materials": {"m": {"roughness": -0.25}}})json",
                    "scene.json: /materials/m/roughness: must be in [0, 1], got -0.25"},
        BadMaterial{"MetallicString", R"json({"materials": {"m": {"metallic": "1"}}})json",
                    "scene.json: /materials/m/metallic: expected a number, got a string"},
        BadMaterial{"BaseColorTooShort", R"json({"materials": {"m": {"base_color": [1, 1]}}})json",
                    "scene.json: /materials/m/base_color: expected an array of 3 numbers, got an array of 2 elements"},
        BadMaterial{"BaseColorNegative", R"json({"materials": {"m": {"base_color": [1, -1, 1]}}})json",
                    "scene.json: /materials/m/base_color/1: must be >= 0, got -1"}),
    [](const ::testing::TestParamInfo<BadMaterial>& param) { return param.param.name; });

TEST(MetallicRoughnessMaterials, MixingNamesBothKeys)
{
    EXPECT_EQ(errorOf(R"json({"materials": {"m": {"base_color": [1, 1, 1], "diffuse": [1, 1, 1]}}})json"),
              std::string("scene.json: /materials/m/diffuse: 'diffuse' cannot be mixed with 'base_color") + kMixing);
    EXPECT_EQ(errorOf(R"json({"materials": {"m": {"metallic": 0.5, "shininess": 8}}})json"),
              std::string("scene.json: /materials/m/shininess: 'shininess' cannot be mixed with 'metallic") + kMixing);
    EXPECT_EQ(errorOf(R"json({"materials": {"m": {"roughness": 0.5, "specular_map": "textures/brick.png"}}})json"),
              std::string("scene.json: /materials/m/specular_map: 'specular_map' cannot be mixed with 'roughness") +
                  kMixing);
}

TEST(MetallicRoughnessMaterials, ModelMaterialsIsOneOfTheModels)
{
    const std::string message = errorOf(R"json({"model_materials": "phong"})json");
    EXPECT_EQ(message.rfind("scene.json: /model_materials: ", 0), 0u) << message;
    EXPECT_NO_THROW(parse(R"json({"model_materials": "blinn-phong"})json"));
}

TEST(MetallicRoughnessMaterials, NotANumberIsASyntaxError)
{
    // JSON has no NaN: the reader stops at it, naming the line and column.
    const std::string message = errorOf("{\"materials\": {\"m\": {\"metallic\": NaN}}}");
    EXPECT_EQ(message.rfind("scene.json:1:", 0), 0u) << message;
    // A number beyond a float's range would be an infinity on the GPU.
    const std::string huge = errorOf(R"json({"materials": {"m": {"roughness": 1e39}}})json");
    EXPECT_EQ(huge.rfind("scene.json: /materials/m/roughness: ", 0), 0u) << huge;
}

TEST(MetallicRoughnessMaterials, BlinnPhongMappingIsTheMappingBeforeIssue31)
{
    Material m;
    m.model = ShadingModel::MetallicRoughness;
    m.baseColor = glm::vec3(0.5f, 0.25f, 1.0f);
    m.metallicFactor = 0.5f;
    m.roughnessFactor = 0.5f;
    m.occlusionMap = "ao.png";
    const Material mapped = blinnPhongMapping(m);
    EXPECT_EQ(mapped.model, ShadingModel::BlinnPhong);
    EXPECT_EQ(mapped.diffuse, glm::vec3(0.25f, 0.125f, 0.5f));
    EXPECT_EQ(mapped.specular, glm::vec3(0.02f));
    EXPECT_EQ(mapped.specularTint, glm::vec3(0.25f, 0.125f, 0.5f));
    EXPECT_FLOAT_EQ(mapped.shininess, blinnPhongExponent(0.5f));
    EXPECT_TRUE(mapped.occlusionMap.empty());
    Material plain;
    plain.diffuse = glm::vec3(0.3f);
    EXPECT_EQ(blinnPhongMapping(plain).diffuse, glm::vec3(0.3f));
}

}  // namespace
}  // namespace manylights
