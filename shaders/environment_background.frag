#version 450 core
// The environment where no surface is (`"background": true`, docs/scene-format.md): the map's
// radiance along the pixel's ray, its first level (the map itself) times the intensity. Drawn
// over the pixels the scene's depth leaves empty, before the transparency pass.
#include "lib/frame.glsl"
#include "lib/environment.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 ray = positionOnPixelRay(ivec2(gl_FragCoord.xy), 1.0) - frameValues().eye;
    outColor = vec4(environmentPrefiltered(normalize(ray), 0.0), frame.background.a);
}
