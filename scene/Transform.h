// Object transforms of docs/scene-format.md: M = T · Rz · Ry · Rx · S, Euler angles in degrees.
#pragma once

#include <glm/glm.hpp>

namespace manylights {

glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotateDegrees, const glm::vec3& scale);

// Inverse transpose of the upper 3x3: transforms normals correctly under non-uniform scale.
glm::mat3 normalMatrix(const glm::mat4& model);

}  // namespace manylights
