// glTF 2.0 model files: hierarchy and transforms, primitives with every index width,
// attributes, the material and light mappings of docs/scene-format.md, and broken hand-made
// files. Debian's assimp-testmodels, broken ones among them, are in GltfAssimpModelsTest.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "scene/GltfLoader.h"
#include "scene/MaterialModels.h"
#include "scene/SceneLoader.h"
#include "tests/unit/ErrorOf.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

using test::errorThrownBy;

std::string base64(const std::vector<unsigned char>& bytes)
{
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t chunk = (std::uint32_t{bytes[i]} << 16) |
                                    (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0u) |
                                    (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0u);
        out += digits[(chunk >> 18) & 63];
        out += digits[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[chunk & 63] : '=';
    }
    return out;
}

// A small glTF built in memory: one buffer (as a data: URI) holding a quad's positions and
// normals, the same quad's indices as u8, u16 and u32, and six unindexed positions.
class GltfBuilder {
public:
    GltfBuilder()
    {
        const float quad[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        const float unindexed[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
        positions = view(quad, sizeof quad, 4, "VEC3", 5126);
        normalAccessor = view(normals, sizeof normals, 4, "VEC3", 5126);
        const std::uint8_t u8[] = {0, 1, 2, 0, 2, 3};
        const std::uint16_t u16[] = {0, 1, 2, 0, 2, 3};
        const std::uint32_t u32[] = {0, 1, 2, 0, 2, 3};
        indices8 = view(u8, sizeof u8, 6, "SCALAR", 5121);
        indices16 = view(u16, sizeof u16, 6, "SCALAR", 5123);
        indices32 = view(u32, sizeof u32, 6, "SCALAR", 5125);
        flatPositions = view(unindexed, sizeof unindexed, 6, "VEC3", 5126);
    }

    int view(const void* data, std::size_t size, std::size_t count, const char* type, int componentType)
    {
        while (buffer.size() % 4 != 0)
            buffer.push_back(0);
        const std::size_t offset = buffer.size();
        const auto* bytes = static_cast<const unsigned char*>(data);
        buffer.insert(buffer.end(), bytes, bytes + size);
        gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
        gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                                     {"componentType", componentType},
                                     {"count", count},
                                     {"type", type}});
        return static_cast<int>(gltf["accessors"].size() - 1);
    }

    std::vector<unsigned char> bytes()
    {
        Json copy = gltf;
        copy["buffers"] = Json::array(
            {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}});
        const std::string text = copy.dump();
        return {text.begin(), text.end()};
    }

    Model load(GltfOptions options = {})
    {
        options.allowExternalFiles = false;
        return loadGltfMemory(bytes(), "test.gltf", {}, options);
    }

    Json gltf = {{"asset", {{"version", "2.0"}}}};
    std::vector<unsigned char> buffer;
    int positions, normalAccessor, indices8, indices16, indices32, flatPositions;
};

