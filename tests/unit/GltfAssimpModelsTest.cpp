// glTF 2.0 files made by others: Debian's assimp-testmodels (scripts/setup.sh installs it), the
// well-formed ones read as their authors meant and the broken ones each one error line naming
// the file, or a warning where tinygltf reads past the break. Skipped where the package is
// missing.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "scene/GltfLoader.h"
#include "scene/SceneLoader.h"
#include "tests/unit/ErrorOf.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

const fs::path kAssimpGltf = "/usr/share/assimp/models/glTF2";

#define SKIP_WITHOUT_ASSIMP_MODELS()                                                                                   \
    if (!fs::is_directory(kAssimpGltf))                                                                                \
    GTEST_SKIP() << kAssimpGltf << " is missing: install assimp-testmodels (scripts/setup.sh)"

using test::errorThrownBy;

std::vector<unsigned char> readBytes(const fs::path& path)
{
    std::ifstream stream(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

TEST(GltfAssimpModels, BoxTexturedInAllThreeContainers)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                             "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(file);
        const Model model = loadGltfFile(kAssimpGltf / file);
        ASSERT_EQ(model.meshes.size(), 1u);
        EXPECT_EQ(model.meshes[0].indices.size(), 36u);
        EXPECT_EQ(model.meshes[0].vertices.size(), 24u);
        ASSERT_EQ(model.materials.size(), 1u);
        const std::string& map = model.materials[0].diffuseMap;
        if (std::string(file).starts_with("BoxTextured-glTF/")) {
            // An external image: its path, checked to exist.
            EXPECT_TRUE(fs::is_regular_file(map)) << map;
            EXPECT_TRUE(model.images.empty());
        } else {
            // Embedded (buffer view in the .glb, data: URI in the .gltf): the encoded PNG bytes.
            ASSERT_EQ(model.images.size(), 1u);
            EXPECT_EQ(model.images[0].key, map);
            ASSERT_GE(model.images[0].bytes.size(), 8u);
            EXPECT_EQ(std::memcmp(model.images[0].bytes.data(), "\x89PNG", 4), 0);
        }
    }
}

// Khronos' TextureTransformTest: six materials with KHR_texture_transform (offsets, a rotation,
// a scale, all three), three marker materials without; its sampler clamps to the edge.
// tests/image/AnalyticTest.cpp checks what the transforms do to the image.
TEST(GltfAssimpModels, TextureTransformTestReadsEveryTransform)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    Warnings warnings;
    const Model model =
        loadGltfFile(kAssimpGltf / "textureTransform/TextureTransformTest.gltf", {.warnings = &warnings});
    ASSERT_EQ(model.materials.size(), 9u);
    std::size_t transformed = 0;
    std::size_t clamped = 0;
    for (const Material& material : model.materials) {
        EXPECT_FALSE(material.diffuseMap.empty()) << material.name;
        if (material.uvTransforms[kDiffuseSlot] != glm::mat3{1.0f})
            ++transformed;
        if (material.wraps[kDiffuseSlot].s == TextureWrap::ClampToEdge &&
            material.wraps[kDiffuseSlot].t == TextureWrap::ClampToEdge)
            ++clamped;
    }
    EXPECT_EQ(transformed, 6u);
    EXPECT_EQ(clamped, 6u);  // the textures with sampler 0; the markers' have none (repeat)
    EXPECT_TRUE(warnings.messages().empty());
}

TEST(GltfAssimpModels, EngineHasManyNodes)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    const Model model = loadGltfFile(kAssimpGltf / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    EXPECT_GT(model.instances.size(), 50u);
    for (const ModelInstance& instance : model.instances)
        ASSERT_LT(instance.mesh, model.meshes.size());
}

struct BrokenAsset {
    const char* file;
    const char* phrase;
};

