#version 450 core
// The first half of FXAA (render/effects/DisplayPass.cpp): keeps only the pixels on an edge
// (lib/fxaa_edge.glsl's test), which the stencil buffer then marks, so that shaders/fxaa.frag
// runs on them alone. No colour is written.
#include "lib/fxaa_edge.glsl"

void main()
{
    if (!onEdge(neighbourhood(ivec2(gl_FragCoord.xy))))
        discard;
}
