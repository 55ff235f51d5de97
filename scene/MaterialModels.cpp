#include "scene/MaterialModels.h"

#include "scene/Shininess.h"

namespace manylights {

Material blinnPhongMapping(const Material& material)
{
    if (material.model != ShadingModel::MetallicRoughness)
        return material;
    Material mapped = material;
    mapped.model = ShadingModel::BlinnPhong;
    // Metals have no diffuse and a specular of the base colour, dielectrics a 4% grey specular
    // (Material::specularTint holds the base-colour part, which maps and vertex colours multiply).
    const float metallic = material.metallicFactor;
    mapped.diffuse = material.baseColor * (1.0f - metallic);
    mapped.specular = glm::vec3{0.04f * (1.0f - metallic)};
    mapped.specularTint = material.baseColor * metallic;
    mapped.shininess = blinnPhongExponent(material.roughnessFactor);
    mapped.occlusionMap.clear();
    return mapped;
}

}  // namespace manylights