// The scene of the tests: a parent node moved to (1, 2, 3) whose child, scaled by 2, holds
// a mesh of four primitives; a point light and a spot light on nodes of their own.
GltfBuilder exampleGltf()
{
    GltfBuilder b;
    const Json attributes = {{"POSITION", b.positions}, {"NORMAL", b.normalAccessor}};
    b.gltf["meshes"] = Json::array({{{"name", "quads"},
                                     {"primitives",
                                      {{{"attributes", attributes}, {"indices", b.indices8}, {"material", 0}},
                                       {{"attributes", attributes}, {"indices", b.indices16}},
                                       {{"attributes", attributes}, {"indices", b.indices32}},
                                       {{"attributes", {{"POSITION", b.flatPositions}}}}}}}});
    b.gltf["materials"] =
        Json::array({{{"pbrMetallicRoughness",
                       {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.5}}},
                      {"emissiveFactor", {0.1, 0.2, 0.3}}}});
    const double halfSqrt2 = std::sqrt(0.5);
    b.gltf["nodes"] = Json::array(
        {{{"name", "parent"}, {"translation", {1, 2, 3}}, {"children", {1}}},
         {{"name", "child"}, {"scale", {2, 2, 2}}, {"mesh", 0}},
         {{"name", "lamp"}, {"translation", {0, 5, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
         // Rotated 90° about X: its −Z axis (the spot's direction) turns to +Y.
         {{"name", "spot"},
          {"rotation", {halfSqrt2, 0, 0, halfSqrt2}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}});
    b.gltf["scenes"] = Json::array({{{"nodes", {0, 2, 3}}}});
    b.gltf["scene"] = 0;
    b.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
    b.gltf["extensions"] = {{"KHR_lights_punctual",
                             {{"lights",
                               {{{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 4.0}, {"range", 10.0}},
                                {{"type", "spot"},
                                 {"intensity", 1.0},
                                 {"spot", {{"innerConeAngle", 0.0}, {"outerConeAngle", std::numbers::pi / 4}}}}}}}}};
    return b;
}

// Extensions: one a file requires but manylights does not read is an error; one it only uses
// is a warning (once), and the file is drawn. KHR_materials_emissive_strength scales the
// emissive colour. What a material has that is not drawn as the file means is said once per kind.
TEST(GltfModel, ExtensionsAndMaterialFeaturesReadOrSaid)
{
    GltfBuilder b = exampleGltf();
    b.gltf["materials"][0]["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5.0}}}};
    b.gltf["materials"][0]["alphaMode"] = "BLEND";
    b.gltf["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform",
                                "EXT_unknown"};
    b.gltf["extensionsRequired"] = {"KHR_texture_transform"};
    Warnings warnings;
    const Model model = b.load({.warnings = &warnings});
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_NEAR(model.materials[0].emissive.x, 0.5f, 1e-6f);
    EXPECT_NEAR(model.materials[0].emissive.z, 1.5f, 1e-6f);
    EXPECT_EQ(model.materials[0].alphaMode, AlphaMode::Blend);
    ASSERT_EQ(warnings.messages().size(), 1u);
    EXPECT_EQ(warnings.messages()[0], "test.gltf: the extension EXT_unknown is not read; the file is drawn without it");
    // Strict: the first is the error.
    Warnings strict(true);
    EXPECT_EQ(errorThrownBy([&] { b.load({.warnings = &strict}); }), warnings.messages()[0]);

    b.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    EXPECT_EQ(errorThrownBy([&] { b.load(); }),
              "test.gltf: requires the extension KHR_draco_mesh_compression, which manylights does not read");
}

// alphaMode, alphaCutoff, the base colour's alpha and doubleSided (glTF 2.0, "Materials").
TEST(GltfModel, AlphaModesAndSidesAreRead)
{
    GltfBuilder b = exampleGltf();
    Json& material = b.gltf["materials"][0];
    EXPECT_EQ(b.load().materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(b.load().materials[0].sides, Sides::Front);  // single-sided: back faces culled

    material["alphaMode"] = "MASK";
    material["alphaCutoff"] = 0.25;
    material["pbrMetallicRoughness"]["baseColorFactor"][3] = 0.75;
    material["doubleSided"] = true;
    Warnings warnings;
    const Material masked = b.load({.warnings = &warnings}).materials[0];
    EXPECT_TRUE(warnings.messages().empty());
    EXPECT_EQ(masked.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(masked.alphaCutoff, 0.25f);
    EXPECT_EQ(masked.opacity, 0.75f);
    EXPECT_EQ(masked.sides, Sides::BothFlipped);

    material.erase("alphaCutoff");  // the default cutoff
    EXPECT_EQ(b.load().materials[0].alphaCutoff, 0.5f);
    material["alphaMode"] = "BLEND";  // transparent: the coverage is its opacity
    const Material blended = b.load().materials[0];
    EXPECT_EQ(blended.alphaMode, AlphaMode::Blend);
    EXPECT_EQ(blended.opacity, 0.75f);
    material["alphaMode"] = "TRANSLUCENT";
    Warnings unknown;
    EXPECT_EQ(b.load({.warnings = &unknown}).materials[0].alphaMode, AlphaMode::Opaque);
    ASSERT_EQ(unknown.messages().size(), 1u);
    EXPECT_EQ(unknown.messages()[0], "test.gltf: materials[0]: unknown alphaMode 'TRANSLUCENT'; drawn OPAQUE");

    material["alphaMode"] = "MASK";
    material["alphaCutoff"] = -1.0;
    EXPECT_EQ(errorThrownBy([&] { b.load(); }), "test.gltf: materials[0]: alphaCutoff must be a finite number >= 0");
}

// KHR_texture_transform: uv' = T · R · S · uv in glTF's uvs, stored for our flipped v.
TEST(GltfModel, TextureTransformsAreStoredPerMapForFlippedUvs)
{
    GltfBuilder b = exampleGltf();
    b.gltf["images"] = Json::array({{{"uri", "data:image/png;base64,iVBORw0KGgo="}}});
    b.gltf["textures"] = Json::array({{{"source", 0}}});
    Json& pbr = b.gltf["materials"][0]["pbrMetallicRoughness"];
    pbr["baseColorTexture"] = {{"index", 0},
                               {"extensions",
                                {{"KHR_texture_transform",
                                  {{"offset", {0.5, 0.25}}, {"rotation", std::numbers::pi / 2}, {"scale", {2, 3}}}}}}};
    pbr["metallicRoughnessTexture"] = {{"index", 0}, {"texCoord", 1}};
    b.gltf["materials"][0]["emissiveTexture"] = {{"index", 0}};
    Warnings warnings;
    const Material material = b.load({.warnings = &warnings}).materials[0];
    EXPECT_FALSE(material.diffuseMap.empty());
    EXPECT_EQ(material.metallicRoughnessMap, material.diffuseMap);
    // glTF uv (0.1, 0.2): scaled (0.2, 0.6); turned by R = [cos sin; −sin cos] at 90°: (0.6, −0.2);
    // moved: (1.1, 0.05). In our uvs: (0.1, 0.8) → (1.1, 0.95).
    const glm::vec3 moved = material.uvTransforms[kDiffuseSlot] * glm::vec3(0.1f, 0.8f, 1.0f);
    EXPECT_NEAR(moved.x, 1.1f, 1e-6f);
    EXPECT_NEAR(moved.y, 0.95f, 1e-6f);
    EXPECT_EQ(moved.z, 1.0f);
    EXPECT_EQ(material.uvTransforms[kEmissiveSlot], glm::mat3{1.0f});
    // A second uv set is not read: said, and drawn with the first.
    ASSERT_EQ(warnings.messages().size(), 1u);
    EXPECT_EQ(warnings.messages()[0], "test.gltf: materials[0].metallicRoughnessTexture: texCoord 1 is not read; the "
                                      "texture is drawn with TEXCOORD_0");
}

// COLOR_0: RGB floats or RGBA normalised bytes, white without; Mesh::hasVertexColours says so.
TEST(GltfModel, VertexColoursAreRead)
{
    GltfBuilder b = exampleGltf();
    EXPECT_FALSE(b.load().meshes[0].hasVertexColours);
    const float rgb[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};
    const std::uint8_t rgba[] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 51, 51, 51, 51};
    const int floats = b.view(rgb, sizeof rgb, 4, "VEC3", 5126);
    const int bytes = b.view(rgba, sizeof rgba, 4, "VEC4", 5121);
    b.gltf["accessors"][static_cast<std::size_t>(bytes)]["normalized"] = true;
    Json& primitives = b.gltf["meshes"][0]["primitives"];
    primitives[0]["attributes"]["COLOR_0"] = floats;
    primitives[1]["attributes"]["COLOR_0"] = bytes;
    const Mesh mesh = b.load().meshes[0];
    EXPECT_TRUE(mesh.hasVertexColours);
    EXPECT_EQ(mesh.vertices[mesh.indices[2]].colour, glm::vec4(0, 0, 1, 1));                    // primitive 0, corner 2
    EXPECT_EQ(mesh.vertices[mesh.indices[6 + 1]].colour, glm::vec4(0, 1, 0, 128.0f / 255.0f));  // primitive 1, corner 1
    EXPECT_EQ(mesh.vertices[mesh.indices[12]].colour, glm::vec4(1.0f));                         // primitive 2 has none

    b.gltf["accessors"][static_cast<std::size_t>(bytes)]["normalized"] = false;
    EXPECT_EQ(errorThrownBy([&] {
                  b.load();
              }).rfind("test.gltf: meshes[0].primitives[1].COLOR_0: expected 4 float components", 0),
              0u);
}

TEST(GltfModel, HierarchyPrimitivesAndIndexWidths)
{
    const Model model = exampleGltf().load();
    ASSERT_EQ(model.instances.size(), 1u);
    EXPECT_EQ(model.instances[0].name, "child");
    const glm::mat4 expected = glm::scale(glm::translate(glm::mat4{1.0f}, {1, 2, 3}), glm::vec3{2.0f});
    EXPECT_EQ(model.instances[0].transform, expected);
    ASSERT_EQ(model.meshes.size(), 1u);
    const Mesh& mesh = model.meshes[0];
    // Four primitives, one range each, two triangles each.
    ASSERT_EQ(mesh.subMeshes.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p) {
        EXPECT_EQ(mesh.subMeshes[p].firstIndex, 6 * p);
        EXPECT_EQ(mesh.subMeshes[p].indexCount, 6u);
    }
    // u8, u16 and u32 indices give the same triangles.
    for (std::size_t p = 1; p < 3; ++p)
        for (std::size_t k = 0; k < 6; ++k)
            EXPECT_EQ(mesh.vertices[mesh.indices[6 * p + k]].position, mesh.vertices[mesh.indices[k]].position);
    // Indexed primitives share their 4 vertices; the one without normals gets flat normals
    // and a vertex per corner (6).
    EXPECT_EQ(mesh.vertices.size(), 4u * 3u + 6u);
    for (const Vertex& vertex : mesh.vertices)
        EXPECT_NEAR(vertex.normal.z, 1.0f, 1e-6f);
    EXPECT_TRUE(mesh.subMeshes[0].material.has_value());
    EXPECT_FALSE(mesh.subMeshes[1].material.has_value());
}

TEST(GltfModel, MaterialsLoadAsMetallicRoughnessAndMapToBlinnPhong)
{
    const Model model = exampleGltf().load();
    ASSERT_EQ(model.materials.size(), 1u);
    const Material& loaded = model.materials[0];
    EXPECT_EQ(loaded.model, ShadingModel::MetallicRoughness);
    EXPECT_NEAR(loaded.baseColor.r, 0.5f, 1e-6f);
    // The mapping of `"model_materials": "blinn-phong"`: kd = base · (1 − metallic), ks = 0.04 ·
    // (1 − metallic) plus the tint base · metallic, s = 2/roughness⁴ − 2.
    const Material m = blinnPhongMapping(loaded);
    EXPECT_EQ(m.model, ShadingModel::BlinnPhong);
    EXPECT_NEAR(m.diffuse.r, 0.25f, 1e-6f);
    EXPECT_NEAR(m.specular.r, 0.02f, 1e-6f);
    EXPECT_NEAR(m.specularTint.r, 0.25f, 1e-6f);
    EXPECT_EQ(m.metallicFactor, 0.5f);
    EXPECT_EQ(m.roughnessFactor, 0.5f);
    EXPECT_NEAR(m.shininess, 30.0f, 1e-3f);
    EXPECT_NEAR(m.emissive.b, 0.3f, 1e-6f);
}

TEST(GltfModel, PunctualLightsTakeTheNodeTransformAndTheDocumentedFalloff)
{
    GltfOptions options;
    options.attenuationThreshold = 1.0f / 256.0f;
    const Model model = exampleGltf().load(options);
    ASSERT_EQ(model.lights.size(), 2u);
    const Light& point = model.lights[0];
    EXPECT_EQ(point.name, "lamp");
    EXPECT_EQ(point.type, LightType::Point);
    EXPECT_EQ(point.position, glm::vec3(0, 5, 0));
    // colour · intensity / π (candela to the scene's units, docs/lighting.md)
    EXPECT_NEAR(point.intensity.r, 4.0 / std::numbers::pi, 1e-6);
    EXPECT_NEAR(point.intensity.g, 2.0 / std::numbers::pi, 1e-6);
    EXPECT_NEAR(point.intensity.b, 1.0 / std::numbers::pi, 1e-6);
    EXPECT_EQ(point.falloff, Falloff::Range);
    EXPECT_EQ(point.range, 10.0f);
    const Light& spot = model.lights[1];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_NEAR(spot.direction.y, 1.0f, 1e-6f);
    // No range: r = sqrt(Imax / t) = sqrt(256 / π), its intensity 1 candela being 1/π.
    EXPECT_NEAR(spot.range, std::sqrt(256.0 / std::numbers::pi), 1e-4);
    EXPECT_NEAR(spot.cutoffDegrees, 45.0f, 1e-4f);
    // (cos θ)^e = 1/2 where cos θ = (cos 0 + cos 45°) / 2.
    const double middle = 0.5 * (1.0 + std::sqrt(0.5));
    EXPECT_NEAR(std::pow(middle, spot.exponent), 0.5, 1e-5);
}

TEST(GltfModel, SceneObjectBecomesOneObjectPerNodeAndAddsTheLights)
{
    const fs::path dir = fs::path(::testing::TempDir()) / "ml_gltf_scene";
    fs::create_directories(dir);
    const std::vector<unsigned char> bytes = exampleGltf().bytes();
    std::ofstream(dir / "lamp.gltf", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    const Scene scene = parseScene(R"({ "objects": [ { "name": "model", "mesh": "lamp.gltf",
                                         "transform": { "translate": [10, 0, 0] } } ] })",
                                   "scene.json", dir);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "model/child");
    EXPECT_FALSE(scene.objects[0].materialOverridesMesh);
    EXPECT_EQ(glm::vec3(scene.objects[0].transform[3]), glm::vec3(11, 2, 3));
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].name, "model/lamp");
    EXPECT_EQ(scene.lights[0].position, glm::vec3(10, 5, 0));
    const Mesh& mesh = scene.meshes[scene.objects[0].mesh];
    ASSERT_TRUE(mesh.subMeshes[0].material.has_value());
    EXPECT_EQ(scene.materials[*mesh.subMeshes[0].material].roughnessFactor, 0.5f);
}

