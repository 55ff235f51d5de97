#version 450 core
// Shadow-map pass: the depth attachment is all it writes. An alpha-masked caster (bit 5 of
// MATERIAL_VARIANT) is cut where shaders/lib/material.glsl's meshSurface() cuts it: its
// coverage, opacity times the diffuse map's alpha (bit 0) times the vertex colour's (bit 6),
// below the cutoff. Light passes through the holes a mask makes.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#ifndef MATERIAL_VARIANT
#define MATERIAL_VARIANT 0
#endif

#if (MATERIAL_VARIANT & 32) != 0
layout(location = 2) in vec2 uv;
layout(location = 9) flat in vec2 materialAlpha;
#if (MATERIAL_VARIANT & 64) != 0
layout(location = 11) in float vertexAlpha;
#endif
#if (MATERIAL_VARIANT & 1) != 0
layout(location = DIFFUSE_UV_TRANSFORM_LOCATION) uniform mat3x2 diffuseUvTransform;
layout(binding = DIFFUSE_MAP_UNIT) uniform sampler2D diffuseMap;
#endif
#endif

void main()
{
#if (MATERIAL_VARIANT & 32) != 0
    float coverage = materialAlpha.x;
#if (MATERIAL_VARIANT & 64) != 0
    coverage *= vertexAlpha;
#endif
#if (MATERIAL_VARIANT & 1) != 0
    coverage *= texture(diffuseMap, diffuseUvTransform * vec3(uv, 1.0)).a;
#endif
    if (coverage < materialAlpha.y)
        discard;
#endif
}
