#version 450 core
// Clears the shadow-page pool's parts that are drawn again this frame to depth 1 (far: lit),
// all of them in one instanced draw of a quad each (render/shadows/ShadowPool.cpp), drawn
// with the depth test passing everywhere.
#include "lib/bindings.glsl"

// Each part's square in atlas NDC: x0, y0, x1, y1.
layout(std430, binding = SHADOW_CLEAR_RECTS_BUFFER_BINDING) readonly buffer ClearRects {
    vec4 clearRects[];
};

void main()
{
    vec4 square = clearRects[gl_InstanceID];
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    gl_Position = vec4(mix(square.xy, square.zw, corner), 1.0, 1.0);
}
