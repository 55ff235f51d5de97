#include "scene/Scene.h"

#include "core/Error.h"

namespace manylights {

Bounds Mesh::bounds() const
{
    Bounds b;
    for (const Vertex& v : vertices)
        b.extend(v.position);
    return b;
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
