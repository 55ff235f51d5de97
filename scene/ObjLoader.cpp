#include "scene/ObjLoader.h"

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
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "core/Error.h"
#include "core/InputFile.h"
#include "scene/Meshes.h"

namespace manylights {

namespace fs = std::filesystem;

namespace {

// Above this, MTL and glTF shininess values add nothing visible and only risk pow() overflow.
constexpr float kMaxShininess = 2048.0f;

[[noreturn]] void fail(const std::string& displayName, const std::string& what)
{
    throw Error(displayName + ": " + what);
}

std::string firstLine(const std::string& text)
{
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == '.' || line.back() == ' '))
        line.pop_back();
    return line;
}

std::string trim(const std::string& text)
{
    const std::size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos)
        return {};
    const std::size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

// Calls visit(lineNumber, keyword, rest-of-line) for every line of `text`.
template <typename Visit>
void forEachLine(const std::string& text, Visit visit)
{
    std::size_t lineNumber = 0;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos)
            end = text.size();
        ++lineNumber;
        const std::string line = text.substr(begin, end - begin);
        begin = end + 1;
        const std::size_t keywordBegin = line.find_first_not_of(" \t");
        if (keywordBegin == std::string::npos)
            continue;
        const std::size_t keywordEnd = std::min(line.find_first_of(" \t\r", keywordBegin), line.size());
        visit(lineNumber, line.substr(keywordBegin, keywordEnd - keywordBegin), line.substr(keywordEnd));
    }
}

// tinyobjloader reads "nan", "inf" and other malformed numbers as 0 without a word, so the
// numbers of the lines that carry them are checked here first, with the line number.
// `keywords` maps a keyword to its description and the count of numbers it needs.
// With `nonNegative` (material libraries: colours and the exponent) a number below zero is an
// error too: a negative reflectance has no meaning, and the scene format refuses it as well.
void checkNumbers(const std::string& text, const std::string& displayName,
                  const std::map<std::string, std::pair<const char*, int>>& keywords, bool nonNegative = false)
{
    forEachLine(text, [&](std::size_t lineNumber, const std::string& keyword, const std::string& rest) {
        const auto found = keywords.find(keyword);
        if (found == keywords.end())
            return;
        const auto [what, needed] = found->second;
        std::istringstream line(rest);
        int count = 0;
        for (std::string token; line >> token;) {
            if (token.front() == '#')
                break;
            float value = 0.0f;
            const char* first = token.data();
            const char* last = first + token.size();
            const auto [next, error] = std::from_chars(first, last, value);
            if (error != std::errc{} || next != last || !std::isfinite(value))
                fail(displayName, "line " + std::to_string(lineNumber) + ": " + what +
                                      " has a non-finite or malformed number '" + token + "'");
            if (nonNegative && value < 0.0f)
                fail(displayName, "line " + std::to_string(lineNumber) + ": " + what + " must not be negative, got '" +
                                      token + "'");
            ++count;
        }
        if (count < needed)
            fail(displayName, "line " + std::to_string(lineNumber) + ": " + what + " needs " +
                                  std::to_string(needed) + " numbers, has " + std::to_string(count));
    });
}

// tinyobjloader reads face indices with atoi, which wraps past 2^31: "f 1 2 4294967299" with
// three vertices drew a triangle. Every index of a face, line or point element must be an
// integer within int's range here first (the count of vertices is checked afterwards).
void checkElementIndices(const std::string& text, const std::string& displayName)
{
    forEachLine(text, [&](std::size_t lineNumber, const std::string& keyword, const std::string& rest) {
        if (keyword != "f" && keyword != "l" && keyword != "p")
            return;
        std::istringstream line(rest);
        for (std::string token; line >> token;) {
            if (token.front() == '#')
                break;
            std::size_t partBegin = 0;
            while (partBegin <= token.size()) {
                const std::size_t slash = std::min(token.find('/', partBegin), token.size());
                if (slash > partBegin) {  // "1//3" leaves the texture coordinate empty
                    long long index = 0;
                    const char* first = token.data() + partBegin;
                    const char* last = token.data() + slash;
                    const auto [next, error] = std::from_chars(first, last, index);
                    if (error != std::errc{} || next != last || index > std::numeric_limits<int>::max() ||
                        index < -static_cast<long long>(std::numeric_limits<int>::max()))
                        fail(displayName, "line " + std::to_string(lineNumber) + ": the index '" +
                                              token.substr(partBegin, slash - partBegin) +
                                              "' is not an integer within ±2147483647");
                }
                partBegin = slash + 1;
            }
        }
    });
}

