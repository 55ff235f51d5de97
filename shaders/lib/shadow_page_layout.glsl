// The shadow-page pool's layout (render/shadows/ShadowPool.h, docs/shadows.md): the one table
// the shaders (which include this file) and the C++ code (render/shadows/ShadowPageLayout.h
// includes it as C++) both read. Written in the common subset of GLSL and C++.
//
// A face of a local light's shadow (one for a spot light of cutoff up to 75 degrees, six for a
// point light or a wider spot) has a level k from 0 to SHADOW_MAX_LEVEL, chosen each frame from
// its receivers' projected size: at level k the whole face is 16 * 2^k - 2 texels across, so
// that with a guard texel on each side it fills 2^k x 2^k pages exactly. Only the part of the
// face its receivers mark is resident (a square of pages, a power of two on a side, in one
// depth atlas), and where that is not the whole face, the whole face at level 0 (one page) is
// resident beside it: a receiver outside the fine part reads the coarse page, never "lit".

// A page: 16 x 16 texels of 32-bit depth, 1 KiB.
const int SHADOW_PAGE_TEXELS = 16;
// Depth rendered around every resident part: one bilinear comparison tap reads the texel on
// each side of its sample, and at a cube face's edge that texel holds depth seen just past the
// face (its projection reaches on), so the faces meet without an atlas' missing seam filter.
const int SHADOW_GUARD_TEXELS = 1;
const int SHADOW_MAX_LEVEL = 6;
// A face's receivers mark which of its 4 x 4 cells they fall in (bits 0-15 of a mark) and
// the level they ask for (bit SHADOW_MARK_LEVEL_SHIFT + k).
const int SHADOW_MARK_CELLS = 4;
const int SHADOW_MARK_LEVEL_SHIFT = 16;
const int SHADOW_CUBE_FACES = 6;
// The page tables' texture is this many texels wide (lib/shadow_pages.glsl: shadowTables).
const int SHADOW_TABLE_WIDTH = 4096;
// A spot light whose cos(cutoff) is at least this (a cutoff up to 75 degrees) has one face
// along its axis; a wider one has six, as a point light.
const float SHADOW_SPOT_FACE_MIN_COS = 0.258819045f;
// A spot's face reaches this much beyond its cone (in the tangent of its half angle), so the
// bilinear tap at the cone's edge stays inside the face.
const float SHADOW_SPOT_FACE_SCALE = 1.05f;
// The near plane of every face, as a fraction of its far plane (the light's reach). Casters
// nearer than it still cast: the pages are drawn with depth clamping.
const float SHADOW_NEAR_FRACTION = 0.001f;
// Receiver bias (lib/shadow_pages.glsl: shadowPageLookup): the receiver moves along its normal
// by SHADOW_NORMAL_OFFSET_TEXELS + sin θ texels of the level read, at most
// SHADOW_MAX_NORMAL_OFFSET_WORLD world units, and its depth towards the light by
// SHADOW_BIAS_TEXELS texels, at most SHADOW_MAX_BIAS_WORLD: both below half of a 0.4-thick wall.
const float SHADOW_NORMAL_OFFSET_TEXELS = 1.0f;
const float SHADOW_MAX_NORMAL_OFFSET_WORLD = 0.15f;
const float SHADOW_BIAS_TEXELS = 1.0f;
const float SHADOW_MAX_BIAS_WORLD = 0.1f;
