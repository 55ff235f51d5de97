#version 450 core
// Debug views: one G-buffer quantity per pixel, unscaled (the CPU scales it for PNG output,
// render/Views.cpp). Background pixels are never shaded and stay 0.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) uniform int viewMode;  // render/Views.h: ViewMode
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 value = vec3(0.0);
    switch (viewMode) {
    case 1: value = s.position; break;
    case 2: value = s.normal; break;
    case 3: value = s.diffuse; break;
    case 4: value = s.specular; break;
    case 5: value = s.emissive; break;
    // View-space distance along the view axis (docs/cli.md).
    case 6: value = vec3(viewDepth(s.position)); break;
    }
    outColor = vec4(value, 1.0);
}
