// Local lights' shadows from the shadow-page pool (render/shadows/ShadowPool.h, docs/shadows.md):
// every local light may cast a shadow, each of its faces drawn into pages of one depth atlas
// at a resolution its receivers chose. Two users:
// - the marking pass (SHADOW_PAGE_MARKING: the clustered lists' walk of lib/list_pixel.glsl
//   over every visible pixel, render/shadows/ShadowPool.cpp) marks, for each pair the lighting
//   will shade, which cell of which face of the light the pixel falls in and the level it
//   needs there (markShadowPages);
// - the shadow-resolution view (SHADOW_RESOLUTION_VIEW, render/shadows/ShadowResolutionView.h)
//   walks the same lists and reads, for each pair, the texels per pixel of the level the
//   lookup reads (shadowPageTexelsPerPixel);
// - the lighting of every technique reads one bilinear depth-comparison tap of the page
//   there (localShadow, called by lib/lighting.glsl's shadeLocalLight for pairs in reach).
// A face's geometry is render/shadows/ShadowFaces.cpp's, which draws the pages.
#include "lib/shadow_page_layout.glsl"

// A face of a light seen from a receiver at offset v from the light.
struct ShadowFaceFrame {
    uint face;     // 0 for a spot's one face; 0-5 for a cube's (+X, −X, +Y, −Y, +Z, −Z)
    vec3 axis;     // the face's view direction
    vec3 across;   // its image's x
    vec3 up;       // its image's y
    float tanHalf; // tangent of its half field of view
};

