// glTF accessors, checked against their buffers, and meshes (scene/GltfReader.h).
#include "scene/GltfReader.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/Meshes.h"

namespace manylights::detail {

namespace fs = std::filesystem;

AccessorView GltfReader::accessor(int index, const std::string& where) const
{
    if (index < 0 || static_cast<std::size_t>(index) >= gltf_.accessors.size())
        fail(where + ": accessor " + std::to_string(index) + " is not an accessor (the file has " +
             std::to_string(gltf_.accessors.size()) + ")");
    const tinygltf::Accessor& a = gltf_.accessors[static_cast<std::size_t>(index)];
    const std::string name = element("accessors", static_cast<std::size_t>(index));
    if (a.sparse.isSparse)
        fail(name + ": sparse accessors are not supported");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= gltf_.bufferViews.size())
        fail(name + ": bufferView " + std::to_string(a.bufferView) + " is not a buffer view (the file has " +
             std::to_string(gltf_.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = gltf_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::vector<unsigned char>& buffer = bufferOf(view, static_cast<std::size_t>(a.bufferView));
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (componentSize <= 0 || components <= 0 || componentSize > 4)
        fail(name + ": unsupported componentType " + std::to_string(a.componentType) + " or type " +
             std::to_string(a.type));
    const std::size_t elementSize = static_cast<std::size_t>(componentSize) * static_cast<std::size_t>(components);
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize)
        fail(element("bufferViews", static_cast<std::size_t>(a.bufferView)) + ": byteStride " + std::to_string(stride) +
             " is smaller than the element size " + std::to_string(elementSize) + " of " + name);
    // Everything in 64-bit sizes, each step checked before it can overflow.
    if (a.byteOffset > view.byteLength ||
        (a.count > 0 && ((a.count - 1) > (view.byteLength - a.byteOffset) / stride ||
                         (a.count - 1) * stride + elementSize > view.byteLength - a.byteOffset)))
        fail(name + ": " + std::to_string(a.count) + " elements at byteOffset " + std::to_string(a.byteOffset) +
             " do not fit in bufferViews[" + std::to_string(a.bufferView) + "] (" + std::to_string(view.byteLength) +
             " bytes)");
    AccessorView result;
    result.data = buffer.data() + view.byteOffset + a.byteOffset;
    result.count = a.count;
    result.stride = stride;
    result.componentType = a.componentType;
    result.components = components;
    result.normalized = a.normalized;
    return result;
}

const std::vector<unsigned char>& GltfReader::bufferOf(const tinygltf::BufferView& view, std::size_t viewIndex) const
{
    const std::string name = element("bufferViews", viewIndex);
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= gltf_.buffers.size())
        fail(name + ": buffer " + std::to_string(view.buffer) + " is not a buffer (the file has " +
             std::to_string(gltf_.buffers.size()) + ")");
    const std::vector<unsigned char>& data = gltf_.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        fail(name + ": bytes " + std::to_string(view.byteOffset) + " to " +
             std::to_string(view.byteOffset + view.byteLength) + " lie outside buffers[" + std::to_string(view.buffer) +
             "] (" + std::to_string(data.size()) + " bytes)");
    return data;
}

template <int N>
glm::vec<N, float> GltfReader::readVector(const AccessorView& view, std::size_t i) const
{
    glm::vec<N, float> result{0.0f};
    const unsigned char* at = view.data + i * view.stride;
    for (int k = 0; k < N; ++k) {
        switch (view.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&result[k], at + 4 * k, 4); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: result[k] = static_cast<float>(at[k]) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, at + 2 * k, 2);
            result[k] = static_cast<float>(v) / 65535.0f;
            break;
        }
        default: break;
        }
    }
    return result;
}

