#version 450 core
// One triangle covering the screen, at the far plane (depth 1). Drawn with the depth test
// GL_GREATER against the G-buffer's depth, only pixels that hold a surface run the fragment
// shader: the background costs nothing.
void main()
{
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
