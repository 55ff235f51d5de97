// Tangent frames (scene/Tangents.h): exact tangents and handedness for meshes whose uv mapping
// is known, mirrored uvs, and degenerate input that must not produce NaN.
#include "scene/Tangents.h"

#include <cmath>

#include <gtest/gtest.h>

#include "scene/Meshes.h"

namespace manylights {
namespace {

// Tangents are computed in double and stored as float: equal to float rounding.
constexpr float kTangentTolerance = 1e-6f;

void expectTangent(const Vertex& vertex, const glm::vec3& tangent, float handedness)
{
    EXPECT_NEAR(vertex.tangent.x, tangent.x, kTangentTolerance);
    EXPECT_NEAR(vertex.tangent.y, tangent.y, kTangentTolerance);
    EXPECT_NEAR(vertex.tangent.z, tangent.z, kTangentTolerance);
    EXPECT_EQ(vertex.tangent.w, handedness);
}

// The bitangent the shader rebuilds, w · cross(N, T), must point along increasing v.
glm::vec3 bitangent(const Vertex& vertex)
{
    return vertex.tangent.w * glm::cross(vertex.normal, glm::vec3(vertex.tangent));
}

TEST(Tangents, PlaneTangentIsItsUAxis)
{
    // makePlane maps u to +X and v to −Z (scene/Meshes.cpp addQuad): T = +X, B = −Z, N = +Y,
    // and cross(N, T) = cross(+Y, +X) = −Z = B, so w = +1.
    const Mesh plane = makePlane(4.0f, 2.0f);
    ASSERT_EQ(plane.vertices.size(), 4u);
    for (const Vertex& vertex : plane.vertices) {
        expectTangent(vertex, {1.0f, 0.0f, 0.0f}, 1.0f);
        const glm::vec3 b = bitangent(vertex);
        EXPECT_NEAR(b.z, -1.0f, kTangentTolerance);
    }
}

TEST(Tangents, EveryBoxFaceGetsDpDuAndRightHandedFrame)
{
    const Mesh box = makeBox(glm::vec3(1.0f, 2.0f, 3.0f));
    ASSERT_EQ(box.vertices.size(), 24u);
    // Each face is a quad of four vertices; its tangent is the exact direction in which u grows
    // along the face, found here from two corners of the quad with different u.
    for (std::size_t face = 0; face < 6; ++face) {
        const Vertex* v = &box.vertices[face * 4];
        glm::vec3 du(0.0f);
        for (int i = 1; i < 4; ++i)
            if (v[i].uv.y == v[0].uv.y && v[i].uv.x != v[0].uv.x)
                du = glm::normalize((v[i].position - v[0].position) * (v[i].uv.x - v[0].uv.x));
        ASSERT_NE(du, glm::vec3(0.0f)) << "face " << face;
        for (int i = 0; i < 4; ++i) {
            expectTangent(v[i], du, 1.0f);
            EXPECT_NEAR(glm::dot(glm::vec3(v[i].tangent), v[i].normal), 0.0f, kTangentTolerance);
        }
    }
}

TEST(Tangents, MirroredUvsGiveNegativeHandedness)
{
    Mesh plane = makePlane(2.0f, 2.0f);
    for (Vertex& vertex : plane.vertices) {
        vertex.uv.x = 1.0f - vertex.uv.x;  // mirror u: the tangent flips, v does not
        vertex.tangent = glm::vec4(0.0f);
    }
    generateTangents(plane);
    for (const Vertex& vertex : plane.vertices) {
        expectTangent(vertex, {-1.0f, 0.0f, 0.0f}, -1.0f);
        // The rebuilt bitangent still points along increasing v (−Z).
        EXPECT_NEAR(bitangent(vertex).z, -1.0f, kTangentTolerance);
    }
}

TEST(Tangents, OrthogonalisedAgainstTheVertexNormal)
{
    Mesh plane = makePlane(2.0f, 2.0f);
    // Tilt every normal towards +X: Gram-Schmidt leaves a unit tangent perpendicular to it.
    const glm::vec3 tilted = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    for (Vertex& vertex : plane.vertices)
        vertex.normal = tilted;
    generateTangents(plane);
    const glm::vec3 expected = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    for (const Vertex& vertex : plane.vertices)
        expectTangent(vertex, expected, 1.0f);
}

TEST(Tangents, SphereFramesAreUnitOrthogonalAndRightHanded)
{
    const Mesh sphere = makeSphere(1.0f, 16, 8);
    for (const Vertex& vertex : sphere.vertices) {
        const glm::vec3 t(vertex.tangent);
        ASSERT_TRUE(std::isfinite(t.x + t.y + t.z));
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, glm::normalize(vertex.normal)), 0.0f, 1e-5f);
        // u runs around Y towards the east, cross(+Y, N). The triangles span two latitudes, so
        // their uv derivatives tilt the tangent off the horizontal by up to half a stack
        // (11.25° here): cos 11.25° ≈ 0.981.
        if (std::abs(vertex.normal.y) < 0.9f) {
            const glm::vec3 east = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), vertex.normal));
            EXPECT_GT(glm::dot(t, east), 0.98f);
        }
        EXPECT_EQ(vertex.tangent.w, 1.0f);
    }
}

TEST(Tangents, DegenerateUvsGiveFiniteFramesNotNaN)
{
    Mesh mesh = makePlane(2.0f, 2.0f);
    for (Vertex& vertex : mesh.vertices) {
        vertex.uv = glm::vec2(0.25f);  // every corner at one uv: no direction at all
        vertex.tangent = glm::vec4(0.0f);
    }
    // And a triangle of zero area (all corners at one point).
    mesh.vertices.push_back({glm::vec3(5.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(0.0f)});
    mesh.vertices.push_back({glm::vec3(5.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(1.0f, 0.0f)});
    mesh.vertices.push_back({glm::vec3(5.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(0.0f, 1.0f)});
    mesh.indices.insert(mesh.indices.end(), {4u, 5u, 6u});
    generateTangents(mesh);
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 t(vertex.tangent);
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(t, vertex.normal), 0.0f, 1e-6f);
        EXPECT_EQ(std::abs(vertex.tangent.w), 1.0f);
    }
}

TEST(Tangents, GivenTangentsAreKept)
{
    Mesh plane = makePlane(2.0f, 2.0f);
    plane.vertices[0].tangent = glm::vec4(0.0f, 0.0f, 1.0f, -1.0f);
    const Vertex before = plane.vertices[1];
    generateTangentsIfMissing(plane);
    EXPECT_EQ(plane.vertices[0].tangent, glm::vec4(0.0f, 0.0f, 1.0f, -1.0f));
    EXPECT_EQ(plane.vertices[1].tangent, before.tangent);
}

}  // namespace
}  // namespace manylights
