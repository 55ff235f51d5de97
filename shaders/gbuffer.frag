#version 450 core
// Geometry pass: writes the surface into the G-buffer in the layout GBUFFER_COMPACT selects
// (render/GBuffer.h and docs/gbuffer.md give both).
#include "lib/lighting.glsl"
#include "lib/material.glsl"
#include "lib/gbuffer_packing.glsl"

layout(location = 0) out vec4 outPositionShininess;  // compact: view depth in r
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outDiffuse;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmissive;

void main()
{
    Surface s = meshSurface();
#ifdef GBUFFER_COMPACT
    vec2 shininessBytes = encodeShininess(s.shininess);
    outPositionShininess = vec4(viewDepth(s.position), 0.0, 0.0, 0.0);
    outNormal = vec4(octahedralEncode(s.normal), 0.0, 0.0);
    outDiffuse = vec4(s.diffuse, shininessBytes.x);
    outSpecular = vec4(s.specular, shininessBytes.y);
#else
    outPositionShininess = vec4(s.position, s.shininess);
    outNormal = vec4(s.normal, 0.0);
    outDiffuse = vec4(s.diffuse, 1.0);
    outSpecular = vec4(s.specular, 1.0);
#endif
    outEmissive = vec4(s.emissive, 1.0);
}
