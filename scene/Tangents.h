// Per-vertex tangent frames for normal mapping, computed from the texture coordinates the way
// MikkTSpace does (the convention glTF and most baking tools assume). No GL here.
#pragma once

#include "scene/Mesh.h"

namespace manylights {

// Fills every vertex's `tangent` of an indexed triangle mesh: xyz the unit tangent (direction of
// increasing u, orthogonalised against the vertex normal), w the handedness ±1 so that the
// bitangent (direction of increasing v) is w · cross(normal, tangent).
//
// Per triangle, the tangent T and bitangent B solve the uv derivatives
// (e1 = du1·T + dv1·B, e2 = du2·T + dv2·B); each corner adds T, projected into the plane of
// its vertex normal and normalised, weighted by the triangle's angle at that corner, to its
// vertex. Triangles of opposite uv orientation (mirrored uvs) are summed apart and a vertex
// takes the orientation with the larger weight (MikkTSpace splits such vertices instead; a
// model that shares one vertex between mirrored halves is rare and only its seam differs).
// Triangles with degenerate uvs (zero uv area) or zero area contribute nothing; a vertex that
// gets nothing receives a tangent perpendicular to its normal with w = 1, never NaN.
void generateTangents(Mesh& mesh);

// generateTangents when no vertex has a tangent (all zero), e.g. OBJ files and primitives; a
// mesh file's own tangents (glTF TANGENT) are kept. The one call every finished mesh goes
// through.
void generateTangentsIfMissing(Mesh& mesh);

}  // namespace manylights