ShadowFaceFrame shadowFaceFrame(GpuLight light, vec3 v)
{
    ShadowFaceFrame f;
#ifndef NO_SPOT_LIGHTS  // a program for scenes without spot lights has no spot faces
    float c = light.spotAxisCosCutoff.w;
    if (c >= SHADOW_SPOT_FACE_MIN_COS) {
        f.face = 0u;
        f.axis = light.spotAxisCosCutoff.xyz;
        vec3 upHint = abs(f.axis.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        f.across = normalize(cross(f.axis, upHint));
        f.up = cross(f.across, f.axis);
        f.tanHalf = sqrt(max(1.0 - c * c, 0.0)) / c * SHADOW_SPOT_FACE_SCALE;
        return f;
    }
#endif
    // A cube face: the major axis of v and its sign. Its frame is lookAt's for the up vectors of
    // render/shadows/ShadowFaces.cpp (kCubeFaceUp; tests/gl/ShadowFacesTest.cpp checks that
    // they agree), written as selects: no cross product, normalisation or array indexed per
    // lookup (llvmpipe keeps an indexed array or vector component in memory).
    vec3 a = abs(v);
    bool onX = a.x >= a.y && a.x >= a.z;
    bool onY = !onX && a.y >= a.z;
    float component = onX ? v.x : (onY ? v.y : v.z);
    float sign = component < 0.0 ? -1.0 : 1.0;
    f.face = (onX ? 0u : (onY ? 2u : 4u)) + (component < 0.0 ? 1u : 0u);
    f.axis = onX ? vec3(sign, 0.0, 0.0) : (onY ? vec3(0.0, sign, 0.0) : vec3(0.0, 0.0, sign));
    f.across = onX ? vec3(0.0, 0.0, -sign) : (onY ? vec3(1.0, 0.0, 0.0) : vec3(sign, 0.0, 0.0));
    f.up = onY ? vec3(0.0, 0.0, sign) : vec3(0.0, -1.0, 0.0);
    f.tanHalf = 1.0;
    return f;
}

// The receiver's place on its face: x and y from 0 to 1 across it.
vec2 shadowFaceUv(ShadowFaceFrame f, vec3 v, float depth)
{
    return vec2(dot(f.across, v), dot(f.up, v)) / (depth * f.tanHalf) * 0.5 + 0.5;
}

#ifdef SHADOW_PAGE_MARKING
// One word per (light, face): render/shadows/ShadowPool.cpp clears the words of the lights that
// cast shadows and sets every bit of the others', so that this pass marks only the former.
layout(std430, binding = SHADOW_PAGE_MARKS_BUFFER_BINDING) coherent buffer ShadowPageMarks {
    uint shadowPageMarks[];
};

// Marks the cell and level that the receiver at `position` needs of light `lightIndex`'s face:
// the level whose texel is about the size of the pixel there (render/shadows/ShadowPool.cpp
// clamps and, when the pool is short, lowers it).
void markShadowPages(uint lightIndex, GpuLight light, vec3 position)
{
    vec3 v = position - light.positionRadius.xyz;
    ShadowFaceFrame f = shadowFaceFrame(light, v);
    float depth = dot(f.axis, v);
    if (depth <= 0.0)
        return;
    ivec2 cell = clamp(ivec2(floor(shadowFaceUv(f, v, depth) * float(SHADOW_MARK_CELLS))), ivec2(0),
                       ivec2(SHADOW_MARK_CELLS - 1));
    // A pixel at view depth z is 2 z tan(fov_y / 2) / height across; a texel of a face of R
    // texels at depth d along its axis is 2 d tanHalf / R: equal where R is this.
    float texelsAcross = depth * f.tanHalf * frame.viewport.y / (max(viewDepth(position), 1e-6) * frame.projection.y);
    // The level nearest that in the log (a level is a factor of 2 in texel size): its texel is
    // within √2 of the pixel's either way, about one texel per pixel. Rounding up instead
    // (never under one) asks for 1 to 2 texels a pixel on this receiver and, as a face takes
    // its finest receiver's level, filled the pool at 1280x720 from 1,024 courtyard lights on.
    float pages = (texelsAcross + float(2 * SHADOW_GUARD_TEXELS)) / float(SHADOW_PAGE_TEXELS);
    int level = clamp(int(round(log2(max(pages, 1.0)))), 0, SHADOW_MAX_LEVEL);
    uint bits = (1u << uint(cell.y * SHADOW_MARK_CELLS + cell.x)) | (1u << uint(SHADOW_MARK_LEVEL_SHIFT + level));
    uint word = lightIndex * uint(SHADOW_CUBE_FACES) + f.face;
    // Most pairs find their bits set already: the atomic only where one is missing.
    if ((shadowPageMarks[word] & bits) != bits)
        atomicOr(shadowPageMarks[word], bits);
}
#endif

// The page tables (render/shadows/ShadowPool.cpp: writeTables), one RGBA32UI texture
// SHADOW_TABLE_WIDTH texels wide, read with texelFetch: llvmpipe fetches a texel for all its
// lanes at once where it loads a storage buffer lane by lane, and a 2D texture holds the
// tables of any light count within GL 4.5's least texture size. Texel i / 4, component i % 4:
// light i's first face record plus 1, or 0 where it has none. From texel `facesBase` on, each
// face's record in one texel:
// - x, y: the atlas texel minus the face texel of its resident part, and the first face texel
//   the tap may read in the part, each as two 16-bit halves (x low, y high) biased by 32768;
// - z: bits 0-2 the face's level, 3-9 its part's pages on a side (0: no part, no receiver asked
//   for the face), bit 10 whether its coarse page is there, 11-20 and 21-30 that page's column
//   and row in the atlas;
// - w: the bits of the face's far plane (its near plane is SHADOW_NEAR_FRACTION of it).
layout(binding = SHADOW_TABLES_UNIT) uniform usampler2D shadowTables;

uvec4 shadowTableTexel(int texel)
{
    return texelFetch(shadowTables, ivec2(texel % SHADOW_TABLE_WIDTH, texel / SHADOW_TABLE_WIDTH), 0);
}

// A record's two biased 16-bit halves.
vec2 shadowTableHalves(uint word)
{
    return vec2(ivec2(uvec2(word & 0xffffu, word >> 16u)) - 32768);
}

// 32-bit depth with hardware comparison (GL_LEQUAL) and bilinear filtering: one tap is a 2x2
// percentage-closer filter.
layout(binding = SHADOW_ATLAS_UNIT) uniform sampler2DShadow shadowAtlas;

// What a receiver at `position` reads of light `lightIndex`'s pages: its face, where the face
// resident part holds it or only the face's coarse page does, and the resolution read there.
struct ShadowPageRead {
    bool found;  // false: no page holds the receiver (the light has no face there)
    ShadowFaceFrame f;
    vec3 v;             // the receiver's offset from the light
    float depth;        // along the face's axis
    vec2 partOffset;    // atlas texel minus face texel in the resident part
    vec2 regionLow;     // the part's first readable face texel, and its last
    vec2 regionHigh;
    float partResolution;  // the face's resolution R at its level
    vec2 coarseOrigin;  // the atlas texel of face texel 0 of the coarse page
    float far;
    bool fine;          // read from the resident part, not the coarse page
    float resolution;   // of the level read
};

const float SHADOW_COARSE_RESOLUTION = float(SHADOW_PAGE_TEXELS - 2 * SHADOW_GUARD_TEXELS);

ShadowPageRead shadowPageRead(uint lightIndex, GpuLight light, vec3 position, int facesBase)
{
    ShadowPageRead r;
    r.found = false;
    // Component lightIndex % 4 as a dot product: an indexed vector component is kept in memory.
    uint first = uint(dot(vec4(shadowTableTexel(int(lightIndex / 4u))),
                          vec4(equal(uvec4(lightIndex % 4u), uvec4(0u, 1u, 2u, 3u)))));
    // No face: no receiver asked for one, so no visible surface reads it.
    if (first == 0u)
        return r;
    r.v = position - light.positionRadius.xyz;
    r.f = shadowFaceFrame(light, r.v);
    uvec4 record = shadowTableTexel(facesBase + int(first - 1u + r.f.face));
    r.partOffset = shadowTableHalves(record.x);
    r.regionLow = shadowTableHalves(record.y);
    uint level = record.z & 7u;
    uint pages = (record.z >> 3u) & 127u;
    r.partResolution = float((uint(SHADOW_PAGE_TEXELS) << level) - uint(2 * SHADOW_GUARD_TEXELS));
    r.regionHigh = r.regionLow + float(pages * uint(SHADOW_PAGE_TEXELS) - uint(2 * SHADOW_GUARD_TEXELS));
    bool coarse = (record.z & 1024u) != 0u;
    r.coarseOrigin = vec2(uvec2((record.z >> 11u) & 1023u, (record.z >> 21u) & 1023u)) * float(SHADOW_PAGE_TEXELS) +
                     float(SHADOW_GUARD_TEXELS);
    r.far = uintBitsToFloat(record.w);
    r.depth = dot(r.f.axis, r.v);
    vec2 fineTexel = shadowFaceUv(r.f, r.v, r.depth) * r.partResolution;
    r.fine = pages != 0u && all(greaterThanEqual(fineTexel, r.regionLow)) && all(lessThanEqual(fineTexel, r.regionHigh));
    r.found = r.fine || coarse;
    r.resolution = r.fine ? r.partResolution : SHADOW_COARSE_RESOLUTION;
    return r;
}

// The fraction of local light `light` (index `lightIndex`) that reaches `position`, a surface
// of normal `normal`: one tap of its face's resident part, or of the face's coarse page where
// the part does not hold the receiver. No loop. `atlasTexelSize`: 1 / the atlas' width, height;
// `facesBase`: the tables' first face texel.
float shadowPageLookup(uint lightIndex, GpuLight light, vec3 position, vec3 normal, vec2 atlasTexelSize,
                       int facesBase)
{
    ShadowPageRead r = shadowPageRead(lightIndex, light, position, facesBase);
    if (!r.found)
        return 1.0;
    // Normal offset: the receiver is moved off its surface along its normal by
    // (SHADOW_NORMAL_OFFSET_TEXELS + sin θ) texels of the level read (θ between its normal and
    // the light), at most SHADOW_MAX_NORMAL_OFFSET_WORLD. A surface tilted by θ changes depth by
    // texel · tan θ across the tap's texels; a point δ off it lies δ / cos θ before it along the
    // light, so δ ≥ texel · sin θ keeps a lit surface from shadowing itself at any tilt, with a
    // bounded offset where a depth bias alone would grow as tan θ. Half a 0.4-thick wall at
    // most: no receiver is moved through one.
    float texelWorld = 2.0 * r.depth * r.f.tanHalf / r.resolution;
    float cosine = clamp(dot(normal, -r.v) / max(length(r.v), 1e-20), 0.0, 1.0);
    float offset = min(texelWorld * (SHADOW_NORMAL_OFFSET_TEXELS + sqrt(1.0 - cosine * cosine)),
                       SHADOW_MAX_NORMAL_OFFSET_WORLD);
    vec3 w = r.v + normal * offset;
    // The same face and level as the receiver itself; the texel kept inside what was drawn.
    float offsetDepth = max(dot(r.f.axis, w), 1e-20);
    vec2 offsetUv = shadowFaceUv(r.f, w, offsetDepth);
    vec2 atlasTexel = r.fine ? clamp(offsetUv * r.partResolution, r.regionLow, r.regionHigh) + r.partOffset
                             : clamp(offsetUv * SHADOW_COARSE_RESOLUTION, vec2(0.0), vec2(SHADOW_COARSE_RESOLUTION)) +
                                   r.coarseOrigin;
    // And its depth pulled towards the light by SHADOW_BIAS_TEXELS texels, at most
    // SHADOW_MAX_BIAS_WORLD world units (a light 0.1 outside a 0.4-thick wall still shadowed).
    float bias = min(texelWorld * SHADOW_BIAS_TEXELS, SHADOW_MAX_BIAS_WORLD);
    float far = r.far;
    float near = SHADOW_NEAR_FRACTION * far;
    float biased = clamp(offsetDepth - bias, near, far);
    // Window depth of the face's perspective at that depth (ShadowFaces.cpp's projection).
    float reference = (far + near) / (far - near) * 0.5 + 0.5 - far * near / ((far - near) * biased);
    return texture(shadowAtlas, vec3(atlasTexel * atlasTexelSize, reference));
}

// The shadow texels per screen pixel at `position` of the level that light `lightIndex`'s lookup
// (shadowPageLookup) reads there: a pixel's footprint at the receiver's view depth z,
// 2 z tan(fov_y / 2) / height, over a texel's at its depth d along the face's axis,
// 2 d tanHalf / R, R the resolution of the face's resident part where the part holds the
// receiver, else of its coarse page (shadowPageRead: the lookup's own choice). 0 where the
// light has no page there (the lookup's "1": nothing to read). --view shadow-resolution
// (docs/shadows.md); no loop.
float shadowPageTexelsPerPixel(uint lightIndex, GpuLight light, vec3 position, int facesBase)
{
    ShadowPageRead r = shadowPageRead(lightIndex, light, position, facesBase);
    if (!r.found)
        return 0.0;
    return r.resolution * viewDepth(position) * frame.projection.y /
           (max(r.depth, 1e-20) * r.f.tanHalf * frame.viewport.y);
}
