#version 450 core
// Fast approximate anti-aliasing on the display pass's output, after Lottes, "FXAA"
// (NVIDIA, 2009; version 3.11's quality algorithm), in display-encoded values as it
// expects. A pixel whose 4-neighbourhood spans less luma than the thresholds is copied
// unchanged, so flat and smoothly shaded regions stay exactly as they were. At an edge, the
// pixel finds the edge's direction from second differences of luma, walks along it both ways
// (SEARCH_STEPS bilinear taps straddling the edge, growing strides) to the ends where the
// luma leaves the edge's average, and takes its colour from a bilinear tap shifted towards the
// other side by how far it is from the nearer end, or by a sub-pixel amount from the 3x3
// average where that is larger. Loop iterations: SEARCH_STEPS. Only the pixels that
// shaders/fxaa_edges.frag marked in the stencil buffer run it (render/effects/DisplayPass.cpp): on
// llvmpipe a pixel that returns early still pays for the whole shader under a lane mask.
#include "lib/fxaa_edge.glsl"
layout(location = 0) out vec4 antialiased;

// Sub-pixel blending at 3/4 strength (FXAA 3.11's default).
const float SUBPIXEL_QUALITY = 0.75;
// FXAA 3.11's quality preset 12: five taps each way, at strides reaching 20.5 pixels.
const int SEARCH_STEPS = 5;
const float STEP_STRIDES[SEARCH_STEPS] = float[](1.0, 1.5, 2.0, 4.0, 12.0);

float lumaAt(vec2 uv)
{
    return textureLod(source, uv, 0.0).a;
}

void main()
{
    Neighbourhood h = neighbourhood(ivec2(gl_FragCoord.xy));
    if (!onEdge(h)) {
        antialiased = vec4(h.centre.rgb, 1.0);
        return;
    }
    vec2 uv = h.uv;
    vec2 texel = h.texel;
    float c = h.c, n = h.n, e = h.e, s = h.s, w = h.w, ne = h.ne, sw = h.sw;
    float range = h.range;
    float nw = textureGatherOffset(source, uv, ivec2(-1, 0), 3).x;
    float se = textureGatherOffset(source, uv, ivec2(0, -1), 3).z;

    // An edge along x changes luma from row to row: its second differences across rows
    // outweigh those across columns.
    float acrossRows = 2.0 * abs(n + s - 2.0 * c) + abs(ne + se - 2.0 * e) + abs(nw + sw - 2.0 * w);
    float acrossColumns = 2.0 * abs(e + w - 2.0 * c) + abs(ne + nw - 2.0 * n) + abs(se + sw - 2.0 * s);
    bool alongX = acrossRows >= acrossColumns;

    // Which neighbour across the edge differs more: the edge lies between it and this pixel.
    float before = alongX ? s : w;
    float after = alongX ? n : e;
    bool towardsBefore = abs(before - c) >= abs(after - c);
    float across = (alongX ? texel.y : texel.x) * (towardsBefore ? -1.0 : 1.0);
    float edgeLuma = 0.5 * (c + (towardsBefore ? before : after));
    float endThreshold = 0.25 * max(abs(before - c), abs(after - c));

    // Walk along the edge, half a pixel across (a bilinear tap averages both sides), until
    // the luma leaves the edge's average at both ends.
    vec2 onEdge = uv + (alongX ? vec2(0.0, 0.5 * across) : vec2(0.5 * across, 0.0));
    vec2 along = alongX ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 uvBack = onEdge;
    vec2 uvForward = onEdge;
    float endBack = 0.0;
    float endForward = 0.0;
    bool doneBack = false;
    bool doneForward = false;
    for (int i = 0; i < SEARCH_STEPS && !(doneBack && doneForward); ++i) {
        if (!doneBack) {
            uvBack -= along * STEP_STRIDES[i];
            endBack = lumaAt(uvBack) - edgeLuma;
            doneBack = abs(endBack) >= endThreshold;
        }
        if (!doneForward) {
            uvForward += along * STEP_STRIDES[i];
            endForward = lumaAt(uvForward) - edgeLuma;
            doneForward = abs(endForward) >= endThreshold;
        }
    }
    float distanceBack = alongX ? uv.x - uvBack.x : uv.y - uvBack.y;
    float distanceForward = alongX ? uvForward.x - uv.x : uvForward.y - uv.y;
    bool backNearer = distanceBack < distanceForward;
    float nearest = min(distanceBack, distanceForward);
    float edgeOffset = 0.5 - nearest / (distanceBack + distanceForward);
    // Only blend where the nearer end turns the way this pixel does (it sits on the side of
    // the edge that the end's luma leaves towards).
    bool pixelBelowEdge = c < edgeLuma;
    bool endAgrees = ((backNearer ? endBack : endForward) < 0.0) != pixelBelowEdge;
    edgeOffset = endAgrees ? edgeOffset : 0.0;

    // Sub-pixel aliasing (features thinner than a pixel): blend by how far the pixel is from
    // its 3x3 neighbourhood's average, relative to the local contrast.
    float average = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
    float contrast = clamp(abs(average - c) / range, 0.0, 1.0);
    float smoothed = (3.0 - 2.0 * contrast) * contrast * contrast;
    float subpixelOffset = smoothed * smoothed * SUBPIXEL_QUALITY;

    float offset = max(edgeOffset, subpixelOffset);
    vec2 shifted = uv + (alongX ? vec2(0.0, offset * across) : vec2(offset * across, 0.0));
    antialiased = vec4(textureLod(source, shifted, 0.0).rgb, 1.0);
}
