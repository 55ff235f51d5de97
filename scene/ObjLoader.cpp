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
#include "scene/Shininess.h"
#include "scene/Warnings.h"

namespace manylights {

namespace fs = std::filesystem;

namespace {

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

std::string_view trim(std::string_view text)
{
    const std::size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos)
        return {};
    const std::size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

// Calls visit(lineNumber, line, isLast) for every line of `text` (without its '\n'). The
// views point into `text`: nothing is copied, which matters on the hot path of every OBJ load.
template <typename Visit>
void forEachRawLine(std::string_view text, Visit visit)
{
    std::size_t lineNumber = 0;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos)
            end = text.size();
        visit(++lineNumber, text.substr(begin, end - begin), end == text.size());
        begin = end + 1;
    }
}

// Calls visit(word) for each word of `line` (separated by spaces, tabs or a '\r'), stopping at
// a word that starts a '#' comment.
template <typename Visit>
void forEachWord(std::string_view line, Visit visit)
{
    for (std::size_t at = line.find_first_not_of(" \t\r"); at != std::string_view::npos;
         at = line.find_first_not_of(" \t\r", at)) {
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        const std::string_view word = line.substr(at, end - at);
        if (word.front() == '#')
            return;
        visit(word);
        at = end;
    }
}

// Calls visit(lineNumber, keyword, rest-of-line) for every line of `text` that is not blank.
template <typename Visit>
void forEachLine(std::string_view text, Visit visit)
{
    forEachRawLine(text, [&](std::size_t lineNumber, std::string_view line, bool) {
        const std::size_t keywordBegin = line.find_first_not_of(" \t");
        if (keywordBegin == std::string_view::npos)
            return;
        const std::size_t keywordEnd = std::min(line.find_first_of(" \t\r", keywordBegin), line.size());
        visit(lineNumber, line.substr(keywordBegin, keywordEnd - keywordBegin), line.substr(keywordEnd));
    });
}

// Appends code point `c` to `out` in UTF-8.
void appendUtf8(std::string& out, std::uint32_t c)
{
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

// The file's text as UTF-8: a UTF-8 byte-order mark is dropped, UTF-16 text (either byte
// order, told by its mark) is converted; both noted. Unpaired surrogates become U+FFFD.
std::string decodedText(const std::string& bytes, FileWarnings& warnings)
{
    const auto starts = [&](const char* mark, std::size_t length) {
        return bytes.compare(0, length, mark, length) == 0;
    };
    if (starts("\xEF\xBB\xBF", 3)) {
        warnings.noteFile("bom", "a UTF-8 byte-order mark, skipped");
        return bytes.substr(3);
    }
    const bool bigEndian = starts("\xFE\xFF", 2);
    if (!bigEndian && !starts("\xFF\xFE", 2))
        return bytes;
    warnings.noteFile("utf16",
                      std::string("UTF-16 text (") + (bigEndian ? "big" : "little") + "-endian), read as such");
    const auto unit = [&](std::size_t i) {
        const auto hi = static_cast<unsigned char>(bytes[bigEndian ? i : i + 1]);
        const auto lo = static_cast<unsigned char>(bytes[bigEndian ? i + 1 : i]);
        return static_cast<std::uint32_t>(hi << 8 | lo);
    };
    std::string text;
    text.reserve(bytes.size() / 2);
    for (std::size_t i = 2; i + 1 < bytes.size(); i += 2) {
        std::uint32_t c = unit(i);
        if (c >= 0xD800 && c < 0xDC00 && i + 3 < bytes.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) < 0xE000) {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c < 0xE000) {
            c = 0xFFFD;
        }
        appendUtf8(text, c);
    }
    return text;
}

// The statements this loader reads or knowingly passes over; any other is reported once.
const std::set<std::string, std::less<>> kObjStatements{"v", "vn", "vt", "vp", "f",      "l",
                                                        "p", "g",  "o",  "s",  "usemtl", "mtllib"};
const std::set<std::string, std::less<>> kMtlStatements{
    "newmtl",   "Ka",    "Kd",     "Ks",     "Ke",     "Ns",     "Ni",        "d",      "Tr",
    "Tf",       "illum", "map_Ka", "map_Kd", "map_Ks", "map_Ke", "map_Ns",    "map_d",  "map_bump",
    "map_Bump", "bump",  "norm",   "disp",   "decal",  "refl",   "sharpness", "Pr",     "Pm",
    "Ps",       "Pc",    "Pcr",    "aniso",  "anisor", "map_Pr", "map_Pm",    "map_Ps", "Tw"};

