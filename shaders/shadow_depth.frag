#version 450 core
// Shadow-map pass: the depth attachment is all it writes.
void main() {}
