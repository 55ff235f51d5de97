// The Wavefront OBJ and MTL loader (docs/scene-format.md): tinyobjloader parses the text after
// this file has decoded it and checked its element indices, and the MTL materials and their
// map paths become Materials. Problems other tools forgive are warnings (scene/Warnings.h).
#include "scene/ObjLoader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "core/Error.h"
#include "core/InputFile.h"
#include "scene/Meshes.h"
#include "scene/MtlMaterials.h"
#include "scene/ObjText.h"
#include "scene/Warnings.h"

namespace manylights {

namespace fs = std::filesystem;

namespace {

// The text checks (scene/ObjText.h) and the MTL materials (scene/MtlMaterials.h).
using detail::checkedNumbers;
using detail::checkElementIndices;
using detail::convertMaterial;
using detail::decodedText;
using detail::failIn;
using detail::firstLine;
using detail::forEachLine;
using detail::kMtlNumberKeywords;
using detail::kMtlStatements;
using detail::kObjNumberKeywords;
using detail::kObjStatements;
using detail::MtlLibrary;
using detail::trim;

// A face corner's (position, normal, texture coordinate) indices: one vertex per distinct key.
struct CornerKey {
    int position, normal, uv;
    bool operator==(const CornerKey&) const = default;
};

struct CornerKeyHash {
    std::size_t operator()(const CornerKey& key) const
    {
        std::size_t hash = static_cast<std::uint32_t>(key.position);
        hash = hash * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.normal);
        return hash * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(key.uv);
    }
};

// Hands tinyobjloader the text of each `mtllib`, after checking its numbers, and records
// where each material came from. A library that is missing is noted on the OBJ file, and its
// materials are missing (their faces take the object's material).
class CheckedMaterialReader : public tinyobj::MaterialReader {
public:
    CheckedMaterialReader(const std::string& objText, const fs::path& baseDirectory, const MtlSource& source,
                          FileWarnings& objWarnings)
        : objText_(objText), base_(baseDirectory), source_(source), objWarnings_(objWarnings)
    {
    }

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* materialMap, std::string* warning, std::string* error) override
    {
        const fs::path path = base_ / name;
        std::optional<std::string> text = source_(name);
        if (!text) {
            objWarnings_.note(mtllibLine(name), "mtllib " + name,
                              "material library '" + name + "' not found (looked for " + path.string() +
                                  "); faces using its materials take the object's material");
            return true;
        }
        MtlLibrary library{path.string(), path.parent_path(), std::move(*text), FileWarnings(path.string())};
        library.text = decodedText(library.text, library.warnings);
        library.text = checkedNumbers(library.text, library.displayName, kMtlNumberKeywords, kMtlStatements,
                                      library.warnings, true);
        const std::size_t before = materials->size();
        std::istringstream stream(library.text);
        tinyobj::LoadMtl(materialMap, materials, &stream, warning, error);
        if (error && !error->empty())
            failIn(library.displayName, firstLine(*error));
        for (std::size_t i = before; i < materials->size(); ++i)
            libraryOf_.push_back(libraries_.size());
        libraries_.push_back(std::move(library));
        return true;
    }

    MtlLibrary& libraryOf(std::size_t material) { return libraries_[libraryOf_[material]]; }
    void flushInto(Warnings& warnings) const
    {
        for (const MtlLibrary& library : libraries_)
            library.warnings.flushInto(warnings);
    }

private:
    std::size_t mtllibLine(const std::string& name) const
    {
        std::size_t at = 0;
        forEachLine(objText_, [&](std::size_t lineNumber, std::string_view keyword, std::string_view rest) {
            if (at == 0 && keyword == "mtllib" && rest.find(name) != std::string_view::npos)
                at = lineNumber;
        });
        return at;
    }

    const std::string& objText_;
    fs::path base_;
    const MtlSource& source_;
    FileWarnings& objWarnings_;
    std::vector<MtlLibrary> libraries_;
    std::vector<std::size_t> libraryOf_;
};

}  // namespace

