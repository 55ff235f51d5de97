// Moving a material between the two reflection models of docs/lighting.md: glTF's
// metallic-roughness materials as they were shaded before issue 31 (Blinn-Phong, the scene file's
// `"model_materials": "blinn-phong"`), and Blinn-Phong materials as metallic-roughness ones (the
// per-pair cost comparison of scripts/measure-pbr-cost.sh).
#pragma once

#include "scene/Scene.h"

namespace manylights {

// A metallic-roughness material mapped to Blinn-Phong: diffuse = base · (1 − metallic),
// specular = 0.04 · (1 − metallic), specularTint = base · metallic, shininess =
// blinnPhongExponent(roughness); a metallic-roughness map redoes this per texel in the shader,
// and the occlusion map is dropped (Blinn-Phong has no such term). Other materials unchanged.
Material blinnPhongMapping(const Material& material);

}  // namespace manylights
