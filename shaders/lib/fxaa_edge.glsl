// The part of FXAA (shaders/fxaa.frag) that decides whether a pixel is on an edge at all,
// shared with shaders/fxaa_edges.frag, which marks those pixels in the stencil buffer so that
// the full filter runs on them alone.
#include "lib/bindings.glsl"
layout(binding = DISPLAY_SOURCE_UNIT) uniform sampler2D source;  // bilinear, clamped to the edge; alpha: luma

// FXAA 3.11's "high quality" settings: edges must span 1/8 of the local maximum luma, and
// at least 0.0312 (dark edges are left alone).
const float EDGE_THRESHOLD = 0.125;
const float EDGE_THRESHOLD_MIN = 0.0312;

// A pixel's luma and its four neighbours', and the contrast among them.
struct Neighbourhood {
    vec2 uv;     // the pixel's centre
    vec2 texel;  // one pixel in texture coordinates
    vec4 centre;
    float c, n, e, s, w, ne, sw;
    float range;  // highest minus lowest of c, n, e, s, w
    float highest;
};

// The luma from two gathers of alpha (a gather at a texel's centre returns that texel and its
// neighbours up and to the right, as x: (0, 1), y: (1, 1), z: (1, 0), w: (0, 0)), clamped to
// the edge by the sampler: on llvmpipe gathers cost far less than one texelFetch per
// neighbour.
Neighbourhood neighbourhood(ivec2 pixel)
{
    Neighbourhood h;
    h.texel = 1.0 / vec2(textureSize(source, 0));
    h.uv = (vec2(pixel) + 0.5) * h.texel;
    h.centre = texelFetch(source, pixel, 0);
    vec4 upRight = textureGather(source, h.uv, 3);
    vec4 downLeft = textureGatherOffset(source, h.uv, ivec2(-1, -1), 3);
    h.c = h.centre.a;
    h.n = upRight.x;
    h.ne = upRight.y;
    h.e = upRight.z;
    h.s = downLeft.z;
    h.w = downLeft.x;
    h.sw = downLeft.w;
    h.highest = max(h.c, max(max(h.n, h.s), max(h.e, h.w)));
    h.range = h.highest - min(h.c, min(min(h.n, h.s), min(h.e, h.w)));
    return h;
}

bool onEdge(Neighbourhood h)
{
    return h.range >= max(EDGE_THRESHOLD_MIN, h.highest * EDGE_THRESHOLD);
}
