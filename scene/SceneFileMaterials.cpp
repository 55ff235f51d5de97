// The scene file's materials (scene/SceneFileLoader.h has the index).
#include "scene/SceneFileLoader.h"

#include <array>

namespace manylights::scene_file {

using namespace scene_json;  // the wording of messages (scene/JsonText.h)

void Loader::readMaterials(const Node& node)
{
    expectObject(node);
    if (node.json->size() > kMaxMaterials)
        fail(node, "too many materials: " + std::to_string(node.json->size()) + " (at most " +
                       std::to_string(kMaxMaterials) + ")");
    for (const auto& item : node.json->items()) {
        Material material = readMaterial(Node{&item.value(), node.path + "/" + escapePointerToken(item.key())});
        material.name = item.key();
        namedMaterials_.emplace(item.key(), scene_.materials.size());
        scene_.materials.push_back(std::move(material));
    }
}

namespace {

// The keys of each reflection model (docs/scene-format.md, "Materials"); the others (emissive,
// normal map, opacity) belong to both.
constexpr std::array kBlinnPhongKeys{"diffuse", "specular", "shininess", "diffuse_map", "specular_map"};
constexpr std::array kMetallicRoughnessKeys{
    "base_color", "metallic", "roughness", "base_color_map", "metallic_roughness_map", "occlusion_map"};

}  // namespace

Material Loader::readMaterial(const Node& node) const
{
    expectKeys(node, {"diffuse", "specular", "shininess", "emissive", "diffuse_map", "specular_map", "normal_map",
                      "normal_scale", "opacity", "opacity_map", "base_color", "metallic", "roughness", "base_color_map",
                      "metallic_roughness_map", "occlusion_map"});
    // A material is of one model: a key of the other would be silently ignored.
    const auto firstOf = [&](const auto& keys) -> const char* {
        for (const char* key : keys)
            if (member(node, key))
                return key;
        return nullptr;
    };
    const char* blinnPhongKey = firstOf(kBlinnPhongKeys);
    const char* metallicRoughnessKey = firstOf(kMetallicRoughnessKeys);
    if (blinnPhongKey && metallicRoughnessKey)
        fail(*member(node, blinnPhongKey), std::string("'") + blinnPhongKey + "' cannot be mixed with '" +
                                               metallicRoughnessKey +
                                               "': a material is either Blinn-Phong (diffuse, specular, "
                                               "shininess) or metallic-roughness (base_color, metallic, roughness)");
    Material material;
    if (metallicRoughnessKey)
        readMetallicRoughness(node, material);
    else
        readBlinnPhong(node, material);
    if (const auto emissive = member(node, "emissive"))
        material.emissive = colour(*emissive);
    material.normalMap = texturePath(node, "normal_map");
    if (const auto value = member(node, "normal_scale"))
        material.normalScale = number(*value);
    // Below 1 the material is transparent: drawn over what lies behind it (the diffuse
    // map's alpha multiplies the opacity).
    if (const auto value = member(node, "opacity")) {
        material.opacity = number(*value);
        if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
            fail(*value, "must be in [0, 1], got " + describeValue(*value->json));
        if (material.opacity < 1.0f)
            material.alphaMode = AlphaMode::Blend;
    }
    material.opacityMap = texturePath(node, "opacity_map");
    if (!material.opacityMap.empty())
        material.alphaMode = AlphaMode::Blend;
    return material;
}

void Loader::readBlinnPhong(const Node& node, Material& material) const
{
    if (const auto diffuse = member(node, "diffuse"))
        material.diffuse = colour(*diffuse);
    if (const auto specular = member(node, "specular"))
        material.specular = colour(*specular);
    if (const auto value = member(node, "shininess"))
        material.shininess = shininess(*value);
    material.diffuseMap = texturePath(node, "diffuse_map");
    material.specularMap = texturePath(node, "specular_map");
}

void Loader::readMetallicRoughness(const Node& node, Material& material) const
{
    material.model = ShadingModel::MetallicRoughness;
    // The defaults: the Blinn-Phong default's grey, a dielectric, fully rough (glTF's roughness).
    material.baseColor = glm::vec3{0.8f};
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 1.0f;
    if (const auto value = member(node, "base_color"))
        material.baseColor = colour(*value);
    const auto unitInterval = [&](const char* key, float& field) {
        if (const auto value = member(node, key)) {
            field = number(*value);
            if (!(field >= 0.0f && field <= 1.0f))
                fail(*value, "must be in [0, 1], got " + describeValue(*value->json));
        }
    };
    unitInterval("metallic", material.metallicFactor);
    unitInterval("roughness", material.roughnessFactor);
    // The base colour map is sRGB colour in the diffuse map's slot; the metallic-roughness map
    // has glTF's channels (G roughness, B metallic) in the specular map's.
    material.diffuseMap = texturePath(node, "base_color_map");
    material.metallicRoughnessMap = texturePath(node, "metallic_roughness_map");
    material.occlusionMap = texturePath(node, "occlusion_map");
}

std::string Loader::texturePath(const Node& material, std::string_view key) const
{
    const auto node = member(material, key);
    if (!node)
        return {};
    const fs::path path = resolve(*node);
    expectRegularFile(*node, path);
    return path.string();
}

std::size_t Loader::objectMaterial(const Node& object)
{
    const auto node = member(object, "material");
    if (!node) {
        if (!defaultMaterial_) {
            Material material;
            material.name = kDefaultMaterialName;
            defaultMaterial_ = scene_.materials.size();
            scene_.materials.push_back(std::move(material));
        }
        return *defaultMaterial_;
    }
    if (node->json->is_string()) {
        const std::string name = node->json->get<std::string>();
        const auto found = namedMaterials_.find(name);
        if (found != namedMaterials_.end())
            return found->second;
        std::vector<std::string> names;
        for (const auto& [known, index] : namedMaterials_)
            names.push_back(known);
        std::string hint = " (the scene's 'materials' defines none)";
        if (!names.empty()) {
            const auto guess = closest(name, names);
            hint = guess ? " (did you mean " + quote(*guess) + "?)" : " (not in 'materials')";
        }
        fail(*node, "unknown material " + quote(name) + hint);
    }
    if (!node->json->is_object())
        fail(*node, "expected a material name or a material object, got " + describeType(*node->json));
    Material material = readMaterial(*node);
    // Inline materials have no name of their own; their JSON path says where they came from.
    material.name = node->path;
    scene_.materials.push_back(std::move(material));
    return scene_.materials.size() - 1;
}

}  // namespace manylights::scene_file
