// OBJ + MTL model files: per-material draw ranges over one vertex buffer, the MTL values and
// maps, and every broken-asset path (one Error naming the file and the line).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/Error.h"
#include "scene/ObjLoader.h"
#include "scene/SceneLoader.h"
#include "tests/unit/ErrorOf.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = fs::path(MANYLIGHTS_TEST_DATA_DIR) / "models";

// A directory of its own per test, for files written by the test.
fs::path scratch()
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(::testing::TempDir()) / (std::string("ml_obj_") + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

fs::path write(const fs::path& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

using test::errorThrownBy;

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

// Loads with the warnings of forgiven problems discarded (the tests of those look at them).
Model loadObj(const fs::path& path)
{
    Warnings warnings;
    return loadObjModelFile(path, warnings);
}

TEST(ObjModel, MaterialsBecomeOneDrawRangeEachOverOneVertexBuffer)
{
    const Model model = loadObj(kModels / "two-materials.obj");
    ASSERT_EQ(model.meshes.size(), 1u);
    const Mesh& mesh = model.meshes[0];
    // Four quads: 8 triangles, 24 indices in total, in three ranges (none, red, textured)
    // that tile the index list in order of first use.
    ASSERT_EQ(mesh.indices.size(), 24u);
    ASSERT_EQ(mesh.subMeshes.size(), 3u);
    EXPECT_FALSE(mesh.subMeshes[0].material.has_value());
    EXPECT_EQ(mesh.subMeshes[0].firstIndex, 0u);
    EXPECT_EQ(mesh.subMeshes[0].indexCount, 6u);
    ASSERT_TRUE(mesh.subMeshes[1].material.has_value());
    EXPECT_EQ(mesh.subMeshes[1].firstIndex, 6u);
    EXPECT_EQ(mesh.subMeshes[1].indexCount, 12u);  // red's two groups together
    ASSERT_TRUE(mesh.subMeshes[2].material.has_value());
    EXPECT_EQ(mesh.subMeshes[2].firstIndex, 18u);
    EXPECT_EQ(mesh.subMeshes[2].indexCount, 6u);
    ASSERT_EQ(model.materials.size(), 2u);

    const Material& red = model.materials[*mesh.subMeshes[1].material];
    EXPECT_NE(red.name.find("two-materials.obj#red"), std::string::npos) << red.name;
    EXPECT_EQ(red.diffuse, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(red.specular, glm::vec3(0.5f));
    EXPECT_EQ(red.shininess, 64.0f);
    EXPECT_EQ(red.emissive, glm::vec3(0.1f, 0.0f, 0.0f));
    EXPECT_TRUE(red.diffuseMap.empty());

    const Material& textured = model.materials[*mesh.subMeshes[2].material];
    EXPECT_EQ(fs::path(textured.diffuseMap), kModels / "brick.png");
    EXPECT_EQ(fs::path(textured.specularMap), kModels / "brick.png");
    EXPECT_EQ(fs::path(textured.normalMap), kModels / "brick_n.png");
    EXPECT_EQ(textured.normalScale, 0.5f);
    // No Kd beside map_Kd: the map is taken at face value. Ns 0 is raised to SPEC's minimum 1.
    EXPECT_EQ(textured.diffuse, glm::vec3(1.0f));
    EXPECT_EQ(textured.shininess, 1.0f);

    // The file has no normals: every one is computed (the quads are flat, facing +Z).
    for (const Vertex& vertex : mesh.vertices)
        EXPECT_NEAR(vertex.normal.z, 1.0f, 1e-6f);
    // 10 positions; the textured quad's corners carry uvs, so those four are separate vertices.
    EXPECT_EQ(mesh.vertices.size(), 14u);
}

// MTL texture options: -o and -s move and scale a map's uvs (uv' = s · uv + o), -clamp on
// clamps it; a map without options keeps the identity and repeats.
TEST(ObjModel, TextureOptionsOffsetScaleAndClampTheMap)
{
    const fs::path dir = scratch();
    fs::copy_file(kModels / "brick.png", dir / "brick.png");
    write(dir / "m.mtl", "newmtl m\nmap_Kd -o 0.5 0.25 0 -s 2 3 1 -clamp on brick.png\nmap_Ks brick.png\n");
    write(dir / "quad.obj", std::string("mtllib m.mtl\n") + kQuad + "vt 0 0\nusemtl m\nf 1/1 2/1 3/1 4/1\n");
    const Model model = loadObj(dir / "quad.obj");
    ASSERT_EQ(model.materials.size(), 1u);
    const Material& material = model.materials[0];
    const glm::vec3 moved = material.uvTransforms[kDiffuseSlot] * glm::vec3(0.1f, 0.2f, 1.0f);
    EXPECT_NEAR(moved.x, 0.7f, 1e-6f);
    EXPECT_NEAR(moved.y, 0.85f, 1e-6f);
    EXPECT_EQ(material.wraps[kDiffuseSlot].s, TextureWrap::ClampToEdge);
    EXPECT_EQ(material.wraps[kDiffuseSlot].t, TextureWrap::ClampToEdge);
    EXPECT_EQ(material.uvTransforms[kSpecularSlot], glm::mat3{1.0f});
    EXPECT_EQ(material.wraps[kSpecularSlot].s, TextureWrap::Repeat);
}

// `d` below 1 (or `Tr` above 0, which tinyobjloader reads as d = 1 − Tr) makes the material
// transparent with that opacity; `d 1` keeps it opaque; `map_d` names an opacity map.
TEST(ObjModel, DissolveMakesTheMaterialTransparent)
{
    const fs::path dir = scratch();
    fs::copy_file(kModels / "brick.png", dir / "leaves.png");
    write(dir / "m.mtl", "newmtl glass\nKd 0.2 0.4 0.8\nd 0.25\nnewmtl tinted\nTr 0.5\nnewmtl solid\nd 1\n"
                         "newmtl cutout\nmap_d leaves.png\n");
    write(dir / "quads.obj", std::string("mtllib m.mtl\n") + kQuad +
                                 "usemtl glass\nf 1 2 3\nusemtl tinted\nf 1 3 4\nusemtl solid\nf 2 3 4\n"
                                 "usemtl cutout\nf 1 2 4\n");
    const Model model = loadObj(dir / "quads.obj");
    ASSERT_EQ(model.materials.size(), 4u);
    std::map<std::string, const Material*> byName;
    for (const Material& material : model.materials)
        byName[material.name.substr(material.name.find('#') + 1)] = &material;
    EXPECT_EQ(byName.at("glass")->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(byName.at("glass")->opacity, 0.25f);
    EXPECT_EQ(byName.at("tinted")->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(byName.at("tinted")->opacity, 0.5f);
    EXPECT_EQ(byName.at("solid")->alphaMode, AlphaMode::Opaque);
    // map_d: an opacity map, which makes the material transparent whatever its d.
    EXPECT_EQ(fs::path(byName.at("cutout")->opacityMap), dir / "leaves.png");
    EXPECT_EQ(byName.at("cutout")->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(byName.at("cutout")->opacity, 1.0f);
}

TEST(ObjModel, WithoutUsemtlThereAreNoSubMeshes)
{
    const fs::path dir = scratch();
    const Model model = loadObj(write(dir / "plain.obj", std::string(kQuad) + "f 1 2 3 4\n"));
    EXPECT_TRUE(model.meshes[0].subMeshes.empty());
    EXPECT_TRUE(model.materials.empty());
}

TEST(ObjModel, SceneObjectWithoutMaterialUsesTheFileMaterialsUnderTheirOwnNames)
{
    const fs::path dir = scratch();
    fs::copy(kModels, dir / "models");
    // The scene's own material "red" must not be confused with the file's "red".
    const std::string json = R"({
        "materials": { "red": { "diffuse": [0, 0, 1] } },
        "objects": [
            { "name": "own", "mesh": "models/two-materials.obj" },
            { "name": "overridden", "mesh": "models/two-materials.obj", "material": "red" } ] })";
    const Scene scene = parseScene(json, "scene.json", dir);
    ASSERT_EQ(scene.meshes.size(), 1u);  // one mesh for both objects
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_FALSE(scene.objects[0].materialOverridesMesh);
    EXPECT_TRUE(scene.objects[1].materialOverridesMesh);
    EXPECT_EQ(scene.materials[scene.objects[1].material].diffuse, glm::vec3(0.0f, 0.0f, 1.0f));
    const Mesh& mesh = scene.meshes[scene.objects[0].mesh];
    ASSERT_EQ(mesh.subMeshes.size(), 3u);
    const Material& fileRed = scene.materials[*mesh.subMeshes[1].material];
    EXPECT_EQ(fileRed.diffuse, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_NE(fileRed.name, "red");
}

struct BrokenObj {
    const char* name;
    std::string obj;
    std::string mtl;  // written as lib.mtl when not empty
    std::string phrase;
};

std::ostream& operator<<(std::ostream& out, const BrokenObj& broken) { return out << broken.name; }

// Writes the case's model.obj (and lib.mtl) into a fresh folder; returns the OBJ.
fs::path writeCase(const BrokenObj& broken)
{
    const fs::path dir = scratch();
    if (!broken.mtl.empty())
        write(dir / "lib.mtl", broken.mtl);
    return write(dir / "model.obj", broken.obj);
}

// Whether `message` starts by naming the OBJ, or the MTL beside it the problem is in.
bool namesTheFile(const std::string& message, const fs::path& obj)
{
    return message.starts_with(obj.string()) || message.starts_with((obj.parent_path() / "lib.mtl").string());
}

class BrokenObjTest : public ::testing::TestWithParam<BrokenObj> {};

TEST_P(BrokenObjTest, OneErrorLineNamingTheFile)
{
    const BrokenObj& broken = GetParam();
    const fs::path obj = writeCase(broken);
    const std::string message = errorThrownBy([&] { loadObj(obj); });
    EXPECT_NE(message.find(broken.phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_TRUE(namesTheFile(message, obj)) << message;
}

const std::string kQuadWithLib = std::string("mtllib lib.mtl\n") + kQuad + "usemtl m\nf 1 2 3 4\n";

INSTANTIATE_TEST_SUITE_P(
    ObjModel, BrokenObjTest,
    ::testing::Values(
        BrokenObj{"NanKd", kQuadWithLib, "newmtl m\nKd nan 1 1\n", "lib.mtl: line 2: Kd has a non-finite"},
        BrokenObj{"NegativeKd", kQuadWithLib, "newmtl m\nKd -1 0.5 0.5\n",
                  "lib.mtl: line 2: Kd must not be negative, got '-1'"},
        BrokenObj{"ShortKs", kQuadWithLib, "newmtl m\nKs 1 1\n", "line 2: Ks needs 3 numbers, has 2"},
        BrokenObj{"InfinitePosition", "v inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "", "line 1: vertex position"},
        BrokenObj{"OverflowingPosition", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "", "line 1"},
        BrokenObj{"IndexOutOfRange", std::string(kQuad) + "f 1 2 9\n", "", "vertex index 9 is out of range"},
        BrokenObj{"NegativeIndexTooFar", std::string(kQuad) + "f -1 -2 -9\n", "", "negative vertex index"},
        BrokenObj{"UvIndexOutOfRange", std::string(kQuad) + "vt 0 0\nf 1/1 2/2 3/1\n", "",
                  "texture coordinate index 2 is out of range"},
        // Indices past 2^31 wrapped in tinyobjloader's atoi to valid ones and drew a triangle.
        BrokenObj{"IndexPast2To32", std::string(kQuad) + "f 1 2 4294967299\n", "",
                  "line 5: the index '4294967299' is not an integer within"},
        BrokenObj{"HugeIndex", std::string(kQuad) + "f 1 2 1e23\n", "", "the index '1e23'"},
        BrokenObj{"FourHundredDigitUvIndex", std::string(kQuad) + "vt 0 0\nf 1/1 2/1 3/" + std::string(400, '9') + "\n",
                  "", "is not an integer within"},
        BrokenObj{"OnlyZeroAreaTriangles", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "", "every triangle has zero area"},
        BrokenObj{"NoFaces", std::string(kQuad), "", "has no faces"},
        BrokenObj{"Truncated", std::string(kQuad) + "f 1 2", "", "has no faces"}),
    [](const ::testing::TestParamInfo<BrokenObj>& param) { return std::string(param.param.name); });

class ForgivenObjTest : public ::testing::TestWithParam<BrokenObj> {};

// What other readers forgive: the model loads, with one warning naming the file and the line
// (where there is one) and saying what was done; under --strict the same text is the error.
TEST_P(ForgivenObjTest, LoadsWithOneWarningAndFailsWhenStrict)
{
    const BrokenObj& forgiven = GetParam();
    const fs::path obj = writeCase(forgiven);
    Warnings warnings;
    const Model model = loadObjModelFile(obj, warnings);
    EXPECT_FALSE(model.meshes.empty());
    ASSERT_EQ(warnings.messages().size(), 1u) << (warnings.messages().empty() ? "" : warnings.messages().front());
    const std::string& message = warnings.messages().front();
    EXPECT_NE(message.find(forgiven.phrase), std::string::npos) << message;
    EXPECT_TRUE(namesTheFile(message, obj)) << message;
    Warnings strict(true);
    EXPECT_EQ(errorThrownBy([&] { loadObjModelFile(obj, strict); }), message);
}

INSTANTIATE_TEST_SUITE_P(
    ObjModel, ForgivenObjTest,
    ::testing::Values(
        BrokenObj{"MissingMtl", "mtllib none.mtl\n" + std::string(kQuad) + "f 1 2 3\n", "",
                  "line 1: material library 'none.mtl' not found"},
        BrokenObj{"UnknownUsemtl", kQuadWithLib, "newmtl other\nKd 1 1 1\n", "line 6: usemtl 'm'"},
        BrokenObj{"UsemtlWithoutLibrary", std::string(kQuad) + "usemtl Default\nf 1 2 3\n", "",
                  "line 5: usemtl 'Default': no material library of the file defines it"},
        BrokenObj{"MissingTexture", kQuadWithLib, "newmtl m\nmap_Kd nothere.png\n",
                  "material 'm': map_Kd 'nothere.png' not found"},
        BrokenObj{"MissingNormalMap", kQuadWithLib, "newmtl m\nbump nothere.png\n", "map_Bump 'nothere.png'"},
        BrokenObj{"OneValueKs", kQuadWithLib, "newmtl m\nKs 0.5\n", "lib.mtl: line 2: Ks with one value"},
        BrokenObj{"PlusSigns", "v +0 0 0\nv 1 +0 0\nv 1 1 0\nf 1 2 3\n", "",
                  "line 1: numbers with a leading '+' read without it (and 1 more lines)"},
        BrokenObj{"TrailingCharacters", "v 0 0 0\nv 1 0 0\nv 1 1 3.1+e2\nf 1 2 3\n", "",
                  "line 3: the number '3.1+e2' read as 3.1"},
        BrokenObj{"UnknownStatement", std::string(kQuad) + "frobnicate 3\nf 1 2 3\n", "",
                  "line 5: unknown statement 'frobnicate' ignored"},
        BrokenObj{"Utf8Bom", "\xEF\xBB\xBF" + std::string(kQuad) + "f 1 2 3\n", "", "a UTF-8 byte-order mark"}),
    [](const ::testing::TestParamInfo<BrokenObj>& param) { return std::string(param.param.name); });

// The numbers the loader rewrites for tinyobjloader ('+' signs, characters after a number,
// one-value colours) reach the model as other readers read them; lines it leaves alone keep
// their numbers exactly, comments after them included.
TEST(ObjModel, RewrittenNumbersReadAsOtherReadersReadThem)
{
    const fs::path dir = scratch();
    write(dir / "lib.mtl", "newmtl m\nKd 0.25 # grey\nKs +0.5 0.5 0.5\n");
    const fs::path obj =
        write(dir / "m.obj", "mtllib lib.mtl\nv +1 +2. 3.1+e2\nv 4 5 6 # plain\nv 0 1e1 -2\nusemtl m\nf 1 2 3\n");
    Warnings warnings;
    const Model model = loadObjModelFile(obj, warnings);
    std::vector<glm::vec3> positions;
    for (const Vertex& vertex : model.meshes[0].vertices)
        positions.push_back(vertex.position);
    for (const glm::vec3 expected : {glm::vec3(1, 2, 3.1f), glm::vec3(4, 5, 6), glm::vec3(0, 10, -2)})
        EXPECT_NE(std::find(positions.begin(), positions.end(), expected), positions.end()) << expected.z;
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].diffuse, glm::vec3(0.25f));
    EXPECT_EQ(model.materials[0].specular, glm::vec3(0.5f));
    EXPECT_EQ(warnings.messages().size(), 4u);  // plus and trailing in the OBJ; one value and plus in the MTL
}

TEST(ObjModel, ZeroAreaTrianglesAreDropped)
{
    const fs::path dir = scratch();
    // The second triangle repeats a corner: it is left out, the first one stays.
    const Model model = loadObj(write(dir / "m.obj", std::string(kQuad) + "f 1 2 3\nf 1 1 4\n"));
    EXPECT_EQ(model.meshes[0].indices.size(), 3u);
}

TEST(ObjModel, SceneMessagesNameSceneObjectAndFile)
{
    const fs::path dir = scratch();
    write(dir / "model.obj", "mtllib none.mtl\n" + std::string(kQuad) + "f 1 2 3\n");
    const std::string scene = R"({ "objects": [ { "mesh": "model.obj" } ] })";
    // Forgiven: the scene loads and carries the warning, placed as an error would be.
    const Scene loaded = parseScene(scene, "scene.json", dir);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_TRUE(loaded.warnings[0].starts_with("scene.json: /objects/0/mesh: ")) << loaded.warnings[0];
    EXPECT_NE(loaded.warnings[0].find("model.obj: line 1: material library 'none.mtl' not found"), std::string::npos)
        << loaded.warnings[0];
    // Strict: the same line is the error.
    EXPECT_EQ(errorThrownBy([&] { parseScene(scene, "scene.json", dir, {.strict = true}); }), loaded.warnings[0]);
    // An error proper is placed the same way.
    write(dir / "broken.obj", std::string(kQuad) + "f 1 2 9\n");
    const std::string message =
        errorThrownBy([&] { parseScene(R"({ "objects": [ { "mesh": "broken.obj" } ] })", "scene.json", dir); });
    EXPECT_TRUE(message.starts_with("scene.json: /objects/0/mesh: ")) << message;
    EXPECT_NE(message.find("broken.obj: vertex index 9 is out of range"), std::string::npos) << message;
}

}  // namespace
}  // namespace manylights