Model loadObjModelText(const std::string& fileText, const std::string& displayName, const fs::path& baseDirectory,
                       const MtlSource& mtlSource, Warnings& forgiven)
{
    FileWarnings warnings(displayName);
    std::string text = decodedText(fileText, warnings);
    text = checkedNumbers(text, displayName, kObjNumberKeywords, kObjStatements, warnings, false);
    checkElementIndices(text, displayName);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning;
    std::string error;
    std::istringstream textStream(text);
    const bool useMaterials = static_cast<bool>(mtlSource);
    const MtlSource noSource = [](const std::string&) { return std::optional<std::string>{}; };
    CheckedMaterialReader reader(text, baseDirectory, useMaterials ? mtlSource : noSource, warnings);
    // No triangulation by tinyobjloader: it reads vertex arrays through unchecked indices
    // while doing so. Polygons are fanned below, after the indices are checked.
    const bool ok =
        tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &textStream, useMaterials ? &reader : nullptr,
                         /*triangulate=*/false, /*default_vcols_fallback=*/false);
    if (!ok || !error.empty())
        failIn(displayName, firstLine(error.empty() ? std::string("cannot parse the file") : error));

    if (useMaterials) {
        // A `usemtl` no library defines (often "Default" with no mtllib at all): its faces take
        // the object's material, as other viewers give them their default one.
        std::set<std::string> known;
        for (const tinyobj::material_t& material : materials)
            known.insert(material.name);
        forEachLine(text, [&](std::size_t lineNumber, std::string_view keyword, std::string_view rest) {
            const std::string name(trim(rest));
            if (keyword == "usemtl" && !known.contains(name))
                warnings.note(
                    lineNumber, "usemtl " + name,
                    "usemtl '" + name +
                        "': no material library of the file defines it; its faces take the object's material");
        });
    }

    const auto positionCount = static_cast<long long>(attrib.vertices.size() / 3);
    const auto normalCount = static_cast<long long>(attrib.normals.size() / 3);
    const auto uvCount = static_cast<long long>(attrib.texcoords.size() / 2);
    const auto checkIndex = [&](int index, long long count, bool optional, const char* what) {
        if (optional && index == -1)
            return;
        // tinyobjloader has already turned a negative (relative) index into an absolute one,
        // so a negative result here means it reached before the first element.
        if (index < 0)
            failIn(displayName, std::string("a negative ") + what + " index reaches before the first one");
        if (index >= count)
            failIn(displayName, std::string(what) + " index " + std::to_string(index + 1) +
                                    " is out of range (the file has " + std::to_string(count) + ")");
    };
    const auto position = [&](int index) {
        const auto i = static_cast<std::size_t>(index) * 3;
        return glm::vec3{attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]};
    };

    Mesh mesh;
    mesh.name = displayName;
    // Hashed, not ordered: loading time stays linear in the file's size.
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertexOf;
    std::vector<bool> needsNormal;
    const auto vertexFor = [&](const tinyobj::index_t& index) {
        const CornerKey key{index.vertex_index, index.normal_index, index.texcoord_index};
        const auto [it, inserted] = vertexOf.try_emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (inserted) {
            if (mesh.vertices.size() >= std::numeric_limits<std::uint32_t>::max())
                failIn(displayName, "has too many vertices for 32-bit indices");
            Vertex vertex{position(index.vertex_index), glm::vec3{0.0f, 1.0f, 0.0f}, glm::vec2{0.0f}};
            bool hasNormal = false;
            if (index.normal_index >= 0) {
                const auto n = static_cast<std::size_t>(index.normal_index) * 3;
                vertex.normal = {attrib.normals[n], attrib.normals[n + 1], attrib.normals[n + 2]};
                const float length = glm::length(vertex.normal);
                // A file's zero normal cannot be normalised; it is replaced like a missing one.
                hasNormal = length > 0.0f && std::isfinite(length);
                if (hasNormal)
                    vertex.normal /= length;
            }
            if (index.texcoord_index >= 0) {
                const auto t = static_cast<std::size_t>(index.texcoord_index) * 2;
                vertex.uv = {attrib.texcoords[t], attrib.texcoords[t + 1]};
            }
            needsNormal.push_back(!hasNormal);
            mesh.vertices.push_back(vertex);
        }
        return it->second;
    };

    // Triangles are gathered per material (in the order the materials are first used) so that
    // each material is one contiguous draw range of the one index list. −1: no material.
    std::vector<std::pair<int, std::vector<std::uint32_t>>> ranges;
    std::map<int, std::size_t> rangeOf;
    std::size_t faceCount = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const unsigned char corners = shape.mesh.num_face_vertices[f];
            const tinyobj::index_t* face = shape.mesh.indices.data() + offset;
            offset += corners;
            for (unsigned char k = 0; k < corners; ++k) {
                checkIndex(face[k].vertex_index, positionCount, false, "vertex");
                checkIndex(face[k].normal_index, normalCount, true, "normal");
                checkIndex(face[k].texcoord_index, uvCount, true, "texture coordinate");
            }
            if (corners < 3)
                continue;
            ++faceCount;
            int material = -1;
            if (useMaterials && f < shape.mesh.material_ids.size())
                material = shape.mesh.material_ids[f];
            if (material < -1 || material >= static_cast<int>(materials.size()))
                material = -1;
            const auto [slot, added] = rangeOf.try_emplace(material, ranges.size());
            if (added)
                ranges.push_back({material, {}});
            std::vector<std::uint32_t>& indices = ranges[slot->second].second;
            // Fan triangulation: exact for the convex polygons OBJ exporters write. Zero-area
            // triangles are dropped: they draw nothing and have no normal.
            for (unsigned char k = 1; k + 1 < corners; ++k) {
                const tinyobj::index_t& a = face[0];
                const tinyobj::index_t& b = face[k];
                const tinyobj::index_t& c = face[k + 1];
                if (isDegenerateTriangle(position(a.vertex_index), position(b.vertex_index), position(c.vertex_index)))
                    continue;
                indices.insert(indices.end(), {vertexFor(a), vertexFor(b), vertexFor(c)});
            }
        }
    }
    if (faceCount == 0)
        failIn(displayName, "has no faces");

    Model model;
    std::map<int, std::size_t> modelMaterialOf;
    const bool anyMaterial = rangeOf.size() > 1 || (rangeOf.size() == 1 && rangeOf.begin()->first != -1);
    for (auto& [material, indices] : ranges) {
        if (indices.empty())
            continue;
        SubMesh range;
        range.firstIndex = static_cast<std::uint32_t>(mesh.indices.size());
        range.indexCount = static_cast<std::uint32_t>(indices.size());
        if (material >= 0) {
            const auto [slot, added] = modelMaterialOf.try_emplace(material, model.materials.size());
            if (added)
                model.materials.push_back(convertMaterial(materials[static_cast<std::size_t>(material)],
                                                          reader.libraryOf(static_cast<std::size_t>(material)),
                                                          displayName));
            range.material = slot->second;
        }
        mesh.indices.insert(mesh.indices.end(), indices.begin(), indices.end());
        if (anyMaterial)
            mesh.subMeshes.push_back(range);
    }
    if (mesh.indices.empty())
        failIn(displayName, "every triangle has zero area");
    // Checked again after conversion: a finite number in the text can still overflow a float.
    for (const Vertex& vertex : mesh.vertices)
        if (!std::isfinite(vertex.position.x + vertex.position.y + vertex.position.z) ||
            !std::isfinite(vertex.uv.x + vertex.uv.y))
            failIn(displayName, "has a non-finite vertex position or texture coordinate");

    computeSmoothNormals(mesh, needsNormal);
    model.meshes.push_back(std::move(mesh));
    model.instances.push_back({displayName, 0, glm::mat4{1.0f}});
    warnings.flushInto(forgiven);
    reader.flushInto(forgiven);
    return model;
}

