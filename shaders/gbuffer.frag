#version 450 core
// Geometry pass: writes the surface into the G-buffer (docs/gbuffer.md gives the layout).
#include "lib/lighting.glsl"
#include "lib/material.glsl"

layout(location = 0) out vec4 outPositionShininess;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outDiffuse;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmissive;

void main()
{
    Surface s = meshSurface();
    outPositionShininess = vec4(s.position, s.shininess);
    outNormal = vec4(s.normal, 0.0);
    outDiffuse = vec4(s.diffuse, 1.0);
    outSpecular = vec4(s.specular, 1.0);
    outEmissive = vec4(s.emissive, 1.0);
}
