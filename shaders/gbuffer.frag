#version 450 core
// Geometry pass: writes the surface into the G-buffer in the layout GBUFFER_COMPACT selects
// (render/frame/GBuffer.h and docs/gbuffer.md give both).
#include "lib/lighting.glsl"
#include "lib/material.glsl"
#include "lib/gbuffer_packing.glsl"

#ifdef GBUFFER_COMPACT
layout(location = 0) out uvec4 outSurface;
layout(location = 1) out vec4 outEmissive;
#else
layout(location = 0) out vec4 outPositionShininess;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outDiffuse;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmissive;
#endif

void main()
{
    Surface s = meshSurface();
    // s.metallicRoughness is the material variant's constant: each program packs one model.
#ifdef GBUFFER_COMPACT
    // The base colour from c_diff + F0 − 0.04 · (1 − metallic) (lib/lighting.glsl Surface).
    vec3 baseColour = s.diffuse + s.specular - vec3(0.04 * (1.0 - s.metallic));
    outSurface = s.metallicRoughness
                     ? packMetallicRoughnessSurface(meshViewDepth(), s.normal, baseColour, s.metallic, s.roughness)
                     : packSurface(meshViewDepth(), s.normal, s.diffuse, s.specular, s.shininess);
#else
    // The seed layout keeps c_diff and F0 as floats, and roughness in the shininess's place.
    outPositionShininess = vec4(s.position, s.metallicRoughness ? s.roughness : s.shininess);
    outNormal = vec4(s.normal, 0.0);
    outDiffuse = vec4(s.diffuse, 1.0);
    outSpecular = vec4(s.specular, 1.0);
#endif
    outEmissive = vec4(s.emissive, packModelOcclusion(s.metallicRoughness, s.occlusion));
}