void GltfReader::expectFormat(const AccessorView& view, int components, bool allowNormalizedInts,
                              const std::string& where) const
{
    const bool floats = view.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool normalizedInts = allowNormalizedInts && view.normalized &&
                                (view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                 view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (view.components != components || !(floats || normalizedInts))
        fail(where + ": expected " + std::to_string(components) + " float components" +
             (allowNormalizedInts ? " (or normalised unsigned bytes/shorts)" : "") + ", got componentType " +
             std::to_string(view.componentType) + " with " + std::to_string(view.components));
}

std::optional<std::size_t> GltfReader::meshFor(std::size_t meshIndex)
{
    if (!meshOf_[meshIndex]) {
        Mesh mesh = readMesh(meshIndex);
        if (mesh.indices.empty()) {
            meshOf_[meshIndex] = kNoTriangles;
        } else {
            meshOf_[meshIndex] = model_.meshes.size();
            model_.meshes.push_back(std::move(mesh));
        }
    }
    if (*meshOf_[meshIndex] == kNoTriangles)
        return std::nullopt;
    return meshOf_[meshIndex];
}

Mesh GltfReader::readMesh(std::size_t meshIndex)
{
    const tinygltf::Mesh& source = gltf_.meshes[meshIndex];
    Mesh mesh;
    mesh.name = displayName_ + "#" + (source.name.empty() ? element("meshes", meshIndex) : source.name);
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
        const std::string where = element("meshes", meshIndex) + "." + element("primitives", p);
        const std::size_t first = mesh.indices.size();
        readPrimitive(source.primitives[p], where, mesh);
        if (mesh.indices.size() == first)
            continue;
        SubMesh range;
        range.firstIndex = static_cast<std::uint32_t>(first);
        range.indexCount = static_cast<std::uint32_t>(mesh.indices.size() - first);
        range.material = materialFor(source.primitives[p].material, where);
        mesh.subMeshes.push_back(range);
    }
    return mesh;
}

