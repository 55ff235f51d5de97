#include "scene/MtlMaterials.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/ObjText.h"
#include "scene/Shininess.h"

namespace manylights::detail {

namespace fs = std::filesystem;

namespace {

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
        failIn(library.displayName, "material '" + materialName + "': non-finite -o or -s texture option");
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
        failIn(library.displayName, "material '" + source.name + "': Pr and Pm must be in [0, 1]");
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

}  // namespace

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
        failIn(library.displayName, "material '" + source.name + "': non-finite -bm");
    readTextureOptions(source.diffuse_texopt, library, source.name, material, kDiffuseSlot);
    readTextureOptions(source.specular_texopt, library, source.name, material, kSpecularSlot);
    readTextureOptions(source.emissive_texopt, library, source.name, material, kEmissiveSlot);
    readTextureOptions(source.alpha_texopt, library, source.name, material, kOpacitySlot);
    readTextureOptions(source.normal_texname.empty() ? source.bump_texopt : source.normal_texopt, library, source.name,
                       material, kNormalSlot);
    // `d` (tinyobjloader also reads `Tr` into it as 1 − Tr): below 1 the material is transparent.
    if (!std::isfinite(source.dissolve))
        failIn(library.displayName, "material '" + source.name + "': non-finite d or Tr");
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

}  // namespace manylights::detail
