#version 450 core
#define FRAME_VALUES_IN  // from volume.vert (lib/frame.glsl says why)
// One light's contribution at the pixel's surface, added by blending into the lit image.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) flat in uint lightIndex;
layout(location = 1) flat in GpuLight volumeLight;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    outColor = vec4(shadeLocalLight(lightIndex, volumeLight, s, viewVector(s.position)), 0.0);
    recordLightEvaluations(1u);
}
