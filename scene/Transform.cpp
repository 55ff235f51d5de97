#include "scene/Transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace manylights {

glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotateDegrees, const glm::vec3& scale)
{
    // Built right to left so that a point is scaled first, then rotated about X, Y and Z in
    // that order, then translated: M = T · Rz · Ry · Rx · S (docs/scene-format.md).
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotateDegrees.z), glm::vec3(0.0f, 0.0f, 1.0f));
    m = glm::rotate(m, glm::radians(rotateDegrees.y), glm::vec3(0.0f, 1.0f, 0.0f));
    m = glm::rotate(m, glm::radians(rotateDegrees.x), glm::vec3(1.0f, 0.0f, 0.0f));
    return glm::scale(m, scale);
}

glm::mat3 normalMatrix(const glm::mat4& model) { return glm::transpose(glm::inverse(glm::mat3(model))); }

}  // namespace manylights
