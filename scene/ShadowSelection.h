// Which local lights cast shadows (the --shadow-lights budget) and which objects each
// shadow map must draw. No GL: the ranking is unit-tested (tests/unit/ShadowSelectionTest.cpp).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace manylights {

// --shadow-lights all (and a scene's "shadow_lights": "all"): a cap no light count reaches, so
// every local light that does not opt out ("casts_shadows": false) casts shadows.
inline constexpr int kAllShadowLights = std::numeric_limits<int>::max();

// The shadow-page pool (render/shadows/, docs/shadows.md), in MiB (--shadow-pool-mib): the
// depth atlas and the page tables together. Whole multiples of kShadowPoolGrainMiB (one
// 1024² block of 32-bit depth); the default holds the arithmetic's 65,536 lights.
inline constexpr int kDefaultShadowPoolMiB = 256;
inline constexpr int kShadowPoolGrainMiB = 4;
inline constexpr int kMinShadowPoolMiB = kShadowPoolGrainMiB;
inline constexpr int kMaxShadowPoolMiB = 1024;

// The axis-aligned box around `local` under an affine transform (its transformed corners'
// box: affine maps keep convex hulls, so it bounds the transformed contents).
Bounds transformedBounds(const Bounds& local, const glm::mat4& transform);

// Whether a box and a sphere overlap (the box's nearest point to the centre is within radius).
bool boxIntersectsSphere(const Bounds& box, const glm::vec3& centre, float radius);

// Whether a box may overlap a spot light's cone of `cutoffDegrees` around unit `axis` from
// `apex`, cut at `radius`: conservative (true when unsure), exact enough to skip objects
// behind or beside the cone. Uses the box's bounding sphere against the cone.
bool boxMayIntersectCone(const Bounds& box, const glm::vec3& apex, const glm::vec3& axis, float cutoffDegrees,
                         float radius);

// The fraction of the image (0..1) covered by the screen rectangle of a sphere, clipped to the
// screen: the projected corners of the sphere's bounding box, or the whole image when the
// sphere reaches behind the camera's near plane. `viewProjection` is the camera's.
double screenCoverage(const glm::vec3& centre, float radius, const glm::mat4& viewProjection);

// What the ranking needs of a local light: its bounding sphere and brightest channel.
struct ShadowCandidate {
    glm::vec3 position{0.0f};
    float radius = 0.0f;        // lightRadius (the culling radius); may be "unbounded"
    float maxIntensity = 0.0f;  // Imax = max(intensity.r, .g, .b)
};

// The lights that get shadow maps, at most `budget` of them, best first: ranked by
// screenCoverage(bounding sphere) × Imax, ties by lower index so the choice is deterministic.
// Lights that cover no pixel or have no intensity are never chosen. Returns indices into
// `candidates`.
std::vector<std::size_t> selectShadowLights(const std::vector<ShadowCandidate>& candidates,
                                            const glm::mat4& viewProjection, int budget);

}  // namespace manylights
