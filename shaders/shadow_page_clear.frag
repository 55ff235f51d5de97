#version 450 core
// shadow_page_clear.vert's quads write depth only.
void main() {}
