// The glTF reader behind scene/GltfLoader.h: the tinygltf model of a file, checked and turned
// into a Model. Its parts live in files of their own: GltfReader.cpp (the file as a whole, nodes,
// cameras and lights), GltfMeshes.cpp (accessors and meshes) and GltfMaterials.cpp (materials
// and textures); GltfLoader.cpp parses the file with tinygltf and hands the result here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

// tinygltf's configuration must be the same in every file that includes it (its declarations
// depend on it); scene/GltfLoader.cpp, which holds the implementation, says why each is set.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "core/Error.h"
#include "scene/GltfLoader.h"
#include "scene/Model.h"
#include "scene/Warnings.h"

namespace manylights::detail {

// `text` as one line: trailing line breaks and spaces dropped, the others made spaces.
std::string oneLine(std::string text);

// "array[index]", the JSON path of an element in messages.
std::string element(const char* array, std::size_t index);

// A checked view of an accessor's elements inside its buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

class GltfReader {
public:
    // `warnings` holds what was noted before tinygltf read the file (scene/GltfFieldChecks.h).
    GltfReader(const tinygltf::Model& gltf, const std::string& displayName, const std::filesystem::path& baseDirectory,
               const GltfOptions& options, FileWarnings warnings)
        : gltf_(gltf),
          displayName_(displayName),
          base_(baseDirectory),
          options_(options),
          warnings_(std::move(warnings))
    {
    }

    Model read();

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(oneLine(displayName_ + ": " + what)); }

    // The extensions this loader reads. A file that requires another cannot be drawn as its
    // author meant (an error); one that only uses another is drawn without it (a warning).
    void checkExtensions();

    // --- nodes ---------------------------------------------------------------------------

    void checkHierarchy() const;

    // The default scene's root nodes; without scenes, every node that is no node's child.
    std::vector<int> rootNodes() const;

    glm::mat4 localMatrix(std::size_t index) const;

    void visit(int nodeIndex, const glm::mat4& parent, int depth);

    // --- cameras -------------------------------------------------------------------------

    // A perspective camera looks down its node's −Z with +Y up (glTF 2.0, "Cameras"). Its
    // aspect ratio is the image's, as for the scene's camera; without zfar (an infinite
    // projection) the far plane is 1000 · znear beyond the default, whichever is larger.
    // Orthographic cameras have no counterpart in the scene's camera: passed over, with a warning.
    void addCamera(int cameraIndex, const glm::mat4& world, const std::string& name, std::size_t nodeIndex);

    // --- lights --------------------------------------------------------------------------

    std::optional<std::size_t> punctualLight(const tinygltf::Node& node) const;

    void addLight(std::size_t lightIndex, const glm::mat4& world, std::size_t nodeIndex);

    // --- accessors -----------------------------------------------------------------------

    AccessorView accessor(int index, const std::string& where) const;

    const std::vector<unsigned char>& bufferOf(const tinygltf::BufferView& view, std::size_t viewIndex) const;

    // Element i of a float (or normalised integer) accessor, `n` components.
    template <int N>
    glm::vec<N, float> readVector(const AccessorView& view, std::size_t i) const;

    // Checks that an attribute has the type the loader reads.
    void expectFormat(const AccessorView& view, int components, bool allowNormalizedInts,
                      const std::string& where) const;

    // --- meshes --------------------------------------------------------------------------

    std::optional<std::size_t> meshFor(std::size_t meshIndex);

    Mesh readMesh(std::size_t meshIndex);

    // Appends the primitive's triangles to `mesh`. Points and lines are skipped (they have no
    // surface to light); strips and fans are turned into triangle lists.
    void readPrimitive(const tinygltf::Primitive& primitive, const std::string& where, Mesh& mesh);

    static std::vector<std::uint32_t> triangleList(const std::vector<std::uint32_t>& corners, int mode);

    // --- materials -----------------------------------------------------------------------

    std::optional<std::size_t> materialFor(int index, const std::string& where);

    Material convertMaterial(std::size_t index);

    // alphaMode, alphaCutoff and the base colour's alpha.
    void readCoverage(const tinygltf::Material& source, const std::string& where, Material& material);

    // A texture reference's path, with its KHR_texture_transform (if any) stored in the
    // material's slot. Only TEXCOORD_0 is read: another set is drawn with it, with a warning.
    template <typename TextureReference>
    std::string texturePath(const TextureReference& reference, const std::string& where, Material& material,
                            MaterialMapSlot slot);

    // KHR_texture_transform's uv' = T · R · S · uv in glTF's uv convention (origin at the top
    // left), conjugated by the v flip readPrimitive applies (F: v → 1 − v, its own inverse), so
    // that it applies to our uvs: F · T · R · S · F.
    glm::mat3 uvTransform(const tinygltf::Value& extension, const std::string& where) const;

    // The path (or Scene::encodedImages key) of a texture's image; empty without a texture.
    std::string texturePath(int textureIndex, const std::string& where);

    // A texture's sampler's wrap modes (none: repeat, glTF's default). Its filters are not
    // read: every map is filtered trilinearly or anisotropically (--anisotropy).
    MapWrap samplerWrap(int samplerIndex);

    std::string imagePath(std::size_t index);

    static constexpr std::size_t kNoTriangles = std::numeric_limits<std::size_t>::max();

    const tinygltf::Model& gltf_;
    std::string displayName_;
    std::filesystem::path base_;
    GltfOptions options_;
    FileWarnings warnings_;  // flushed into options_.warnings once the file has loaded
    Model model_;
    std::vector<std::optional<std::size_t>> meshOf_;      // glTF mesh → Model::meshes
    std::vector<std::optional<std::size_t>> materialOf_;  // glTF material → Model::materials
    std::vector<std::optional<std::string>> imagePathOf_;
    std::vector<bool> onPath_;  // nodes between the root and the node being visited
};

}  // namespace manylights::detail
