#version 450 core
// --view volumes: each light's volume drawn as a wireframe in the light's hue.
#include "lib/lights.glsl"

layout(location = 0) flat in uint lightIndex;
layout(location = 0) out vec4 outColor;

void main()
{
    vec3 intensity = lights[lightIndex].intensityExponent.rgb;
    outColor = vec4(intensity / max(max(intensity.r, intensity.g), max(intensity.b, 1e-6)), 1.0);
}
