// The scene file's materials (scene/SceneFileLoader.h has the index).
#include "scene/SceneFileLoader.h"

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

Material Loader::readMaterial(const Node& node) const
{
    expectKeys(node, {"diffuse", "specular", "shininess", "emissive", "diffuse_map", "specular_map", "normal_map",
                      "normal_scale", "opacity", "opacity_map"});
    Material material;
    if (const auto diffuse = member(node, "diffuse"))
        material.diffuse = colour(*diffuse);
    if (const auto specular = member(node, "specular"))
        material.specular = colour(*specular);
    if (const auto value = member(node, "shininess"))
        material.shininess = shininess(*value);
    if (const auto emissive = member(node, "emissive"))
        material.emissive = colour(*emissive);
    material.diffuseMap = texturePath(node, "diffuse_map");
    material.specularMap = texturePath(node, "specular_map");
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