// What a keyword's numbers are, how many it needs, and whether one value stands for three (an
// MTL colour: "Ks 0.5" is grey, as the format allows).
struct NumberKeyword {
    const char* what;
    int needed;
    bool oneForThree;
};

const std::map<std::string, NumberKeyword, std::less<>> kObjNumberKeywords{
    {"v", {"vertex position", 3, false}}, {"vn", {"normal", 3, false}}, {"vt", {"texture coordinate", 1, false}}};

const std::map<std::string, NumberKeyword, std::less<>> kMtlNumberKeywords{{"Kd", {"Kd", 3, true}},
                                                                           {"Ks", {"Ks", 3, true}},
                                                                           {"Ke", {"Ke", 3, true}},
                                                                           {"Ka", {"Ka", 3, true}},
                                                                           {"Ns", {"Ns", 1, false}}};

// The text tinyobjloader is given: the numbers of the lines that carry them read here first,
// with the line number, since tinyobjloader reads "nan", "inf" and malformed numbers as 0
// without a word. Non-finite and unreadable numbers are errors; what other readers forgive
// is rewritten and noted: a leading '+', trailing characters after a number ("3.1+e2" reads
// as 3.1, as C's strtod and assimp read it), a one-value MTL colour. Unknown statements are
// noted once each. With `nonNegative` (material libraries) a number below zero is an error: a
// negative reflectance has no meaning, and the scene format refuses it too.
std::string checkedNumbers(const std::string& text, const std::string& displayName,
                           const std::map<std::string, NumberKeyword, std::less<>>& keywords,
                           const std::set<std::string, std::less<>>& known, FileWarnings& warnings, bool nonNegative)
{
    std::string out;
    out.reserve(text.size());
    std::vector<std::string_view> numbers;  // reused: no allocation per line
    forEachRawLine(text, [&](std::size_t lineNumber, std::string_view line, bool lastLine) {
        const auto emit = [&](std::string_view written) {
            out += written;
            if (!lastLine)
                out += '\n';
        };
        const std::size_t keywordBegin = line.find_first_not_of(" \t\r");
        const std::string_view keyword =
            keywordBegin == std::string_view::npos || line[keywordBegin] == '#'
                ? std::string_view()
                : line.substr(keywordBegin,
                              std::min(line.find_first_of(" \t\r", keywordBegin), line.size()) - keywordBegin);
        const auto found = keyword.empty() ? keywords.end() : keywords.find(keyword);
        if (found == keywords.end()) {
            if (!keyword.empty() && !known.contains(keyword))
                warnings.note(lineNumber, "statement " + std::string(keyword),
                              "unknown statement '" + std::string(keyword) + "' ignored");
            return emit(line);
        }
        const NumberKeyword& spec = found->second;
        const auto failHere = [&](const std::string& what) {
            fail(displayName, "line " + std::to_string(lineNumber) + ": " + spec.what + " " + what);
        };
        numbers.clear();
        bool rewritten = false;
        forEachWord(line.substr(keywordBegin + keyword.size()), [&](std::string_view token) {
            std::string_view digits = token;
            if (digits.size() > 1 && digits.front() == '+') {
                digits.remove_prefix(1);
                rewritten = true;
                warnings.note(lineNumber, "plus", "numbers with a leading '+' read without it");
            }
            float value = 0.0f;
            const auto [next, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
            if (error != std::errc{} || !std::isfinite(value))
                failHere("has a non-finite or malformed number '" + std::string(token) + "'");
            const std::string_view read(digits.data(), static_cast<std::size_t>(next - digits.data()));
            if (read.size() != digits.size()) {
                rewritten = true;
                warnings.note(lineNumber, "trailing",
                              "the number '" + std::string(token) + "' read as " + std::string(read) +
                                  " (the characters after it ignored)");
            }
            if (nonNegative && value < 0.0f)
                failHere("must not be negative, got '" + std::string(token) + "'");
            numbers.push_back(read);
        });
        if (spec.oneForThree && numbers.size() == 1) {
            numbers.resize(3, numbers.front());
            rewritten = true;
            warnings.note(lineNumber, "one value",
                          std::string(spec.what) + " with one value taken for all three channels");
        }
        if (static_cast<int>(numbers.size()) < spec.needed)
            failHere("needs " + std::to_string(spec.needed) + " numbers, has " + std::to_string(numbers.size()));
        if (!rewritten)
            return emit(line);
        std::string written(keyword);
        for (const std::string_view number : numbers) {
            written += ' ';
            written += number;
        }
        emit(written);
    });
    return out;
}

// tinyobjloader reads face indices with atoi, which wraps past 2^31: "f 1 2 4294967299" with
// three vertices drew a triangle. Every index of a face, line or point element must be an
// integer within int's range here first (the count of vertices is checked afterwards).
void checkElementIndices(const std::string& text, const std::string& displayName)
{
    forEachLine(text, [&](std::size_t lineNumber, std::string_view keyword, std::string_view rest) {
        if (keyword != "f" && keyword != "l" && keyword != "p")
            return;
        forEachWord(rest, [&](std::string_view corner) {
            // "1/2/3", "1//3" (no texture coordinate), "1": each present index in int's range.
            for (std::size_t begin = 0; begin <= corner.size();) {
                const std::size_t slash = std::min(corner.find('/', begin), corner.size());
                const std::string_view part = corner.substr(begin, slash - begin);
                long long index = 0;
                const auto [next, error] = std::from_chars(part.data(), part.data() + part.size(), index);
                if (!part.empty() && (error != std::errc{} || next != part.data() + part.size() ||
                                      index > std::numeric_limits<int>::max() ||
                                      index < -static_cast<long long>(std::numeric_limits<int>::max())))
                    fail(displayName, "line " + std::to_string(lineNumber) + ": the index '" + std::string(part) +
                                          "' is not an integer within ±2147483647");
                begin = slash + 1;
            }
        });
    });
}

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

// One material library as it was read: its name (for messages), its directory (for its maps),
// its text (for line numbers) and what was forgiven in it.
struct MtlLibrary {
    std::string displayName;
    fs::path directory;
    std::string text;
    FileWarnings warnings;
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
            fail(library.displayName, firstLine(*error));
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

// `name` in `directory` as exporters on other systems write it: Windows separators, a leading
// "./", another letter case (a file saved on a case-insensitive system). Empty when none fits.
fs::path findMapFile(const fs::path& directory, std::string name)
{
    std::replace(name.begin(), name.end(), '\\', '/');
    while (name.starts_with("./"))
        name.erase(0, 2);
    const fs::path path = directory / name;
    std::error_code error;
    if (fs::is_regular_file(path, error))
        return path;
    const auto lower = [](std::string text) {
        std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
        return text;
    };
    const fs::path folder = path.parent_path();
    const std::string wanted = lower(path.filename().string());
    for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
        if (lower(entry->path().filename().string()) == wanted && entry->is_regular_file(error))
            return entry->path();
    return {};
}

// A map named by a material library, resolved against the library's directory. A map that
// cannot be found is noted and left out: the material's colour stands in for it.
std::string mapPath(MtlLibrary& library, const std::string& materialName, const char* keyword, const std::string& name)
{
    if (name.empty())
        return {};
    const fs::path found = findMapFile(library.directory, name);
    if (found.empty()) {
        library.warnings.noteFile(std::string("map ") + name, "material '" + materialName + "': " + keyword + " '" +
                                                                  name + "' not found (" +
                                                                  (library.directory / name).string() +
                                                                  "); the material's colour stands in for it");
        return {};
    }
    if (found.filename().string() != fs::path(name).filename().string() || name.find('\\') != std::string::npos)
        library.warnings.noteFile(std::string("map ") + name, "material '" + materialName + "': " + keyword + " '" +
                                                                  name + "' read as " + found.string());
    return found.string();
}

glm::vec3 colour(const tinyobj::real_t (&value)[3]) { return {value[0], value[1], value[2]}; }

// A map's MTL texture options that manylights reads: `-o u v` and `-s u v` move and scale its
// uvs, uv' = s · uv + o (OBJ's uvs are ours, origin at the bottom left; Blender's importer reads
// them the same way), and `-clamp on` clamps to the edge instead of repeating.
void readTextureOptions(const tinyobj::texture_option_t& options, const MtlLibrary& library,
                        const std::string& materialName, Material& material, MaterialMapSlot slot)
{
    const glm::vec2 offset(options.origin_offset[0], options.origin_offset[1]);
    const glm::vec2 scale(options.scale[0], options.scale[1]);
    if (!std::isfinite(offset.x + offset.y + scale.x + scale.y))
        fail(library.displayName, "material '" + materialName + "': non-finite -o or -s texture option");
    glm::mat3 transform{1.0f};
    transform[0][0] = scale.x;
    transform[1][1] = scale.y;
    transform[2] = glm::vec3(offset, 1.0f);
    material.uvTransforms[slot] = transform;
    if (options.clamp)
        material.wraps[slot] = {TextureWrap::ClampToEdge, TextureWrap::ClampToEdge};
}

// MTL's PBR extension (Pr roughness, Pm metallic, map_Pr, map_Pm) makes the material a
// metallic-roughness one (docs/scene-format.md, "Model files"), its base colour Kd and map_Kd.
// tinyobjloader reads an absent Pr or Pm as 0, so a material with both at 0 and neither map stays
// Blinn-Phong. The shader reads one metallic-roughness map with glTF's channels (G roughness,
// B metallic): map_Pr and map_Pm naming the same image are read so; other maps are noted and
// left out (their factors stand).
void readPbrKeys(const tinyobj::material_t& source, MtlLibrary& library, Material& material)
{
    const bool hasMaps = !source.roughness_texname.empty() || !source.metallic_texname.empty();
    if (source.roughness == 0.0f && source.metallic == 0.0f && !hasMaps)
        return;
    const float roughness = source.roughness;
    const float metallic = source.metallic;
    if (!(roughness >= 0.0f && roughness <= 1.0f) || !(metallic >= 0.0f && metallic <= 1.0f))
        fail(library.displayName, "material '" + source.name + "': Pr and Pm must be in [0, 1]");
    material.model = ShadingModel::MetallicRoughness;
    material.baseColor = material.diffuse;
    // A map without its factor is taken at face value (factor 1), as glTF's default factors are.
    material.roughnessFactor = source.roughness_texname.empty() || roughness > 0.0f ? roughness : 1.0f;
    material.metallicFactor = source.metallic_texname.empty() || metallic > 0.0f ? metallic : 1.0f;
    if (source.roughness_texname == source.metallic_texname) {
        material.metallicRoughnessMap = mapPath(library, source.name, "map_Pr", source.roughness_texname);
        readTextureOptions(source.roughness_texopt, library, source.name, material, kSpecularSlot);
    } else {
        library.warnings.noteFile("map_Pr map_Pm", "material '" + source.name +
                                                       "': map_Pr and map_Pm in separate images are not read "
                                                       "(one image with glTF's channels is: G roughness, B metallic)");
    }
    material.specularMap.clear();
}

Material convertMaterial(const tinyobj::material_t& source, MtlLibrary& library, const std::string& objName)
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
    material.opacityMap = mapPath(library, source.name, "map_d", source.alpha_texname);
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
    readTextureOptions(source.diffuse_texopt, library, source.name, material, kDiffuseSlot);
    readTextureOptions(source.specular_texopt, library, source.name, material, kSpecularSlot);
    readTextureOptions(source.emissive_texopt, library, source.name, material, kEmissiveSlot);
    readTextureOptions(source.alpha_texopt, library, source.name, material, kOpacitySlot);
    readTextureOptions(source.normal_texname.empty() ? source.bump_texopt : source.normal_texopt, library, source.name,
                       material, kNormalSlot);
    // `d` (tinyobjloader also reads `Tr` into it as 1 − Tr): below 1 the material is transparent.
    if (!std::isfinite(source.dissolve))
        fail(library.displayName, "material '" + source.name + "': non-finite d or Tr");
    material.opacity = std::clamp(static_cast<float>(source.dissolve), 0.0f, 1.0f);
    if (material.opacity < 1.0f || !material.opacityMap.empty())
        material.alphaMode = AlphaMode::Blend;
    // An MTL without Kd leaves it 0 in tinyobjloader, which would blacken its map_Kd: a
    // texture with no Kd is taken at face value (Kd = 1).
    if (!material.diffuseMap.empty() && material.diffuse == glm::vec3{0.0f})
        material.diffuse = glm::vec3{1.0f};
    readPbrKeys(source, library, material);
    return material;
}

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
        fail(displayName, firstLine(error.empty() ? std::string("cannot parse the file") : error));

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
