// Per-frame constants, one uniform buffer shared by every pass (render/scene/GpuFrame.cpp fills it
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

// Distance from the eye along the view axis (the depth the techniques cull with). precise,
// and the dot product written out: every program that computes it (the forward, G-buffer and
// transparency passes) rounds it alike, so the depth the compact G-buffer stores is the one the
// forward pass shades at (positionOnPixelRay).
float viewDepth(vec3 worldPosition)
{
    precise vec3 offset = worldPosition - frame.eye.xyz;
    precise float depth = offset.x * frame.viewAxis.x + offset.y * frame.viewAxis.y + offset.z * frame.viewAxis.z;
    return depth;
}

// The frame's values that shaders read for every pixel: the eye, the scale of the pixel's
// ray (lib/gbuffer_position.glsl: 1 / viewport size, then the tangents of the half field of
// view), the view's inverse rotation and the viewer's diffuse and specular switches.
//
// The light volumes' fragment shader runs once per (pixel, light) pair, so there their
// vertex shader passes these on as flat varyings: volume.vert defines FRAME_VALUES_OUT and
// calls passFrameValues(), volume.frag defines FRAME_VALUES_IN. On llvmpipe a fragment
// shader loads each value of a uniform block again for every 8 fragments, about 20 times
// what a flat input costs (docs/performance.md: the 12 values of the ray cost a pass of 128
// screen-filling volumes 66 ms, 12 flat inputs 3 ms). The varyings are copies of the
// block's values, so the image is the same bit for bit. Not for the mesh passes: llvmpipe
// sets up every varying per triangle, and there (small triangles, one fragment shader run
// per pixel and triangle) the flat inputs cost more than the loads they replace.
struct FrameValues {
    vec3 eye;
    vec4 pixelRayScale;
    mat3 inverseViewRotation;
    vec2 diffuseSpecularSwitches;
};

// Six locations from here; below them are those of the shaders' own varyings.
const int FRAME_VALUES_LOCATION = 16;

FrameValues frameValuesFromBlock()
{
    // frame.view is a rigid transform, so its inverse rotation is its transpose.
    return FrameValues(frame.eye.xyz, vec4(frame.viewport.zw, frame.projection.xy), transpose(mat3(frame.view)),
                       frame.terms.yz);
}

#ifdef FRAME_VALUES_IN
layout(location = FRAME_VALUES_LOCATION) flat in FrameValues frameValuesInput;

FrameValues frameValues()
{
    return frameValuesInput;
}
#else
FrameValues frameValues()
{
    return frameValuesFromBlock();
}
#endif

#ifdef FRAME_VALUES_OUT
layout(location = FRAME_VALUES_LOCATION) flat out FrameValues frameValuesOutput;

void passFrameValues()
{
    frameValuesOutput = frameValuesFromBlock();
}
#endif

// The point at view depth `depth` on the ray through the centre of `pixel`: the point every
// technique shades at a pixel (docs/lighting.md, "The shaded point"). The mesh passes take the
// depth they interpolate, the deferred passes the depth the G-buffer holds, and both build the
// point with this one function. Not the interpolated world position: a rasteriser may snap
// the vertices to its sub-pixel grid (GL's SUBPIXEL_BITS) before it interpolates, so that the
// interpolated point lies up to a fraction of a pixel beside the pixel's ray, by an amount that
// differs from driver to driver; a light whose cut-off sphere passed there then reached a
// pixel in forward's image and missed it in the compact G-buffer's (an NVIDIA H100, issue 40).
// precise: no program contracts these multiply-adds in its own way.
vec3 positionOnPixelRay(ivec2 pixel, float depth)
{
    FrameValues values = frameValues();
    precise vec2 ndc = (vec2(pixel) + 0.5) * values.pixelRayScale.xy * 2.0 - 1.0;
    // The direction through the pixel's centre whose component along the view axis is 1.
    precise vec3 viewSpace = vec3(ndc * values.pixelRayScale.zw, -1.0);
    precise vec3 ray = values.inverseViewRotation * viewSpace;
    precise vec3 position = values.eye + ray * depth;
    return position;
}
