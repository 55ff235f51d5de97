// A surface of revolution whose profile moves with time: the radius at height fraction v is
//     r(v, t) = radius + amplitude · sin(2π · (waves · v − speed · t))
// (a wave travelling up a vase), and the surface point at (u, v) is
//     P(u, v, t) = (r cos 2πu, height · v, r sin 2πu).
// The same formulas run in shaders/lib/revolution.glsl, where the vertex shader computes the
// dynamic surface from the mesh's uvs and the frame time; the functions here build the static
// CPU mesh and are what the GPU version is tested against.
#pragma once

#include <glm/glm.hpp>

namespace manylights {

struct Mesh;  // scene/Mesh.h

struct RevolutionProfile {
    float radius = 0.5f;  // mean radius; > amplitude so that the surface never pinches
    float height = 1.5f;
    float amplitude = 0.12f;
    float waves = 1.5f;  // wave crests along the height
    float speed = 0.5f;  // crests passing a point per second (0: a static surface)
};

glm::vec3 revolutionPosition(const RevolutionProfile& profile, float u, float v, double t);
// The unit outward normal: the normalised cross product of ∂P/∂v and ∂P/∂u, analytically.
glm::vec3 revolutionNormal(const RevolutionProfile& profile, float u, float v, double t);

// The surface at time t as a grid of (around + 1) × (up + 1) vertices whose uvs are (u, v):
// the seam is duplicated so that u runs 0..1. The open ends are not capped.
Mesh makeRevolutionMesh(const RevolutionProfile& profile, double t, int around = 48, int up = 24);

}  // namespace manylights
