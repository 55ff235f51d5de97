// Per-frame constants, one uniform buffer shared by every pass (render/GpuScene.cpp fills it
// with the same std140 layout).
#include "lib/bindings.glsl"
layout(std140, binding = FRAME_BLOCK_BINDING) uniform Frame {
    mat4 viewProjection;
    mat4 view;
    vec4 eye;                   // xyz: camera position
    vec4 viewAxis;              // xyz: unit direction the camera looks along
    vec4 ambient;               // rgb
    vec4 directionalToLight;    // xyz: unit vector towards the directional light (L)
    vec4 directionalIntensity;  // rgb; zero when the scene has none
    vec4 background;            // rgb
    uvec4 counts;               // x: number of local lights
    vec4 projection;            // x: tan(horizontal fov / 2), y: tan(vertical fov / 2), z: near, w: far
    vec4 viewport;              // x: width, y: height in pixels; z, w: their reciprocals
    vec4 time;                  // x: the scene time in seconds
    vec4 terms;                 // 1 or 0: ambient, diffuse, specular terms on (the viewer's toggles)
} frame;

// Distance from the eye along the view axis (the depth the techniques cull with).
float viewDepth(vec3 worldPosition)
{
    return dot(worldPosition - frame.eye.xyz, frame.viewAxis.xyz);
}
