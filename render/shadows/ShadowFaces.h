// The geometry of a local light's shadow faces (docs/shadows.md), the same on both sides of
// the shadow-page pool: shaders/lib/shadow_pages.glsl computes a receiver's face, texel and
// marks from it, and render/shadows/ShadowPool.cpp draws each resident part with the matrices
// built here. No GL: unit-tested (tests/gl/ShadowFacesTest.cpp).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "render/scene/SceneLights.h"
#include "scene/Scene.h"

namespace manylights {

// Texels across a whole face at `level` (16 · 2^level − 2: with its guard texels it fills
// 2^level pages on a side).
int shadowFaceResolution(int level);

// 1 for a spot light of cutoff up to 75 degrees, 6 for a point light or a wider spot: decided
// from the packed record, as the shaders decide it.
int shadowFaceCount(const GpuLight& light);

// A face's frame: its view looks along `axis` from the light, with `across` and `up` its
// image's x and y (lookAt's), and a square field of view of half-angle tangent `tanHalf`.
struct ShadowFaceFrame {
    glm::vec3 axis{0.0f, 0.0f, -1.0f};
    glm::vec3 across{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float tanHalf = 1.0f;
};
// Face `face` (0 for a spot's one; 0-5 for a cube: +X, −X, +Y, −Y, +Z, −Z).
ShadowFaceFrame shadowFaceFrame(const GpuLight& light, int face);
// World → the face's clip space: its view from `position` and a perspective of near and far.
glm::mat4 shadowFaceViewProjection(const glm::vec3& position, const ShadowFaceFrame& frame, float near, float far);

// A mark (shaders/lib/shadow_pages.glsl): the 4x4 cells a face's receivers fall in and the
// levels they ask for.
std::uint32_t markedCells(std::uint32_t mark);
// The highest level asked for; -1 where the mark has none.
int markedLevel(std::uint32_t mark);

// The resident part of a face at `level`: face texels [x0, x0 + 16 · pages) on each axis
// (guard texels included; texel coordinates run 0 to shadowFaceResolution(level) across the
// face), a square of `pages` on a side in the atlas. `whole`: the part is the whole face, and
// no coarse page goes with it.
struct ShadowFaceRegion {
    int level = 0;
    int x0 = -1;
    int y0 = -1;
    int pages = 1;
    bool whole = true;
    friend bool operator==(const ShadowFaceRegion&, const ShadowFaceRegion&) = default;
};
// The smallest such square around the marked `cells` (a texel of margin beyond them and the
// guard), or the whole face where that is no smaller.
ShadowFaceRegion shadowFaceRegion(std::uint32_t cells, int level);
// The whole face at level 0: the coarse page.
ShadowFaceRegion coarseShadowFaceRegion();
// The pages a face at `region` holds: its square, and the coarse page beside a part.
std::size_t shadowFacePages(const ShadowFaceRegion& region);

// Whether a caster's world box may draw into `region` of a face of a light at `position` that
// reaches `far`: the box meets the light's sphere, and its projection meets the region (a box
// reaching behind the near plane is kept: conservative).
bool casterMayMeetFace(const Bounds& box, const glm::vec3& position, float near, float far,
                       const ShadowFaceFrame& frame, const ShadowFaceRegion& region);

}  // namespace manylights
