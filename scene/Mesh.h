// Meshes as every loader and primitive builds them: indexed triangle lists in object space
// with the vertex attributes the shaders read, ranges drawn with a material of the model file,
// and their bounds. Apart from scene/Scene.h so that the mesh builders (scene/Meshes.h,
// scene/Revolution.h, scene/Tangents.h) need not see the whole scene.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace manylights {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    // Tangent-space basis for normal maps: xyz the unit tangent (direction of increasing u),
    // w the handedness (±1; bitangent = w · cross(normal, tangent)). All zero when the mesh has
    // no texture coordinates to derive it from.
    glm::vec4 tangent{0.0f};
    // Multiplies the material's base colour (glTF COLOR_0; alpha joins the coverage). White
    // unless the file gives colours (Mesh::hasVertexColours).
    glm::vec4 colour{1.0f};
};

// A range of a mesh's index list drawn with one material: a model file may give different
// groups different materials, all in the one vertex buffer of the model.
struct SubMesh {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    // The mesh file's own material for this range (index into Scene::materials); none means the
    // object's material.
    std::optional<std::size_t> material;
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
};

// Indexed triangle list in object space.
struct Mesh {
    std::string name;  // the primitive's description or the file it came from
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    // Empty: the whole index list is one range drawn with the object's material.
    std::vector<SubMesh> subMeshes;
    // Whether any vertex has a colour other than white: only then do the shaders read it.
    bool hasVertexColours = false;
    Bounds bounds() const;
};

}  // namespace manylights
