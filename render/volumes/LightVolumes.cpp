#include "render/volumes/LightVolumes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "scene/Falloff.h"

namespace manylights {

namespace {

void addVertex(Mesh& mesh, const glm::vec3& position)
{
    mesh.vertices.push_back({position, glm::normalize(position), glm::vec2(0.0f)});
}

}  // namespace

Mesh makeBoundingSphere(int subdivisions)
{
    // The icosahedron, then each triangle split in four with the new vertices pushed out to
    // the unit sphere.
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                        {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& p : positions)
        p = glm::normalize(p);
    std::vector<std::uint32_t> triangles = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                            4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                            6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [found, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(positions.size()));
            if (inserted)
                positions.push_back(glm::normalize(positions[a] + positions[b]));
            return found->second;
        };
        std::vector<std::uint32_t> finer;
        for (std::size_t i = 0; i < triangles.size(); i += 3) {
            const std::uint32_t a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        triangles = std::move(finer);
    }
    // The faces' planes pass inside the unit sphere; scale by 1 / (nearest plane distance).
    float inradius = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < triangles.size(); i += 3) {
        const glm::vec3 a = positions[triangles[i]], b = positions[triangles[i + 1]], c = positions[triangles[i + 2]];
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
        inradius = std::min(inradius, std::abs(glm::dot(normal, a)));
    }
    Mesh mesh;
    mesh.name = "light volume sphere";
    for (const glm::vec3& p : positions)
        addVertex(mesh, p / inradius);
    mesh.indices = std::move(triangles);
    return mesh;
}

Mesh makeBoundingCone(int segments)
{
    Mesh mesh;
    mesh.name = "light volume cone";
    // A regular polygon circumscribing the unit circle has its corners at 1 / cos(π / n).
    // Unlike a sphere's edge, where the attenuation is already zero, a spot cone's side is a
    // hard edge of light: a surface exactly on a mesh face that touches the true cone would
    // be a depth-test tie, lit or not by rounding. So the mesh is pushed strictly outside
    // the cone, 1% wider at the base and with its apex 1% of the radius behind the light;
    // the cone from (0, 0, -apexMargin) through the widened base stays outside the true
    // cone all the way down to the apex.
    constexpr float kBaseMargin = 1.01f;
    constexpr float kApexMargin = 0.01f;
    const float corner = kBaseMargin / std::cos(3.14159265358979f / static_cast<float>(segments));
    addVertex(mesh, glm::vec3(0.0f, 0.0f, -kApexMargin));  // apex
    addVertex(mesh, glm::vec3(0.0f, 0.0f, 1.0f));          // centre of the base cap
    for (int i = 0; i < segments; ++i) {
        const float angle = 2.0f * 3.14159265358979f * static_cast<float>(i) / static_cast<float>(segments);
        addVertex(mesh, glm::vec3(corner * std::cos(angle), corner * std::sin(angle), 1.0f));
    }
    for (int i = 0; i < segments; ++i) {
        const auto current = static_cast<std::uint32_t>(2 + i);
        const auto next = static_cast<std::uint32_t>(2 + (i + 1) % segments);
        // Counter-clockwise seen from outside: the side faces look away from the axis, the
        // cap looks along +Z.
        mesh.indices.insert(mesh.indices.end(), {0u, next, current});
        mesh.indices.insert(mesh.indices.end(), {1u, current, next});
    }
    return mesh;
}

LightVolumeGroups groupLightVolumes(const std::vector<GpuLight>& lights)
{
    const float minConeCos = std::cos(glm::radians(kMaxConeCutoffDegrees));
    LightVolumeGroups groups;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const GpuLight& light = lights[i];
        const float radius = light.positionRadius.w;
        const auto index = static_cast<std::uint32_t>(i);
        if (radius <= 0.0f)
            continue;
        if (radius >= falloff::kUnboundedRadius)
            groups.fullScreen.push_back(index);
        else if (light.spotAxisCosCutoff.w >= minConeCos)
            groups.cones.push_back(index);
        else
            groups.spheres.push_back(index);
    }
    return groups;
}

bool eyeInsideSphereVolume(const GpuLight& light, const glm::vec3& eye)
{
    const float radius = light.positionRadius.w;
    return glm::distance(glm::vec3(light.positionRadius), eye) < radius * (1.0f - 1e-3f);
}

}  // namespace manylights
