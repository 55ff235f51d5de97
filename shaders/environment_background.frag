#version 450 core
// The environment where no surface is (`"background": true`, docs/scene-format.md): the map's
// radiance along the pixel's ray, level 0 (the map itself, at its own resolution up to
// EnvironmentLight::kMaxMapWidth) times the intensity. Drawn
// over the pixels the scene's depth leaves empty, before the transparency pass.
#include "lib/frame.glsl"
#include "lib/environment.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 ray = positionOnPixelRay(ivec2(gl_FragCoord.xy), 1.0) - frameValues().eye;
    outColor = vec4(environmentShown(normalize(ray)), frame.background.a);
}
