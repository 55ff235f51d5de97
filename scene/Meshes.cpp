#include "scene/Meshes.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numbers>
#include <tuple>
#include <unordered_map>

#include "core/Error.h"
#include "scene/Tangents.h"

namespace manylights {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string formatNumber(float value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(value));
    return buffer;
}

std::uint32_t vertexIndex(const Mesh& mesh) { return static_cast<std::uint32_t>(mesh.vertices.size()); }

void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// One flat rectangle with normal u × v, spanning ±halfU along u and ±halfV along v around
// `centre`. Texture coordinates follow u and v so that the tangent frame (dP/du, dP/dv, N)
// is right-handed, which normal mapping relies on.
void addQuad(Mesh& mesh, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float halfU, float halfV)
{
    const glm::vec3 normal = glm::cross(u, v);
    const std::uint32_t first = vertexIndex(mesh);
    const glm::vec2 corners[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
    for (const glm::vec2& corner : corners) {
        const glm::vec3 position = centre + u * (corner.x * halfU) + v * (corner.y * halfV);
        mesh.vertices.push_back({position, normal, 0.5f * corner + 0.5f});
    }
    addTriangle(mesh, first, first + 1, first + 2);
    addTriangle(mesh, first, first + 2, first + 3);
}

// The unit vector around the Y axis at angle phi, measured from +Z towards +X, so that
// increasing phi (increasing u) together with +Y gives an outward-facing frame.
glm::vec3 aroundY(double phi) { return {static_cast<float>(std::sin(phi)), 0.0f, static_cast<float>(std::cos(phi))}; }

double sliceAngle(double j, int slices) { return kTwoPi * j / slices; }

// A flat disc at height y facing up (+Y) or down (−Y), with its own vertices so that the
// edge between it and the side stays sharp.
void addDisc(Mesh& mesh, float radius, float y, bool facingUp, int slices)
{
    const glm::vec3 normal{0.0f, facingUp ? 1.0f : -1.0f, 0.0f};
    // Planar mapping; v flips with the facing so that the tangent frame stays right-handed.
    const float vSign = facingUp ? -1.0f : 1.0f;
    const std::uint32_t centre = vertexIndex(mesh);
    mesh.vertices.push_back({{0.0f, y, 0.0f}, normal, {0.5f, 0.5f}});
    for (int j = 0; j < slices; ++j) {
        const glm::vec3 direction = aroundY(sliceAngle(j, slices));
        mesh.vertices.push_back({direction * radius + glm::vec3{0.0f, y, 0.0f},
                                 normal,
                                 {0.5f + 0.5f * direction.x, 0.5f + 0.5f * vSign * direction.z}});
    }
    for (int j = 0; j < slices; ++j) {
        const std::uint32_t a = centre + 1 + static_cast<std::uint32_t>(j);
        const std::uint32_t b = centre + 1 + static_cast<std::uint32_t>((j + 1) % slices);
        // Going from slice j to j+1 turns counter-clockwise seen from +Y.
        if (facingUp)
            addTriangle(mesh, centre, a, b);
        else
            addTriangle(mesh, centre, b, a);
    }
}

// A (rows+1) × (columns+1) grid of vertices, laid out row by row, whose u runs along the
// columns and v along the rows; (u, v, outward normal) is right-handed, so the quads are
// counter-clockwise seen from outside. Triangles whose corners coincide (at a pole) are
// left out.
void addGridTriangles(Mesh& mesh, std::uint32_t first, int rows, int columns)
{
    const auto at = [&](int row, int column) {
        return first + static_cast<std::uint32_t>(row * (columns + 1) + column);
    };
    const auto distinct = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const glm::vec3& pa = mesh.vertices[a].position;
        const glm::vec3& pb = mesh.vertices[b].position;
        const glm::vec3& pc = mesh.vertices[c].position;
        return pa != pb && pb != pc && pc != pa;
    };
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const std::uint32_t a = at(row, column);
            const std::uint32_t b = at(row, column + 1);
            const std::uint32_t c = at(row + 1, column + 1);
            const std::uint32_t d = at(row + 1, column);
            if (distinct(a, b, c))
                addTriangle(mesh, a, b, c);
            if (distinct(a, c, d))
                addTriangle(mesh, a, c, d);
        }
    }
}

}  // namespace