const std::map<std::string, std::pair<const char*, int>> kObjNumberKeywords{
    {"v", {"vertex position", 3}}, {"vn", {"normal", 3}}, {"vt", {"texture coordinate", 1}}};

const std::map<std::string, std::pair<const char*, int>> kMtlNumberKeywords{
    {"Kd", {"Kd", 3}}, {"Ks", {"Ks", 3}}, {"Ke", {"Ke", 3}}, {"Ka", {"Ka", 3}}, {"Ns", {"Ns", 1}}};

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

// One material library as it was read: its name (for messages), its directory (for its maps)
// and its text (for line numbers).
struct MtlLibrary {
    std::string displayName;
    fs::path directory;
    std::string text;
};

// Hands tinyobjloader the text of each `mtllib`, after checking its numbers, and records
// where each material came from.
class CheckedMaterialReader : public tinyobj::MaterialReader {
public:
    CheckedMaterialReader(const std::string& objName, const std::string& objText, const fs::path& baseDirectory,
                          const MtlSource& source)
        : objName_(objName), objText_(objText), base_(baseDirectory), source_(source)
    {
    }

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* materialMap, std::string* warning, std::string* error) override
    {
        const fs::path path = base_ / name;
        std::optional<std::string> text = source_(name);
        if (!text)
            fail(objName_, "line " + std::to_string(mtllibLine(name)) + ": material library '" + name +
                               "' not found (looked for " + path.string() + ")");
        MtlLibrary library{path.string(), path.parent_path(), std::move(*text)};
        checkNumbers(library.text, library.displayName, kMtlNumberKeywords, true);
        const std::size_t before = materials->size();
        std::istringstream stream(library.text);
        tinyobj::LoadMtl(materialMap, materials, &stream, warning, error);
        if (error && !error->empty())
            fail(library.displayName, firstLine(*error));
        for (std::size_t i = before; i < materials->size(); ++i)
            libraryOf_.push_back(libraries_.size());
        libraries_.push_back(std::move(library));
        return true;
    }

    const MtlLibrary& libraryOf(std::size_t material) const { return libraries_[libraryOf_[material]]; }

private:
    std::size_t mtllibLine(const std::string& name) const
    {
        std::size_t at = 0;
        forEachLine(objText_, [&](std::size_t lineNumber, const std::string& keyword, const std::string& rest) {
            if (at == 0 && keyword == "mtllib" && rest.find(name) != std::string::npos)
                at = lineNumber;
        });
        return at;
    }

    std::string objName_;
    const std::string& objText_;
    fs::path base_;
    const MtlSource& source_;
    std::vector<MtlLibrary> libraries_;
    std::vector<std::size_t> libraryOf_;
};

// A map named by a material library, resolved against the library's directory; it must exist
// (the render layer decodes it). Empty when the material has none.
std::string mapPath(const MtlLibrary& library, const std::string& materialName, const char* keyword,
                    const std::string& name)
{
    if (name.empty())
        return {};
    const fs::path path = library.directory / name;
    std::error_code error;
    if (!fs::is_regular_file(path, error))
        fail(library.displayName, "material '" + materialName + "': " + keyword + " '" + name + "' not found (" +
                                      path.string() + ")");
    return path.string();
}

glm::vec3 colour(const tinyobj::real_t (&value)[3])
{
    return {value[0], value[1], value[2]};
}