// Schema breaks tinygltf reads past (issue 33): each is a warning naming the file, the JSON
// pointer and the field, the file is still drawn (as tinygltf reads it), and under --strict
// the first is an error.
TEST(GltfModel, SchemaBreaksTinygltfPassesOverAreSaid)
{
    GltfBuilder b = exampleGltf();
    b.gltf["materials"][0]["pbrMetallicRoughness"] = Json::array({"not an object"});
    b.gltf["materials"][0]["normalTexture"] = {{"index", -1}};
    b.gltf["nodes"][1]["name"] = 42;
    b.gltf["extensions"]["KHR_lights_punctual"]["lights"][0]["range"] = 0;
    Warnings warnings;
    const Model model = b.load({.warnings = &warnings});
    EXPECT_EQ(model.lights.size(), 2u);
    const std::vector<std::string> expected = {
        "test.gltf: /materials/0/pbrMetallicRoughness: pbrMetallicRoughness must be an object, got an array; the "
        "field is not read",
        "test.gltf: /materials/0/normalTexture/index: index must be an integer ≥ 0, got -1; read as none",
        "test.gltf: /nodes/1/name: name must be a string, got 42; the field is not read",
        "test.gltf: /extensions/KHR_lights_punctual/lights/0/range: range must be > 0, got 0; the light is drawn as "
        "one without a range (inverse-square, cut at the scene's attenuation_threshold)",
    };
    EXPECT_EQ(warnings.messages(), expected);
    Warnings strict(true);
    EXPECT_EQ(errorThrownBy([&] { b.load({.warnings = &strict}); }), expected[0]);
}