Mesh makePlane(float sizeX, float sizeZ)
{
    ML_ASSERT(sizeX > 0.0f && sizeZ > 0.0f);
    Mesh mesh;
    mesh.name = "plane " + formatNumber(sizeX) + "x" + formatNumber(sizeZ);
    addQuad(mesh, glm::vec3{0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.5f * sizeX, 0.5f * sizeZ);
    generateTangentsIfMissing(mesh);
    return mesh;
}

Mesh makeBox(const glm::vec3& size)
{
    ML_ASSERT(size.x > 0.0f && size.y > 0.0f && size.z > 0.0f);
    Mesh mesh;
    mesh.name = "box " + formatNumber(size.x) + "x" + formatNumber(size.y) + "x" + formatNumber(size.z);
    const glm::vec3 half = 0.5f * size;
    // Each face: (u, v) with u × v the outward normal.
    struct Face {
        glm::vec3 u, v;
    };
    const Face faces[6] = {
        {{0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}},  // +X
        {{0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}},   // −X
        {{1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}},  // +Y
        {{1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}},   // −Y
        {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},   // +Z
        {{-1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},  // −Z
    };
    for (const Face& face : faces) {
        const glm::vec3 normal = glm::cross(face.u, face.v);
        addQuad(mesh, normal * half, face.u, face.v, glm::dot(glm::abs(face.u), half),
                glm::dot(glm::abs(face.v), half));
    }
    generateTangentsIfMissing(mesh);
    return mesh;
}

Mesh makeSphere(float radius, int slices, int stacks)
{
    ML_ASSERT(radius > 0.0f && slices >= 3 && stacks >= 2);
    Mesh mesh;
    mesh.name = "sphere r=" + formatNumber(radius);
    // Rows run from the south pole (v = 0) up to the north pole (v = 1); the seam column is
    // duplicated so that u can reach 1.
    for (int i = 0; i <= stacks; ++i) {
        const bool pole = i == 0 || i == stacks;
        const double theta = std::numbers::pi * i / stacks;  // from the south pole
        // Exact poles, so the pole triangles are recognised as degenerate and the bounds are exact.
        const double ringRadius = pole ? 0.0 : std::sin(theta);
        const double y = i == 0 ? -1.0 : i == stacks ? 1.0 : -std::cos(theta);
        for (int j = 0; j <= slices; ++j) {
            // A pole vertex sits in the middle of its slice so that its triangle's texture is symmetric.
            const double u = pole ? (j + 0.5) / slices : static_cast<double>(j) / slices;
            const glm::vec3 normal =
                aroundY(kTwoPi * u) * static_cast<float>(ringRadius) + glm::vec3{0.0f, static_cast<float>(y), 0.0f};
            mesh.vertices.push_back(
                {normal * radius, normal, {static_cast<float>(u), static_cast<float>(i) / static_cast<float>(stacks)}});
        }
    }
    addGridTriangles(mesh, 0, stacks, slices);
    generateTangentsIfMissing(mesh);
    return mesh;
}

Mesh makeCone(float radius, float height, int slices)
{
    ML_ASSERT(radius > 0.0f && height > 0.0f && slices >= 3);
    Mesh mesh;
    mesh.name = "cone r=" + formatNumber(radius) + " h=" + formatNumber(height);
    const float top = 0.5f * height;
    const float bottom = -0.5f * height;
    // The side's outward normal: the gradient of (distance from the axis − radius at that
    // height), i.e. radial · height + up · radius, normalised.
    const auto sideNormal = [&](double phi) {
        return glm::normalize(aroundY(phi) * height + glm::vec3{0.0f, radius, 0.0f});
    };
    const std::uint32_t base = vertexIndex(mesh);
    for (int j = 0; j <= slices; ++j) {
        const double phi = sliceAngle(j, slices);
        mesh.vertices.push_back({aroundY(phi) * radius + glm::vec3{0.0f, bottom, 0.0f},
                                 sideNormal(phi),
                                 {static_cast<float>(j) / static_cast<float>(slices), 0.0f}});
    }
    // One apex vertex per slice, with the normal of the slice's middle: a single shared apex
    // would need one normal for every direction at once.
    const std::uint32_t apex = vertexIndex(mesh);
    for (int j = 0; j < slices; ++j) {
        const double phi = sliceAngle(j + 0.5, slices);
        mesh.vertices.push_back(
            {{0.0f, top, 0.0f}, sideNormal(phi), {(static_cast<float>(j) + 0.5f) / static_cast<float>(slices), 1.0f}});
    }
    for (int j = 0; j < slices; ++j) {
        const auto offset = static_cast<std::uint32_t>(j);
        addTriangle(mesh, base + offset, base + offset + 1, apex + offset);
    }
    addDisc(mesh, radius, bottom, false, slices);
    generateTangentsIfMissing(mesh);
    return mesh;
}

Mesh makeCylinder(float radius, float height, int slices)
{
    ML_ASSERT(radius > 0.0f && height > 0.0f && slices >= 3);
    Mesh mesh;
    mesh.name = "cylinder r=" + formatNumber(radius) + " h=" + formatNumber(height);
    const float half = 0.5f * height;
    for (int row = 0; row < 2; ++row) {
        const float y = row == 0 ? -half : half;
        for (int j = 0; j <= slices; ++j) {
            const glm::vec3 normal = aroundY(sliceAngle(j, slices));
            mesh.vertices.push_back({normal * radius + glm::vec3{0.0f, y, 0.0f},
                                     normal,
                                     {static_cast<float>(j) / static_cast<float>(slices), static_cast<float>(row)}});
        }
    }
    addGridTriangles(mesh, 0, 1, slices);
    addDisc(mesh, radius, half, true, slices);
    addDisc(mesh, radius, -half, false, slices);
    generateTangentsIfMissing(mesh);
    return mesh;
}

Mesh makeTorus(float radius, float tube, int rings, int sides)
{
    ML_ASSERT(radius > 0.0f && tube > 0.0f && rings >= 3 && sides >= 3);
    Mesh mesh;
    mesh.name = "torus r=" + formatNumber(radius) + " tube=" + formatNumber(tube);
    // Rows follow the tube (v), columns the ring (u): at ψ = 0 the tube's outside faces away
    // from the axis and ψ grows upwards, so (u, v, N) is right-handed.
    for (int i = 0; i <= sides; ++i) {
        const double psi = kTwoPi * i / sides;
        const auto cosPsi = static_cast<float>(std::cos(psi));
        const auto sinPsi = static_cast<float>(std::sin(psi));
        for (int j = 0; j <= rings; ++j) {
            const glm::vec3 around = aroundY(sliceAngle(j, rings));
            const glm::vec3 normal = around * cosPsi + glm::vec3{0.0f, sinPsi, 0.0f};
            mesh.vertices.push_back({around * radius + normal * tube,
                                     normal,
                                     {static_cast<float>(j) / static_cast<float>(rings),
                                      static_cast<float>(i) / static_cast<float>(sides)}});
        }
    }
    addGridTriangles(mesh, 0, sides, rings);
    generateTangentsIfMissing(mesh);
    return mesh;
}

namespace {

// Position bits as a key; +0.0f folds −0 into +0 so that equal positions share a key.
struct PositionKey {
    float x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    std::size_t operator()(const PositionKey& key) const
    {
        std::uint32_t bits[3];
        std::memcpy(bits, &key, sizeof bits);
        std::size_t hash = 0;
        for (std::uint32_t b : bits)
            hash = hash * 0x9E3779B97F4A7C15ull + b;
        return hash;
    }
};

// Smooth normals for the vertices with `replace[i]` set: the sum of the (area-weighted)
// normals of every triangle touching a vertex at the same position. Shared by position
// value, not by vertex, so seams where a file repeats a position (texture seams, patch
// borders of the teapot) are shaded smoothly too.
void smoothNormals(Mesh& mesh, const std::vector<bool>& replace)
{
    std::unordered_map<PositionKey, std::size_t, PositionKeyHash> groupOf;
    std::vector<std::size_t> group(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::vec3 p = mesh.vertices[i].position + 0.0f;
        group[i] = groupOf.try_emplace(PositionKey{p.x, p.y, p.z}, groupOf.size()).first->second;
    }
    // Double precision so large, far-from-origin meshes neither overflow nor lose small faces.
    std::vector<glm::dvec3> sum(groupOf.size(), glm::dvec3{0.0});
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a{mesh.vertices[mesh.indices[t]].position};
        const glm::dvec3 b{mesh.vertices[mesh.indices[t + 1]].position};
        const glm::dvec3 c{mesh.vertices[mesh.indices[t + 2]].position};
        // The cross product's length is twice the area: that is the weighting.
        const glm::dvec3 faceNormal = glm::cross(b - a, c - a);
        for (std::size_t k = 0; k < 3; ++k)
            sum[group[mesh.indices[t + k]]] += faceNormal;
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (!replace[i])
            continue;
        const glm::dvec3& n = sum[group[i]];
        const double length = glm::length(n);
        // A vertex on no face (or only on faces that cancel out) still needs a unit normal.
        mesh.vertices[i].normal =
            length > 0.0 && std::isfinite(length) ? glm::vec3{n / length} : glm::vec3{0.0f, 1.0f, 0.0f};
    }
}

}  // namespace

// Twice the triangle's area is |e1 × e2|; a triangle is degenerate when that is zero
// relative to its edges (the sine of its angle at a), which would make its normal NaN.
bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    const glm::dvec3 e1 = glm::dvec3{b} - glm::dvec3{a};
    const glm::dvec3 e2 = glm::dvec3{c} - glm::dvec3{a};
    const double crossLength = glm::length(glm::cross(e1, e2));
    return !(crossLength > 1e-12 * glm::length(e1) * glm::length(e2));
}

void computeSmoothNormals(Mesh& mesh) { smoothNormals(mesh, std::vector<bool>(mesh.vertices.size(), true)); }

void computeSmoothNormals(Mesh& mesh, const std::vector<bool>& replace)
{
    ML_ASSERT(replace.size() == mesh.vertices.size());
    smoothNormals(mesh, replace);
}

}  // namespace manylights
