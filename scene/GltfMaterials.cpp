// glTF materials and their textures, samplers and texture transforms (scene/GltfReader.h).
#include "scene/GltfReader.h"

#include <algorithm>
#include <cmath>

namespace manylights::detail {

namespace fs = std::filesystem;

std::optional<std::size_t> GltfReader::materialFor(int index, const std::string& where)
{
    if (index < 0)
        return std::nullopt;  // glTF's default material: the object's (or scene default) material
    if (static_cast<std::size_t>(index) >= gltf_.materials.size())
        fail(where + ": material " + std::to_string(index) + " is not a material (the file has " +
             std::to_string(gltf_.materials.size()) + ")");
    auto& slot = materialOf_[static_cast<std::size_t>(index)];
    if (!slot) {
        slot = model_.materials.size();
        model_.materials.push_back(convertMaterial(static_cast<std::size_t>(index)));
    }
    return slot;
}

Material GltfReader::convertMaterial(std::size_t index)
{
    const tinygltf::Material& source = gltf_.materials[index];
    const std::string where = element("materials", index);
    const auto colour = [&](const std::vector<double>& values, std::size_t size, const char* what) {
        if (values.size() < 3 || values.size() != size)
            fail(where + ": " + what + " needs " + std::to_string(size) + " numbers, has " +
                 std::to_string(values.size()));
        const glm::vec3 c(values[0], values[1], values[2]);
        if (!std::isfinite(c.x + c.y + c.z) || glm::any(glm::lessThan(c, glm::vec3{0.0f})))
            fail(where + ": " + what + " must be finite and not negative");
        return c;
    };
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    const glm::vec3 baseColour = colour(pbr.baseColorFactor, 4, "baseColorFactor");
    const auto metallic = static_cast<float>(pbr.metallicFactor);
    const auto roughness = static_cast<float>(pbr.roughnessFactor);
    if (!(metallic >= 0.0f && metallic <= 1.0f) || !(roughness >= 0.0f && roughness <= 1.0f))
        fail(where + ": metallicFactor and roughnessFactor must be in [0, 1]");
    Material material;
    material.name = displayName_ + "#" + (source.name.empty() ? where : source.name);
    // glTF's own model (docs/lighting.md); scene/MaterialModels.h maps it to Blinn-Phong for
    // a scene that asks for it (`"model_materials": "blinn-phong"`).
    material.model = ShadingModel::MetallicRoughness;
    material.baseColor = baseColour;
    material.metallicFactor = metallic;
    material.roughnessFactor = roughness;
    material.emissive = colour(source.emissiveFactor, 3, "emissiveFactor");
    material.diffuseMap = texturePath(pbr.baseColorTexture, where + ".baseColorTexture", material, kDiffuseSlot);
    material.metallicRoughnessMap =
        texturePath(pbr.metallicRoughnessTexture, where + ".metallicRoughnessTexture", material, kSpecularSlot);
    material.emissiveMap = texturePath(source.emissiveTexture, where + ".emissiveTexture", material, kEmissiveSlot);
    material.normalMap = texturePath(source.normalTexture, where + ".normalTexture", material, kNormalSlot);
    material.normalScale = static_cast<float>(source.normalTexture.scale);
    if (!std::isfinite(material.normalScale))
        fail(where + ".normalTexture: scale is not finite");
    material.occlusionMap = texturePath(source.occlusionTexture, where + ".occlusionTexture", material, kOcclusionSlot);
    material.occlusionStrength = static_cast<float>(source.occlusionTexture.strength);
    if (!(material.occlusionStrength >= 0.0f && material.occlusionStrength <= 1.0f))
        fail(where + ".occlusionTexture: strength must be in [0, 1]");
    if (const auto found = source.extensions.find("KHR_materials_emissive_strength");
        found != source.extensions.end() && found->second.Has("emissiveStrength")) {
        const tinygltf::Value& strength = found->second.Get("emissiveStrength");
        const double value = strength.IsNumber() || strength.IsInt() ? strength.GetNumberAsDouble() : -1.0;
        if (!(value >= 0.0) || !std::isfinite(value))
            fail(where + ": KHR_materials_emissive_strength.emissiveStrength must be a finite number >= 0");
        material.emissive *= static_cast<float>(value);
    }
    readCoverage(source, where, material);
    material.sides = source.doubleSided ? Sides::BothFlipped : Sides::Front;
    return material;
}

void GltfReader::readCoverage(const tinygltf::Material& source, const std::string& where, Material& material)
{
    const double alpha = source.pbrMetallicRoughness.baseColorFactor[3];
    if (!std::isfinite(alpha) || alpha < 0.0)
        fail(where + ": baseColorFactor's alpha must be a finite number >= 0");
    material.opacity = static_cast<float>(std::min(alpha, 1.0));
    if (source.alphaMode == "MASK") {
        if (!std::isfinite(source.alphaCutoff) || source.alphaCutoff < 0.0)
            fail(where + ": alphaCutoff must be a finite number >= 0");
        material.alphaMode = AlphaMode::Mask;
        material.alphaCutoff = static_cast<float>(source.alphaCutoff);
    } else if (source.alphaMode == "BLEND") {
        material.alphaMode = AlphaMode::Blend;
    } else if (source.alphaMode != "OPAQUE") {
        warnings_.noteFile("alphaMode " + source.alphaMode,
                           where + ": unknown alphaMode '" + source.alphaMode + "'; drawn OPAQUE");
    }
}

template <typename TextureReference>
std::string GltfReader::texturePath(const TextureReference& reference, const std::string& where, Material& material,
                                    MaterialMapSlot slot)
{
    if (reference.index < 0)
        return {};
    int texCoord = reference.texCoord;
    if (const auto found = reference.extensions.find("KHR_texture_transform"); found != reference.extensions.end()) {
        material.uvTransforms[slot] = uvTransform(found->second, where + ".KHR_texture_transform");
        const tinygltf::Value& set = found->second.Get("texCoord");
        if (set.IsInt())
            texCoord = set.GetNumberAsInt();
    }
    if (texCoord != 0)
        warnings_.noteFile("texCoord", where + ": texCoord " + std::to_string(texCoord) +
                                           " is not read; the texture is drawn with TEXCOORD_0");
    std::string path = texturePath(reference.index, where);
    material.wraps[slot] = samplerWrap(gltf_.textures[static_cast<std::size_t>(reference.index)].sampler);
    return path;
}

glm::mat3 GltfReader::uvTransform(const tinygltf::Value& extension, const std::string& where) const
{
    const auto numbers = [&](const char* key, glm::vec2 fallback) {
        const tinygltf::Value& value = extension.Get(key);
        if (!value.IsArray())
            return fallback;
        if (value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
            fail(where + ": " + key + " needs 2 numbers");
        return glm::vec2(value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble());
    };
    const glm::vec2 offset = numbers("offset", glm::vec2{0.0f});
    const glm::vec2 scale = numbers("scale", glm::vec2{1.0f});
    const tinygltf::Value& rotationValue = extension.Get("rotation");
    const float rotation = rotationValue.IsNumber() ? static_cast<float>(rotationValue.GetNumberAsDouble()) : 0.0f;
    if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation))
        fail(where + ": offset, rotation and scale must be finite");
    // glm matrices are column-major: m[column][row].
    glm::mat3 translation{1.0f};
    translation[2] = glm::vec3(offset, 1.0f);
    glm::mat3 turn{1.0f};
    turn[0] = glm::vec3(std::cos(rotation), -std::sin(rotation), 0.0f);
    turn[1] = glm::vec3(std::sin(rotation), std::cos(rotation), 0.0f);
    glm::mat3 scaling{1.0f};
    scaling[0][0] = scale.x;
    scaling[1][1] = scale.y;
    glm::mat3 flip{1.0f};
    flip[1][1] = -1.0f;
    flip[2][1] = 1.0f;
    return flip * translation * turn * scaling * flip;
}