// Many elements with the same break give one warning, as other forgiven problems do.
TEST(GltfModel, OneSchemaWarningPerKindOfBreak)
{
    GltfBuilder b = exampleGltf();
    for (Json& node : b.gltf["nodes"])
        node["name"] = 7;
    Warnings warnings;
    b.load({.warnings = &warnings});
    ASSERT_EQ(warnings.messages().size(), 1u);
    EXPECT_EQ(warnings.messages()[0],
              "test.gltf: /nodes/0/name: name must be a string, got 7; the field is not read (and 3 more)");
}

// --- broken hand-made files --------------------------------------------------------------

struct BrokenGltf {
    const char* name;
    void (*breakIt)(GltfBuilder&);
    const char* phrase;
};

std::ostream& operator<<(std::ostream& out, const BrokenGltf& broken) { return out << broken.name; }

class BrokenGltfTest : public ::testing::TestWithParam<BrokenGltf> {};

TEST_P(BrokenGltfTest, OneErrorLineNamingTheFileAndElement)
{
    GltfBuilder builder = exampleGltf();
    GetParam().breakIt(builder);
    const std::string message = errorThrownBy([&] { builder.load(); });
    EXPECT_TRUE(message.starts_with("test.gltf: ")) << message;
    EXPECT_NE(message.find(GetParam().phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    GltfModel, BrokenGltfTest,
    ::testing::Values(
        BrokenGltf{"AccessorPastItsView", [](GltfBuilder& b) { b.gltf["accessors"][0]["count"] = 5; },
                   "accessors[0]: 5 elements at byteOffset 0 do not fit"},
        BrokenGltf{"HugeCount", [](GltfBuilder& b) { b.gltf["accessors"][0]["count"] = 4611686018427387904ull; },
                   "do not fit"},
        BrokenGltf{"ViewPastItsBuffer", [](GltfBuilder& b) { b.gltf["bufferViews"][0]["byteLength"] = 100000; },
                   "bufferViews[0]: bytes 0 to 100000 lie outside buffers[0]"},
        BrokenGltf{"IndexOutOfRange",
                   [](GltfBuilder& b) {
                       const std::uint8_t bad[] = {0, 1, 7};
                       b.gltf["meshes"][0]["primitives"][0]["indices"] = b.view(bad, 3, 3, "SCALAR", 5121);
                   },
                   "meshes[0].primitives[0].indices: index 2 is 7, out of range (POSITION has 4 elements)"},
        BrokenGltf{"InfinitePosition",
                   [](GltfBuilder& b) {
                       const float bad[] = {0, 0, 0, 1, 0, 0, 0, INFINITY, 0};
                       b.gltf["meshes"][0]["primitives"][3]["attributes"]["POSITION"] =
                           b.view(bad, sizeof bad, 3, "VEC3", 5126);
                   },
                   "meshes[0].primitives[3].POSITION"},
        BrokenGltf{"NotWholeTriangles", [](GltfBuilder& b) { b.gltf["accessors"][b.flatPositions]["count"] = 5; },
                   "5 corners are not whole triangles"},
        BrokenGltf{"NormalCountDiffers", [](GltfBuilder& b) { b.gltf["accessors"][1]["count"] = 3; },
                   "NORMAL: has 3 elements, POSITION has 4"},
        BrokenGltf{"PositionsAsIntegers", [](GltfBuilder& b) { b.gltf["accessors"][0]["componentType"] = 5125; },
                   "POSITION: expected 3 float components"},
        BrokenGltf{"UnknownMesh", [](GltfBuilder& b) { b.gltf["nodes"][1]["mesh"] = 9; }, "nodes[1]: mesh 9"},
        BrokenGltf{"UnknownChild", [](GltfBuilder& b) { b.gltf["nodes"][0]["children"] = {42}; },
                   "nodes[0]: child 42 is not a node"},
        BrokenGltf{"Cycle", [](GltfBuilder& b) { b.gltf["nodes"][1]["children"] = {0}; },
                   "nodes[0] is its own ancestor (the node hierarchy has a cycle)"},
        BrokenGltf{"TwoParents", [](GltfBuilder& b) { b.gltf["nodes"][2]["children"] = {1}; },
                   "nodes[1] has more than one parent"},
        BrokenGltf{"UnknownMaterial", [](GltfBuilder& b) { b.gltf["meshes"][0]["primitives"][1]["material"] = 3; },
                   "meshes[0].primitives[1]: material 3"},
        BrokenGltf{"UnknownLight",
                   [](GltfBuilder& b) { b.gltf["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 5; },
                   "KHR_lights_punctual: a node names light 5"},
        BrokenGltf{"SpotConeInverted",
                   [](GltfBuilder& b) {
                       b.gltf["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 1.0;
                   },
                   "lights[1]: spot cone angles"},
        BrokenGltf{"ShortTranslation",
                   [](GltfBuilder& b) {
                       b.gltf["nodes"][0]["translation"] = {1, 2};
                   },
                   "nodes[0]: translation needs 3 numbers"},
        BrokenGltf{"MissingTexture",
                   [](GltfBuilder& b) {
                       b.gltf["images"] = Json::array({{{"uri", "nothere.png"}}});
                       b.gltf["textures"] = Json::array({{{"source", 0}}});
                       b.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
                   },
                   "images[0]: external image 'nothere.png'"},
        BrokenGltf{"UnknownTexture",
                   [](GltfBuilder& b) {
                       b.gltf["materials"][0]["normalTexture"] = {{"index", 4}};
                   },
                   "materials[0].normalTexture: texture 4 is not a texture"},
        BrokenGltf{"NoVersion", [](GltfBuilder& b) { b.gltf.erase("asset"); }, "test.gltf: "},
        BrokenGltf{"ExternalBuffer",
                   [](GltfBuilder& b) {
                       b.gltf["images"] = Json::array({{{"uri", "../../etc/passwd"}}});
                       b.gltf["textures"] = Json::array({{{"source", 0}}});
                       b.gltf["materials"][0]["emissiveTexture"] = {{"index", 0}};
                   },
                   "not allowed when loading from memory"}),
    [](const ::testing::TestParamInfo<BrokenGltf>& param) { return std::string(param.param.name); });

// glTF puts uv (0, 0) at the image's top-left corner, GL and our texture cache at the
// bottom-left: the loader turns v into 1 − v. The bitangent (the direction of increasing v)
// reverses with it, so a file's tangent handedness w flips too; keeping either would show
// glTF textures upside down or their normal maps' green channel inverted.
TEST(GltfModel, TextureCoordinatesAndTangentsTakeTheGlOrigin)
{
    GltfBuilder b = exampleGltf();
    const float uvs[] = {0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.25f, 0.0f, 0.25f};
    const float tangents[] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1, 1, 0, 0, -1};
    const int uvAccessor = b.view(uvs, sizeof uvs, 4, "VEC2", 5126);
    const int tangentAccessor = b.view(tangents, sizeof tangents, 4, "VEC4", 5126);
    b.gltf["meshes"][0]["primitives"] = Json::array({{{"attributes",
                                                       {{"POSITION", b.positions},
                                                        {"NORMAL", b.normalAccessor},
                                                        {"TEXCOORD_0", uvAccessor},
                                                        {"TANGENT", tangentAccessor}}},
                                                      {"indices", b.indices16}}});
    const Model model = b.load();
    ASSERT_EQ(model.meshes.size(), 1u);
    const Mesh& mesh = model.meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.vertices[i].uv.x, uvs[2 * i]) << i;
        EXPECT_EQ(mesh.vertices[i].uv.y, 1.0f - uvs[2 * i + 1]) << i;
        EXPECT_EQ(mesh.vertices[i].tangent, glm::vec4(1.0f, 0.0f, 0.0f, -tangents[4 * i + 3])) << i;
    }
}

TEST(GltfModel, PointsAndLinesAreSkipped)
{
    GltfBuilder b = exampleGltf();
    for (auto& primitive : b.gltf["meshes"][0]["primitives"])
        primitive["mode"] = 1;  // LINES
    b.gltf["meshes"][0]["primitives"][0]["mode"] = 4;
    const Model model = b.load();
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].subMeshes.size(), 1u);
}

TEST(GltfModel, EveryTruncationOfTheTextIsAnError)
{
    const std::vector<unsigned char> bytes = exampleGltf().bytes();
    for (std::size_t size = 0; size < bytes.size(); size += 7) {
        const std::vector<unsigned char> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
        EXPECT_THROW(loadGltfMemory(cut, "cut.gltf", {}, {1.0f / 256.0f, false}), Error) << size;
    }
}

}  // namespace
}  // namespace manylights
