// Mesh sources: procedural primitives (centred on the origin, docs/scene-format.md) and OBJ files.
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "scene/Mesh.h"

namespace manylights {

Mesh makePlane(float sizeX, float sizeZ);  // XZ plane, normal +Y
Mesh makeBox(const glm::vec3& size);
Mesh makeSphere(float radius, int slices = 48, int stacks = 24);
Mesh makeCone(float radius, float height, int slices = 48);      // apex at +height/2, base capped
Mesh makeCylinder(float radius, float height, int slices = 48);  // capped
Mesh makeTorus(float radius, float tube, int rings = 48, int sides = 24);

// Replaces every vertex normal with the normalised, area-weighted sum of the normals of the
// faces sharing its position.
void computeSmoothNormals(Mesh& mesh);
// The same for the vertices with replace[i] set only (those a file gave no normal).
void computeSmoothNormals(Mesh& mesh, const std::vector<bool>& replace);

// True when the triangle's area is zero relative to its edges: its normal would be NaN.
bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace manylights