std::string GltfReader::texturePath(int textureIndex, const std::string& where)
{
    if (textureIndex < 0)
        return {};
    if (static_cast<std::size_t>(textureIndex) >= gltf_.textures.size())
        fail(where + ": texture " + std::to_string(textureIndex) + " is not a texture (the file has " +
             std::to_string(gltf_.textures.size()) + ")");
    const int source = gltf_.textures[static_cast<std::size_t>(textureIndex)].source;
    if (source < 0)
        return {};  // a texture without an image (e.g. only an extension's): none
    if (static_cast<std::size_t>(source) >= gltf_.images.size())
        fail(element("textures", static_cast<std::size_t>(textureIndex)) + ": source " + std::to_string(source) +
             " is not an image (the file has " + std::to_string(gltf_.images.size()) + ")");
    auto& path = imagePathOf_[static_cast<std::size_t>(source)];
    if (!path)
        path = imagePath(static_cast<std::size_t>(source));
    return *path;
}

MapWrap GltfReader::samplerWrap(int samplerIndex)
{
    if (samplerIndex < 0)
        return {};
    if (static_cast<std::size_t>(samplerIndex) >= gltf_.samplers.size())
        fail("a texture's sampler " + std::to_string(samplerIndex) + " is not a sampler (the file has " +
             std::to_string(gltf_.samplers.size()) + ")");
    const tinygltf::Sampler& sampler = gltf_.samplers[static_cast<std::size_t>(samplerIndex)];
    const auto wrap = [&](int mode, const char* axis) {
        switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        default:
            warnings_.noteFile("sampler wrap", element("samplers", static_cast<std::size_t>(samplerIndex)) +
                                                   ": unknown " + axis + " " + std::to_string(mode) +
                                                   "; drawn with REPEAT");
            return TextureWrap::Repeat;
        }
    };
    return {wrap(sampler.wrapS, "wrapS"), wrap(sampler.wrapT, "wrapT")};
}

