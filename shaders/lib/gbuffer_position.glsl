// The world position of a G-buffer pixel, in either layout (render/frame/GBuffer.h: GBufferLayout):
// the only G-buffer value the culling compute shaders need. Needs lib/frame.glsl.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/gbuffer_packing.glsl"

#ifdef GBUFFER_COMPACT
// Compact layout: one RGBA32UI texel holds the whole surface (lib/gbuffer.glsl reads the rest
// of it), its x the bits of the view-space depth (distance along the view axis); the position
// is the point at that depth on the ray through the pixel's centre, as the mesh passes build
// it from the depth they interpolate (lib/frame.glsl positionOnPixelRay): the same bits.
layout(binding = GBUFFER_SURFACE_UNIT) uniform usampler2D gSurface;

// The position at `pixel` from the view depth stored there (lib/frame.glsl).
vec3 gbufferPositionAtDepth(ivec2 pixel, float viewDepth)
{
    return positionOnPixelRay(pixel, viewDepth);
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