void GltfReader::readPrimitive(const tinygltf::Primitive& primitive, const std::string& where, Mesh& mesh)
{
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP)
            return;
        fail(where + ": unknown mode " + std::to_string(mode));
    }
    const auto attribute = [&](const char* name) -> std::optional<AccessorView> {
        const auto found = primitive.attributes.find(name);
        if (found == primitive.attributes.end())
            return std::nullopt;
        return accessor(found->second, where + "." + name);
    };
    const auto positions = attribute("POSITION");
    if (!positions)
        fail(where + ": has no POSITION attribute");
    expectFormat(*positions, 3, false, where + ".POSITION");
    const std::size_t vertexCount = positions->count;
    const auto normals = attribute("NORMAL");
    const auto uvs = attribute("TEXCOORD_0");
    const auto tangents = attribute("TANGENT");
    const auto colours = attribute("COLOR_0");
    const auto sameCount = [&](const std::optional<AccessorView>& view, const char* name, int components,
                               bool normalizedInts) {
        if (!view)
            return;
        expectFormat(*view, components, normalizedInts, where + "." + name);
        if (view->count != vertexCount)
            fail(where + "." + name + ": has " + std::to_string(view->count) + " elements, POSITION has " +
                 std::to_string(vertexCount));
    };
    sameCount(normals, "NORMAL", 3, false);
    sameCount(uvs, "TEXCOORD_0", 2, true);
    sameCount(tangents, "TANGENT", 4, false);
    if (colours) {
        // RGB or RGBA, floats or normalised unsigned bytes/shorts (glTF 2.0, "Meshes").
        sameCount(colours, "COLOR_0", colours->components == 3 ? 3 : 4, true);
        mesh.hasVertexColours = true;
    }

    // The primitive's corner list: its indices, or 0..n−1 when it has none.
    std::vector<std::uint32_t> corners;
    if (primitive.indices >= 0) {
        const AccessorView indices = accessor(primitive.indices, where + ".indices");
        if (indices.components != 1 || (indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                        indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                        indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            fail(where + ".indices: expected unsigned byte, short or int scalars");
        corners.resize(indices.count);
        for (std::size_t i = 0; i < indices.count; ++i) {
            const unsigned char* at = indices.data + i * indices.stride;
            std::uint32_t value = 0;
            if (indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                value = at[0];
            } else if (indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                std::uint16_t v;
                std::memcpy(&v, at, 2);
                value = v;
            } else {
                std::memcpy(&value, at, 4);
            }
            if (value >= vertexCount)
                fail(where + ".indices: index " + std::to_string(i) + " is " + std::to_string(value) +
                     ", out of range (POSITION has " + std::to_string(vertexCount) + " elements)");
            corners[i] = value;
        }
    } else {
        if (vertexCount > std::numeric_limits<std::uint32_t>::max())
            fail(where + ": too many vertices for 32-bit indices");
        corners.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            corners[i] = static_cast<std::uint32_t>(i);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && corners.size() % 3 != 0)
        fail(where + ": " + std::to_string(corners.size()) + " corners are not whole triangles (not a multiple of 3)");
    const std::vector<std::uint32_t> triangles = triangleList(corners, mode);

    // glTF asks for flat normals when a primitive has none, so such a primitive gets three
    // vertices of its own per triangle; otherwise its vertices are shared as in the file.
    const bool flat = !normals;
    const auto vertexAt = [&](std::uint32_t i) {
        Vertex vertex{readVector<3>(*positions, i), glm::vec3{0.0f, 1.0f, 0.0f}, glm::vec2{0.0f}};
        if (!std::isfinite(vertex.position.x + vertex.position.y + vertex.position.z))
            fail(where + ".POSITION: element " + std::to_string(i) + " is not finite");
        if (normals) {
            const glm::vec3 n = readVector<3>(*normals, i);
            const float length = glm::length(n);
            if (!std::isfinite(length))
                fail(where + ".NORMAL: element " + std::to_string(i) + " is not finite");
            vertex.normal = length > 0.0f ? n / length : glm::vec3{0.0f, 1.0f, 0.0f};
        }
        if (uvs) {
            vertex.uv = readVector<2>(*uvs, i);
            if (!std::isfinite(vertex.uv.x + vertex.uv.y))
                fail(where + ".TEXCOORD_0: element " + std::to_string(i) + " is not finite");
            // glTF's uv origin is the image's top-left corner; ours (OBJ, GL, the texture
            // cache's bottom-up rows) the bottom-left.
            vertex.uv.y = 1.0f - vertex.uv.y;
        }
        if (colours) {
            vertex.colour =
                colours->components == 3 ? glm::vec4(readVector<3>(*colours, i), 1.0f) : readVector<4>(*colours, i);
            if (!std::isfinite(vertex.colour.r + vertex.colour.g + vertex.colour.b + vertex.colour.a))
                fail(where + ".COLOR_0: element " + std::to_string(i) + " is not finite");
            // Colours are linear and in [0, 1] by the specification; anything outside is clamped.
            vertex.colour = glm::clamp(vertex.colour, 0.0f, 1.0f);
        }
        if (tangents) {
            vertex.tangent = readVector<4>(*tangents, i);
            if (!std::isfinite(vertex.tangent.x + vertex.tangent.y + vertex.tangent.z + vertex.tangent.w))
                fail(where + ".TANGENT: element " + std::to_string(i) + " is not finite");
            // w is the handedness, ±1 by the specification; anything else is read by its sign.
            // Flipping v above reverses the bitangent (the direction of increasing v), so
            // the handedness flips with it.
            vertex.tangent.w = vertex.tangent.w < 0.0f ? 1.0f : -1.0f;
        }
        return vertex;
    };
    const std::size_t base = mesh.vertices.size();
    std::vector<std::int64_t> slotOf(flat ? 0 : vertexCount, -1);
    const auto addCorner = [&](std::uint32_t i) {
        if (mesh.vertices.size() >= std::numeric_limits<std::uint32_t>::max())
            fail(where + ": too many vertices for 32-bit indices");
        if (flat) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
            mesh.vertices.push_back(vertexAt(i));
            return;
        }
        if (slotOf[i] < 0) {
            slotOf[i] = static_cast<std::int64_t>(mesh.vertices.size());
            mesh.vertices.push_back(vertexAt(i));
        }
        mesh.indices.push_back(static_cast<std::uint32_t>(slotOf[i]));
    };
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::vec3 a = readVector<3>(*positions, triangles[t]);
        const glm::vec3 b = readVector<3>(*positions, triangles[t + 1]);
        const glm::vec3 c = readVector<3>(*positions, triangles[t + 2]);
        // Zero-area triangles draw nothing and have no normal: dropped, as in OBJ files.
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z))
            fail(where + ".POSITION: a triangle has a non-finite corner");
        if (isDegenerateTriangle(a, b, c))
            continue;
        for (std::size_t k = 0; k < 3; ++k)
            addCorner(triangles[t + k]);
    }
    if (flat) {
        for (std::size_t v = base; v + 2 < mesh.vertices.size(); v += 3) {
            const glm::vec3 n = glm::normalize(glm::cross(mesh.vertices[v + 1].position - mesh.vertices[v].position,
                                                          mesh.vertices[v + 2].position - mesh.vertices[v].position));
            for (std::size_t k = 0; k < 3; ++k)
                mesh.vertices[v + k].normal = std::isfinite(n.x + n.y + n.z) ? n : glm::vec3{0.0f, 1.0f, 0.0f};
        }
    }
}

std::vector<std::uint32_t> GltfReader::triangleList(const std::vector<std::uint32_t>& corners, int mode)
{
    if (mode == TINYGLTF_MODE_TRIANGLES)
        return corners;
    std::vector<std::uint32_t> list;
    for (std::size_t i = 2; i < corners.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            list.insert(list.end(), {corners[0], corners[i - 1], corners[i]});
        else if (i % 2 == 0)  // strip: every other triangle flips to keep the winding
            list.insert(list.end(), {corners[i - 2], corners[i - 1], corners[i]});
        else
            list.insert(list.end(), {corners[i - 1], corners[i - 2], corners[i]});
    }
    return list;
}

}  // namespace manylights::detail