std::string GltfReader::imagePath(std::size_t index)
{
    const tinygltf::Image& image = gltf_.images[index];
    const std::string name = element("images", index);
    EncodedImage encoded;
    encoded.key = displayName_ + "#" + name;
    encoded.mimeType = image.mimeType;
    if (image.bufferView >= 0) {
        if (static_cast<std::size_t>(image.bufferView) >= gltf_.bufferViews.size())
            fail(name + ": bufferView " + std::to_string(image.bufferView) + " is not a buffer view");
        const tinygltf::BufferView& view = gltf_.bufferViews[static_cast<std::size_t>(image.bufferView)];
        const std::vector<unsigned char>& buffer = bufferOf(view, static_cast<std::size_t>(image.bufferView));
        const auto begin = buffer.begin() + static_cast<std::ptrdiff_t>(view.byteOffset);
        encoded.bytes.assign(begin, begin + static_cast<std::ptrdiff_t>(view.byteLength));
    } else if (!image.image.empty()) {
        encoded.bytes = image.image;
    } else {
        // An external image: only its existence is checked; the render layer decodes it.
        if (image.uri.empty())
            fail(name + ": has neither a uri nor a bufferView");
        if (!options_.allowExternalFiles)
            fail(name + ": external image '" + image.uri + "' not allowed when loading from memory");
        const fs::path path = base_ / image.uri;
        std::error_code error;
        if (!fs::is_regular_file(path, error))
            fail(name + ": image file '" + image.uri + "' not found (" + path.string() + ")");
        return path.string();
    }
    if (encoded.bytes.empty())
        fail(name + ": the embedded image is empty");
    model_.images.push_back(std::move(encoded));
    return model_.images.back().key;
}

}  // namespace manylights::detail
