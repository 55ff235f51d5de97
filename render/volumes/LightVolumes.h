// Bounding meshes for local lights, and which shape each light is drawn with.
//
// A volume must enclose the whole region where the light's A·S is non-zero, or the
// techniques that shade only inside volumes would cut light off. A tessellated sphere
// inscribed in the radius does not: its flat faces pass inside the sphere. The meshes here
// are scaled so that their faces lie outside the unit sphere (or unit cone), and every
// light's instance scales them by its radius.
#pragma once

#include <cstdint>
#include <vector>

#include "render/scene/GpuScene.h"
#include "scene/Scene.h"

namespace manylights {

// An icosphere subdivided `subdivisions` times, scaled so that the distance from the centre
// to its nearest face is 1: it contains the unit sphere. Convex, outward (CCW) faces.
// The light-volume techniques draw the icosahedron itself (20 faces, reaching 1.26 from the
// centre at its corners): llvmpipe sets up every triangle and shades every 4x4 block a
// triangle touches, so on screen-small volumes the 320 faces of two subdivisions cost more
// than the icosahedron's slack. Courtyard at 4096 lights, 1280x720: 2 subdivisions 44.97 M
// fragment-shader invocations and 475 ms of volumes' lighting pass, 1 subdivision 31.0 M and
// 352 ms, none 26.4 M and 265 ms (docs/performance.md).
Mesh makeBoundingSphere(int subdivisions = 0);

// A cone with its apex at (just behind) the origin, its axis along +Z, its base cap at z = 1,
// and its polygonal base circumscribing the circle of radius 1 (with a margin, see the .cpp):
// scaled by (R tan θ, R tan θ, R) it
// contains the part of the sphere of radius R inside the cone of half-angle θ < 90°, because
// that region never reaches further than R along the axis.
Mesh makeBoundingCone(int segments = 32);

// Spot lights up to this half-angle get a cone; wider ones a sphere, which is then the
// tighter bound (the cone's base radius R tan θ exceeds R beyond 45°, and it grows without
// limit towards 90°).
inline constexpr float kMaxConeCutoffDegrees = 60.0f;

// Indices into the light buffer, grouped by the shape each light is drawn with.
struct LightVolumeGroups {
    std::vector<std::uint32_t> spheres;     // point lights, and spots wider than the cone limit
    std::vector<std::uint32_t> cones;       // spots up to kMaxConeCutoffDegrees
    std::vector<std::uint32_t> fullScreen;  // unbounded lights: no volume encloses them
    // Lights that contribute nothing anywhere (radius 0) are in no group.
};

LightVolumeGroups groupLightVolumes(const std::vector<GpuLight>& lights);

// Whether `eye` lies inside light `light`'s sphere, well enough inside (1e-3 of the radius) that
// rounding cannot put it outside the bounding mesh, which contains the sphere. From there every
// face of the convex mesh faces away from the eye: there is no front face on screen, and each
// pixel's ray leaves the volume through exactly one back face.
bool eyeInsideSphereVolume(const GpuLight& light, const glm::vec3& eye);

}  // namespace manylights
