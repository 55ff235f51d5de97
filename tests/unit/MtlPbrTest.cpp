// MTL's PBR extension (docs/scene-format.md, "OBJ and MTL"): Pr, Pm, map_Pr and map_Pm make a
// metallic-roughness material whose base colour is Kd; what stays Blinn-Phong; the errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "scene/ObjLoader.h"
#include "tests/unit/ErrorOf.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

// Texture maps of the library resolve against its directory: the scene tests' textures.
const fs::path kTextures = fs::path(MANYLIGHTS_TEST_DATA_DIR) / "scene" / "textures";

const char* kQuadUsing = "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl m\nf 1 2 3\n";

Model loadWithLibrary(const std::string& mtl, Warnings& warnings)
{
    const MtlSource source = [&](const std::string& name) -> std::optional<std::string> {
        return name == "lib.mtl" ? std::optional<std::string>(mtl) : std::nullopt;
    };
    return loadObjModelText(kQuadUsing, "quad.obj", kTextures, source, warnings);
}

Material materialOf(const std::string& mtl)
{
    Warnings warnings;
    const Model model = loadWithLibrary(mtl, warnings);
    EXPECT_EQ(model.materials.size(), 1u);
    return model.materials.at(0);
}

TEST(MtlPbr, RoughnessAndMetallicMakeAMetallicRoughnessMaterial)
{
    const Material m = materialOf("newmtl m\nKd 0.8 0.6 0.2\nKs 0.5 0.5 0.5\nPr 0.3\nPm 1\nmap_Kd brick.png\n");
    EXPECT_EQ(m.model, ShadingModel::MetallicRoughness);
    EXPECT_EQ(m.baseColor, glm::vec3(0.8f, 0.6f, 0.2f));
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.3f);
    EXPECT_FLOAT_EQ(m.metallicFactor, 1.0f);
    EXPECT_FALSE(m.diffuseMap.empty());  // the base colour map
    EXPECT_TRUE(m.metallicRoughnessMap.empty());
}

TEST(MtlPbr, WithoutThemTheMaterialStaysBlinnPhong)
{
    const Material m = materialOf("newmtl m\nKd 0.8 0.6 0.2\nKs 0.5 0.5 0.5\nNs 40\n");
    EXPECT_EQ(m.model, ShadingModel::BlinnPhong);
    EXPECT_FLOAT_EQ(m.shininess, 40.0f);
}

TEST(MtlPbr, OneImageForBothMapsIsTheMetallicRoughnessMap)
{
    const Material m = materialOf("newmtl m\nKd 1 1 1\nmap_Pr brick.png\nmap_Pm brick.png\n");
    EXPECT_EQ(m.model, ShadingModel::MetallicRoughness);
    EXPECT_FALSE(m.metallicRoughnessMap.empty());
    // A map without its factor takes the factor 1.
    EXPECT_FLOAT_EQ(m.roughnessFactor, 1.0f);
    EXPECT_FLOAT_EQ(m.metallicFactor, 1.0f);
}

TEST(MtlPbr, SeparateImagesAreNotedAndLeftOut)
{
    Warnings warnings;
    const Model model = loadWithLibrary("newmtl m\nKd 1 1 1\nPr 0.5\nmap_Pr brick.png\nmap_Pm brick_n.png\n", warnings);
    const Material& m = model.materials.at(0);
    EXPECT_EQ(m.model, ShadingModel::MetallicRoughness);
    EXPECT_TRUE(m.metallicRoughnessMap.empty());
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.5f);
    ASSERT_EQ(warnings.messages().size(), 1u);
    EXPECT_NE(warnings.messages()[0].find("map_Pr and map_Pm in separate images are not read"), std::string::npos)
        << warnings.messages()[0];
}

TEST(MtlPbr, FactorsOutsideZeroToOneAreAnError)
{
    Warnings warnings;
    EXPECT_EQ(test::errorThrownBy([&] { loadWithLibrary("newmtl m\nKd 1 1 1\nPm 1.5\n", warnings); }),
              (kTextures / "lib.mtl").string() + ": material 'm': Pr and Pm must be in [0, 1]");
}

}  // namespace
}  // namespace manylights
