#version 450 core
// The shadow and ssao views (render/Views.h): the directional light's shadow factor, or the
// blurred ambient-occlusion factor, of each visible surface, in all three channels.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) uniform int viewMode;  // render/Views.h: ViewMode
layout(location = 0) out vec4 outColor;

const int VIEW_SHADOW = 9;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface s = gbufferSurface(pixel);
    float value = viewMode == VIEW_SHADOW ? directionalShadow(s.position) : texelFetch(ambientOcclusionMap, pixel, 0).r;
    outColor = vec4(vec3(value), 1.0);
}