namespace {

std::optional<std::string> readTextFile(const fs::path& path)
{
    if (!inputFileProblem(path).empty())
        return std::nullopt;
    try {
        return readInputFile(path, "the file");
    } catch (const Error&) {
        return std::nullopt;
    }
}

}  // namespace

Model loadObjModelFile(const fs::path& path, Warnings& warnings)
{
    const std::string displayName = path.string();
    const std::string text = readInputFile(path, "the file");
    const fs::path directory = path.parent_path();
    return loadObjModelText(
        text, displayName, directory, [&](const std::string& name) { return readTextFile(directory / name); },
        warnings);
}

Mesh loadObjStream(std::istream& stream, const std::string& displayName)
{
    const std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    if (stream.bad())
        throw Error(displayName + ": cannot read the file");
    // Materials are not read here, so nothing about them can be forgiven; a plain mesh's other
    // warnings (an unknown statement) do not concern its one use, the built-in scene's assets.
    Warnings ignored;
    Model model = loadObjModelText(text, displayName, {}, MtlSource{}, ignored);
    return std::move(model.meshes.front());
}

Mesh loadObjFile(const std::filesystem::path& path)
{
    std::istringstream stream(readInputFile(path, "the file"));
    return loadObjStream(stream, path.string());
}

}  // namespace manylights