Material convertMaterial(const tinyobj::material_t& source, const MtlLibrary& library, const std::string& objName)
{
    Material material;
    // Named after the file, so that it can never be taken for one of the scene's own
    // (named) materials.
    material.name = objName + "#" + source.name;
    material.diffuse = colour(source.diffuse);
    material.specular = colour(source.specular);
    material.emissive = colour(source.emission);
    material.shininess = std::clamp(static_cast<float>(source.shininess), 1.0f, kMaxShininess);
    material.diffuseMap = mapPath(library, source.name, "map_Kd", source.diffuse_texname);
    material.specularMap = mapPath(library, source.name, "map_Ks", source.specular_texname);
    material.emissiveMap = mapPath(library, source.name, "map_Ke", source.emissive_texname);
    // `norm` is the explicit normal map; map_Bump/bump is used as one too (what exporters
    // write there today), with -bm as its strength.
    if (!source.normal_texname.empty()) {
        material.normalMap = mapPath(library, source.name, "norm", source.normal_texname);
        material.normalScale = static_cast<float>(source.normal_texopt.bump_multiplier);
    } else {
        material.normalMap = mapPath(library, source.name, "map_Bump", source.bump_texname);
        material.normalScale = static_cast<float>(source.bump_texopt.bump_multiplier);
    }
    if (!std::isfinite(material.normalScale))
        fail(library.displayName, "material '" + source.name + "': non-finite -bm");
    // An MTL without Kd leaves it 0 in tinyobjloader, which would blacken its map_Kd: a
    // texture with no Kd is taken at face value (Kd = 1).
    if (!material.diffuseMap.empty() && material.diffuse == glm::vec3{0.0f})
        material.diffuse = glm::vec3{1.0f};
    return material;
}

}  // namespace

Model loadObjModelText(const std::string& text, const std::string& displayName, const fs::path& baseDirectory,
                       const MtlSource& mtlSource)
{
    checkNumbers(text, displayName, kObjNumberKeywords);
    checkElementIndices(text, displayName);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning;
    std::string error;
    std::istringstream textStream(text);
    const bool useMaterials = static_cast<bool>(mtlSource);
    const MtlSource noSource = [](const std::string&) { return std::optional<std::string>{}; };
    CheckedMaterialReader reader(displayName, text, baseDirectory, useMaterials ? mtlSource : noSource);
    // No triangulation by tinyobjloader: it reads vertex arrays through unchecked indices
    // while doing so. Polygons are fanned below, after the indices are checked.
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &textStream,
                                     useMaterials ? &reader : nullptr,
                                     /*triangulate=*/false, /*default_vcols_fallback=*/false);
    if (!ok || !error.empty())
        fail(displayName, firstLine(error.empty() ? std::string("cannot parse the file") : error));

    if (useMaterials) {
        // tinyobjloader only warns about a `usemtl` no library defines; it is an error here,
        // as an unknown material in the scene file is.
        std::set<std::string> known;
        for (const tinyobj::material_t& material : materials)
            known.insert(material.name);
        forEachLine(text, [&](std::size_t lineNumber, const std::string& keyword, const std::string& rest) {
            const std::string name = trim(rest);
            if (keyword == "usemtl" && !known.contains(name))
                fail(displayName, "line " + std::to_string(lineNumber) + ": usemtl '" + name +
                                      "': no material library of the file defines it");
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
            fail(displayName, std::string("a negative ") + what + " index reaches before the first one");
        if (index >= count)
            fail(displayName, std::string(what) + " index " + std::to_string(index + 1) +
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
                fail(displayName, "has too many vertices for 32-bit indices");
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
        fail(displayName, "has no faces");

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
        fail(displayName, "every triangle has zero area");
    // Checked again after conversion: a finite number in the text can still overflow a float.
    for (const Vertex& vertex : mesh.vertices)
        if (!std::isfinite(vertex.position.x + vertex.position.y + vertex.position.z) ||
            !std::isfinite(vertex.uv.x + vertex.uv.y))
            fail(displayName, "has a non-finite vertex position or texture coordinate");

    computeSmoothNormals(mesh, needsNormal);
    model.meshes.push_back(std::move(mesh));
    model.instances.push_back({displayName, 0, glm::mat4{1.0f}});
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

Model loadObjModelFile(const fs::path& path)
{
    const std::string displayName = path.string();
    const std::string text = readInputFile(path, "the file");
    const fs::path directory = path.parent_path();
    return loadObjModelText(text, displayName, directory,
                            [&](const std::string& name) { return readTextFile(directory / name); });
}

}  // namespace manylights
