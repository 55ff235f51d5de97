#include "scene/Scene.h"

#include <cmath>

#include "core/Error.h"

namespace manylights {

CameraProblem cameraProblem(const Camera& camera)
{
    const glm::vec3 view = camera.lookAt - camera.eye;
    if (glm::dot(view, view) == 0.0f)
        return CameraProblem::LookAtIsEye;
    // eye [3e38, 0, 0] and look_at [-3e38, 0, 0] are finite floats whose difference is not,
    // and past about 1.8e19 the squared distance is not.
    if (!std::isfinite(glm::length(view)))
        return CameraProblem::DistanceOverflows;
    // The sine of the angle between up and the view direction; below this the view basis is
    // numerically meaningless (about 0.00006 degrees). A zero up fails the first test.
    if (!(glm::length(camera.up) > 0.0f) ||
        !(glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) >= 1e-6f))
        return CameraProblem::UpAlongView;
    return CameraProblem::None;
}

const char* describe(CameraProblem problem)
{
    switch (problem) {
    case CameraProblem::None: return "a valid camera";
    case CameraProblem::LookAtIsEye: return "look_at must differ from eye";
    case CameraProblem::DistanceOverflows:
        return "look_at - eye overflows a float (their distance squared is beyond 3.4e38); bring them closer together";
    case CameraProblem::UpAlongView: return "up is parallel to the view direction (look_at - eye)";
    }
    return "";
}

Bounds Scene::worldBounds() const
{
    // Shared meshes are common (every primitive with the same parameters is one mesh), so
    // each mesh's local bounds are computed once rather than once per object.
    std::vector<Bounds> local;
    local.reserve(meshes.size());
    for (const Mesh& mesh : meshes)
        local.push_back(mesh.bounds());

    Bounds world;
    for (const Object& object : objects) {
        ML_ASSERT(object.mesh < meshes.size());
        const Bounds& b = local[object.mesh];
        if (b.empty())
            continue;
        // The transformed box's corners bound the transformed mesh (affine maps keep convex
        // hulls), which is tight enough for framing a camera or sizing shadow maps.
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                              (corner & 4) ? b.max.z : b.min.z);
            world.extend(glm::vec3(object.transform * glm::vec4(p, 1.0f)));
        }
    }
    return world;
}

}  // namespace manylights