TEST(GltfAssimpModels, BrokenModelsAreOneErrorLineNamingTheFile)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    const BrokenAsset broken[] = {
        {"IndexOutOfRange/IndexOutOfRange.gltf", "out of range"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range"},

        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "non-finite"},
        {"IncorrectVertexArrays/Cube.gltf", "not whole triangles"},
        {"RecursiveNodes/RecursiveNodes.gltf", "cycle"},
        {"TestNoRootNode/NoScene.gltf", "no triangle mesh"},
        {"draco/2CylinderEngine.gltf", ""},
    };
    for (const BrokenAsset& asset : broken) {
        SCOPED_TRACE(asset.file);
        const fs::path path = kAssimpGltf / asset.file;
        const std::string message = errorThrownBy([&] { loadGltfFile(path); });
        EXPECT_TRUE(message.starts_with(path.string() + ": ")) << message;
        EXPECT_NE(message.find(asset.phrase), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// assimp's glTF2/wrongTypes set: each file breaks the schema in one field. All but badArray
// (its mesh's primitives an object, so no triangle is left) and badNumber (a normalTexture
// without the index tinygltf requires, which it reports) are drawn, with a warning naming the
// field.
TEST(GltfAssimpModels, WrongTypesAreWarningsNamingTheField)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    const BrokenAsset wrong[] = {
        {"badObject.gltf", ": /materials/0/pbrMetallicRoughness: pbrMetallicRoughness must be an object, got an array"},
        {"badString.gltf", ": /scenes/0/name: name must be a string, got 42"},
        {"badUint.gltf", ": /materials/0/pbrMetallicRoughness/baseColorTexture/index: index must be an integer ≥ 0, "
                         "got -1; read as none"},
        {"badExtension.gltf", "KHR_texture_transform must be an object, got 'Not an object'"},
    };
    for (const BrokenAsset& asset : wrong) {
        SCOPED_TRACE(asset.file);
        const fs::path path = kAssimpGltf / "wrongTypes" / asset.file;
        Warnings warnings;
        const Model model = loadGltfFile(path, {.warnings = &warnings});
        EXPECT_FALSE(model.instances.empty());
        ASSERT_FALSE(warnings.messages().empty());
        EXPECT_TRUE(warnings.messages()[0].starts_with(path.string() + ": /")) << warnings.messages()[0];
        EXPECT_NE(warnings.messages()[0].find(asset.phrase), std::string::npos) << warnings.messages()[0];
        Warnings strict(true);
        EXPECT_EQ(errorThrownBy([&] { loadGltfFile(path, {.warnings = &strict}); }), warnings.messages()[0]);
    }
    const fs::path badArray = kAssimpGltf / "wrongTypes/badArray.gltf";
    Warnings warnings;
    EXPECT_NE(errorThrownBy([&] { loadGltfFile(badArray, {.warnings = &warnings}); }).find("no triangle mesh"),
              std::string::npos);
    const fs::path badNumber = kAssimpGltf / "wrongTypes/badNumber.gltf";
    EXPECT_EQ(errorThrownBy([&] { loadGltfFile(badNumber); }),
              badNumber.string() + ": 'index' property is missing in NormalTextureInfo.");
}

// A missing external buffer is named by its full path, beside the model, not by its uri alone.
TEST(GltfAssimpModels, MissingBufferNamesItsFullPath)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    for (const char* folder : {"MissingBin", "SchemaFailures"}) {
        const fs::path model =
            kAssimpGltf / folder / (folder == std::string("MissingBin") ? "BoxTextured.gltf" : "sceneWrongType.gltf");
        EXPECT_EQ(errorThrownBy([&] { loadGltfFile(model); }), (kAssimpGltf / folder / "BoxTextured0.bin").string() +
                                                                   ": cannot open a buffer of " + model.string() +
                                                                   ": No such file or directory");
    }
}

TEST(GltfAssimpModels, EveryTruncationOfABinaryFileIsAnError)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    const std::vector<unsigned char> bytes = readBytes(kAssimpGltf / "BoxTextured-glTF-Binary/BoxTextured.glb");
    ASSERT_FALSE(bytes.empty());
    for (std::size_t size = 0; size < bytes.size(); size += 13) {
        const std::vector<unsigned char> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
        EXPECT_THROW(loadGltfMemory(cut, "cut.glb", {}, {1.0f / 256.0f, false}), Error) << size;
    }
}

TEST(GltfAssimpModels, PerspectiveCamerasLookDownTheirNodesMinusZ)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    Warnings warnings;
    const Model model = loadGltfFile(kAssimpGltf / "cameras/Cameras.gltf", {.warnings = &warnings});
    // Node 1 holds the perspective camera at (0.5, 0.5, 3); node 2's orthographic one has no
    // counterpart in the scene's camera and is passed over, with a warning.
    ASSERT_EQ(warnings.messages().size(), 1u);
    EXPECT_NE(warnings.messages()[0].find("cameras[1]: type orthographic has no counterpart"), std::string::npos)
        << warnings.messages()[0];
    ASSERT_EQ(model.cameras.size(), 1u);
    const Camera& camera = model.cameras[0].camera;
    EXPECT_EQ(model.cameras[0].name, "nodes[1]");
    EXPECT_EQ(camera.eye, glm::vec3(0.5f, 0.5f, 3.0f));
    EXPECT_EQ(camera.lookAt, glm::vec3(0.5f, 0.5f, 2.0f));
    EXPECT_EQ(camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_NEAR(camera.fovYDegrees, 0.7 * 180.0 / 3.14159265358979, 1e-4);
    EXPECT_FLOAT_EQ(camera.nearPlane, 0.01f);
    EXPECT_FLOAT_EQ(camera.farPlane, 100.0f);
}

TEST(GltfAssimpModels, OnlyVersion2GlbContainersAreRead)
{
    SKIP_WITHOUT_ASSIMP_MODELS();
    std::vector<unsigned char> bytes = readBytes(kAssimpGltf / "BoxTextured-glTF-Binary/BoxTextured.glb");
    ASSERT_GE(bytes.size(), 8u);
    EXPECT_NO_THROW(loadGltfMemory(bytes, "v2.glb", {}, {1.0f / 256.0f, false}));
    bytes[4] = 3;  // the little-endian version field
    try {
        loadGltfMemory(bytes, "v3.glb", {}, {1.0f / 256.0f, false});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "v3.glb: a .glb container of version 3; only version 2 (glTF 2.0) is read");
    }
}

}  // namespace
}  // namespace manylights
