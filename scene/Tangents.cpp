#include "scene/Tangents.h"

#include <algorithm>
#include <cmath>

namespace manylights {

namespace {

// Per vertex, the angle-weighted sums of the triangles' tangents, apart for each uv orientation.
struct TangentSums {
    glm::dvec3 tangent[2]{glm::dvec3(0.0), glm::dvec3(0.0)};  // [0]: w = +1, [1]: w = −1
    double weight[2]{0.0, 0.0};
};

glm::dvec3 projectIntoPlane(const glm::dvec3& v, const glm::dvec3& normal) { return v - normal * glm::dot(normal, v); }

// Any unit vector perpendicular to `normal` (for vertices no triangle gives a tangent to).
glm::dvec3 anyPerpendicular(const glm::dvec3& normal)
{
    const glm::dvec3 axis = std::abs(normal.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 t = projectIntoPlane(axis, normal);
    return glm::normalize(t);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b)
{
    const double la = glm::length(a);
    const double lb = glm::length(b);
    if (la == 0.0 || lb == 0.0)
        return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

glm::dvec3 unitNormal(const Vertex& vertex)
{
    const glm::dvec3 n(vertex.normal);
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
}

}  // namespace

void generateTangents(Mesh& mesh)
{
    std::vector<TangentSums> sums(mesh.vertices.size());
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t corner[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        if (corner[0] >= mesh.vertices.size() || corner[1] >= mesh.vertices.size() || corner[2] >= mesh.vertices.size())
            continue;
        const Vertex* v[3] = {&mesh.vertices[corner[0]], &mesh.vertices[corner[1]], &mesh.vertices[corner[2]]};
        const glm::dvec3 e1 = glm::dvec3(v[1]->position) - glm::dvec3(v[0]->position);
        const glm::dvec3 e2 = glm::dvec3(v[2]->position) - glm::dvec3(v[0]->position);
        const glm::dvec2 d1 = glm::dvec2(v[1]->uv) - glm::dvec2(v[0]->uv);
        const glm::dvec2 d2 = glm::dvec2(v[2]->uv) - glm::dvec2(v[0]->uv);
        const double uvArea = d1.x * d2.y - d2.x * d1.y;
        // Zero uv area: the uvs give no direction (all corners share a uv, or lie on a line).
        // The tolerance is relative to the uv extent so tiny but valid uv triangles still count.
        const double uvScale = std::max({std::abs(d1.x), std::abs(d1.y), std::abs(d2.x), std::abs(d2.y)});
        if (!(std::abs(uvArea) > 1e-12 * uvScale * uvScale) || !std::isfinite(uvArea))
            continue;
        // e1 = d1.x·T + d1.y·B, e2 = d2.x·T + d2.y·B, solved for T (the direction of increasing u);
        // T is left unnormalised here, its length says nothing after projection.
        const glm::dvec3 faceTangent = (e1 * d2.y - e2 * d1.y) / uvArea;
        const glm::dvec3 faceBitangent = (e2 * d1.x - e1 * d2.x) / uvArea;
        const glm::dvec3 faceNormal = glm::cross(e1, e2);
        if (glm::dot(faceNormal, faceNormal) == 0.0 || !std::isfinite(glm::dot(faceTangent, faceTangent)))
            continue;
        // Handedness of the uv mapping on this face: is (T, B, face normal) right-handed?
        const int side = glm::dot(glm::cross(faceNormal, faceTangent), faceBitangent) < 0.0 ? 1 : 0;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 here(v[k]->position);
            const double angle =
                angleBetween(glm::dvec3(v[(k + 1) % 3]->position) - here, glm::dvec3(v[(k + 2) % 3]->position) - here);
            const glm::dvec3 projected = projectIntoPlane(faceTangent, unitNormal(*v[k]));
            const double length = glm::length(projected);
            if (!(length > 0.0) || !(angle > 0.0))
                continue;
            TangentSums& sum = sums[corner[k]];
            sum.tangent[side] += projected / length * angle;
            sum.weight[side] += angle;
        }
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        Vertex& vertex = mesh.vertices[i];
        const glm::dvec3 normal = unitNormal(vertex);
        const TangentSums& sum = sums[i];
        const int side = sum.weight[1] > sum.weight[0] ? 1 : 0;
        // Gram-Schmidt: the tangent is made exactly perpendicular to the normal.
        glm::dvec3 tangent = projectIntoPlane(sum.tangent[side], normal);
        const double length = glm::length(tangent);
        tangent = length > 1e-12 ? tangent / length : anyPerpendicular(normal);
        // With B the direction of increasing v: w = sign(dot(cross(N, T), B)), which is −1
        // exactly for the mirrored side.
        const float handedness = side == 1 ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(glm::vec3(tangent), handedness);
    }
}

void generateTangentsIfMissing(Mesh& mesh)
{
    const bool anyGiven = std::any_of(mesh.vertices.begin(), mesh.vertices.end(),
                                      [](const Vertex& v) { return v.tangent != glm::vec4(0.0f); });
    if (!anyGiven)
        generateTangents(mesh);
}

}  // namespace manylights
