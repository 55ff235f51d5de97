#version 450 core
// The viewer's axes display: three lines from the origin, X red, Y green, Z blue, drawn with
// glDrawArrays(GL_LINES, 0, 6) and no vertex buffer.
#include "lib/frame.glsl"

layout(location = 0) uniform float axisLength;

layout(location = 0) out vec3 colour;

void main()
{
    int axis = gl_VertexID / 2;
    vec3 direction = vec3(axis == 0, axis == 1, axis == 2);
    vec3 position = (gl_VertexID % 2 == 1) ? direction * axisLength : vec3(0.0);
    colour = direction;
    gl_Position = frame.viewProjection * vec4(position, 1.0);
}
