// The world position of a G-buffer pixel, in either layout (render/frame/GBuffer.h: GBufferLayout):
// the only G-buffer value the culling compute shaders need. Needs lib/frame.glsl.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/gbuffer_packing.glsl"

#ifdef GBUFFER_COMPACT
// Compact layout: one RGBA32UI texel holds the whole surface (lib/gbuffer.glsl reads the rest
// of it), its x the bits of the view-space depth (distance along the view axis); the position
// is the point at that depth on the ray through the pixel's centre, where the rasteriser
// evaluated the forward shader's interpolated position too.
layout(binding = GBUFFER_SURFACE_UNIT) uniform usampler2D gSurface;

// The world-space direction through the centre of `pixel` whose component along the view
// axis is 1, built from the camera of lib/frame.glsl.
vec3 pixelRay(ivec2 pixel)
{
    FrameValues values = frameValues();
    vec2 ndc = (vec2(pixel) + 0.5) * values.pixelRayScale.xy * 2.0 - 1.0;
    vec3 viewSpace = vec3(ndc * values.pixelRayScale.zw, -1.0);
    return values.inverseViewRotation * viewSpace;
}

// The position at `pixel` from the view depth stored there.
vec3 gbufferPositionAtDepth(ivec2 pixel, float viewDepth)
{
    return frameValues().eye + pixelRay(pixel) * viewDepth;
}

vec3 gbufferPosition(ivec2 pixel)
{
    return gbufferPositionAtDepth(pixel, surfaceViewDepth(texelFetch(gSurface, pixel, 0)));
}
#else
// Seed layout: the position is stored as it is.
layout(binding = GBUFFER_POSITION_UNIT) uniform sampler2D gPositionShininess;

vec3 gbufferPosition(ivec2 pixel)
{
    return texelFetch(gPositionShininess, pixel, 0).xyz;
}
#endif
