#version 450 core
// The light-independent terms (emissive, ambient, directional) of every covered pixel: the
// first pass of the volume techniques, onto which each light's volume is added.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    outColor = vec4(shadeGlobal(s, viewVector(s.position)), 1.0);
}
