#include "scene/Meshes.h"
#include "scene/ObjLoader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"

namespace manylights {
namespace {

Bounds boundsOf(const Mesh& mesh)
{
    Bounds bounds;
    for (const Vertex& vertex : mesh.vertices)
        bounds.extend(vertex.position);
    return bounds;
}

// Signed volume by the divergence theorem: positive for a closed mesh wound counter-clockwise
// seen from outside, so it checks the winding of the whole surface at once.
double signedVolume(const Mesh& mesh)
{
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::dvec3 a{mesh.vertices[mesh.indices[t]].position};
        const glm::dvec3 b{mesh.vertices[mesh.indices[t + 1]].position};
        const glm::dvec3 c{mesh.vertices[mesh.indices[t + 2]].position};
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

// What every mesh must satisfy: indices in range, finite data, unit normals, and each
// triangle's winding (its edges' cross product) agreeing with its vertices' normals.
void expectWellFormed(const Mesh& mesh)
{
    ASSERT_FALSE(mesh.vertices.empty());
    ASSERT_FALSE(mesh.indices.empty());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (const std::uint32_t index : mesh.indices)
        ASSERT_LT(index, mesh.vertices.size());
    for (const Vertex& vertex : mesh.vertices) {
        ASSERT_TRUE(std::isfinite(vertex.position.x) && std::isfinite(vertex.position.y) &&
                    std::isfinite(vertex.position.z));
        ASSERT_TRUE(std::isfinite(vertex.uv.x) && std::isfinite(vertex.uv.y));
        // float precision over a few trigonometric operations
        ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f) << mesh.name;
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 faceNormal = glm::cross(b.position - a.position, c.position - a.position);
        ASSERT_GT(glm::length(faceNormal), 0.0f) << mesh.name << " triangle " << t / 3 << " is degenerate";
        const glm::vec3 unitFace = glm::normalize(faceNormal);
        for (const Vertex* vertex : {&a, &b, &c})
            ASSERT_GT(glm::dot(unitFace, vertex->normal), 0.0f)
                << mesh.name << " triangle " << t / 3 << " is wound against its normals";
    }
}

// Outward: each normal points away from `inside(position)`, a point inside the solid near it.
void expectOutward(const Mesh& mesh, const std::function<glm::vec3(const glm::vec3&)>& inside)
{
    for (const Vertex& vertex : mesh.vertices)
        ASSERT_GT(glm::dot(vertex.normal, vertex.position - inside(vertex.position)), 0.0f)
            << mesh.name << " at (" << vertex.position.x << ", " << vertex.position.y << ", " << vertex.position.z
            << ")";
}

const auto kOrigin = [](const glm::vec3&) { return glm::vec3{0.0f}; };

void expectBounds(const Mesh& mesh, const glm::vec3& expectedMin, const glm::vec3& expectedMax)
{
    const Bounds bounds = boundsOf(mesh);
    // float rounding of sin/cos at exact quarter turns
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(bounds.min[axis], expectedMin[axis], 1e-5f) << mesh.name << " axis " << axis;
        EXPECT_NEAR(bounds.max[axis], expectedMax[axis], 1e-5f) << mesh.name << " axis " << axis;
    }
}

TEST(Primitives, PlaneFacesUpAndHasTheRequestedSize)
{
    const Mesh mesh = makePlane(4.0f, 2.0f);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.indices.size(), 6u);
    for (const Vertex& vertex : mesh.vertices)
        EXPECT_EQ(vertex.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    expectBounds(mesh, {-2.0f, 0.0f, -1.0f}, {2.0f, 0.0f, 1.0f});
}

TEST(Primitives, BoxHas24VerticesFlatOutwardNormalsAndTheRequestedSize)
{
    const Mesh mesh = makeBox({1.0f, 2.0f, 3.0f});
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertices.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    expectOutward(mesh, kOrigin);
    // Flat faces: each normal is an axis, and the vertex lies on that face's plane.
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 n = glm::abs(vertex.normal);
        EXPECT_FLOAT_EQ(n.x + n.y + n.z, 1.0f);
        EXPECT_FLOAT_EQ(glm::dot(vertex.normal, vertex.position), glm::dot(n, glm::vec3(0.5f, 1.0f, 1.5f)));
    }
    expectBounds(mesh, {-0.5f, -1.0f, -1.5f}, {0.5f, 1.0f, 1.5f});
    EXPECT_NEAR(signedVolume(mesh), 6.0, 1e-5);
}

TEST(Primitives, SphereNormalsAreRadialAndOutward)
{
    const float radius = 1.5f;
    const Mesh mesh = makeSphere(radius);
    expectWellFormed(mesh);
    expectOutward(mesh, kOrigin);
    for (const Vertex& vertex : mesh.vertices) {
        EXPECT_NEAR(glm::length(vertex.position), radius, 1e-5f);
        EXPECT_NEAR(glm::dot(vertex.normal, glm::normalize(vertex.position)), 1.0f, 1e-5f);
    }
    expectBounds(mesh, glm::vec3{-radius}, glm::vec3{radius});
    // A 48 × 24 tessellation holds a little less than the true ball.
    const double ball = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    EXPECT_GT(signedVolume(mesh), 0.97 * ball);
    EXPECT_LT(signedVolume(mesh), ball);
}

TEST(Primitives, SphereWithOtherTessellationIsWellFormed)
{
    const Mesh mesh = makeSphere(0.5f, 7, 3);
    expectWellFormed(mesh);
    expectOutward(mesh, kOrigin);
    EXPECT_GT(signedVolume(mesh), 0.0);
}

TEST(Primitives, ConeHasSlantedSideNormalsAndACap)
{
    const float radius = 1.0f;
    const float height = 2.0f;
    const Mesh mesh = makeCone(radius, height);
    expectWellFormed(mesh);
    expectOutward(mesh, kOrigin);
    expectBounds(mesh, {-radius, -0.5f * height, -radius}, {radius, 0.5f * height, radius});
    const glm::vec3 apex{0.0f, 0.5f * height, 0.0f};
    // The side's normal rises at atan(radius / height) and is perpendicular to the slant line.
    const float expectedNormalY = radius / std::sqrt(radius * radius + height * height);
    int sideVertices = 0;
    for (const Vertex& vertex : mesh.vertices) {
        if (vertex.normal.y <= -0.5f)
            continue;  // the cap
        ++sideVertices;
        EXPECT_NEAR(vertex.normal.y, expectedNormalY, 1e-5f);
        if (vertex.position != apex) {
            EXPECT_NEAR(glm::dot(vertex.normal, glm::normalize(apex - vertex.position)), 0.0f, 1e-5f);
        }
    }
    // One apex vertex per slice, not a single shared one.
    int apexVertices = 0;
    for (const Vertex& vertex : mesh.vertices)
        apexVertices += vertex.position == apex ? 1 : 0;
    EXPECT_EQ(apexVertices, 48);
    EXPECT_GT(sideVertices, 48);
    const double cone = std::numbers::pi * radius * radius * height / 3.0;
    EXPECT_GT(signedVolume(mesh), 0.98 * cone);
    EXPECT_LT(signedVolume(mesh), cone);
}

TEST(Primitives, CylinderHasRadialSidesAndFlatCaps)
{
    const float radius = 0.5f;
    const float height = 3.0f;
    const Mesh mesh = makeCylinder(radius, height);
    expectWellFormed(mesh);
    expectOutward(mesh, kOrigin);
    expectBounds(mesh, {-radius, -0.5f * height, -radius}, {radius, 0.5f * height, radius});
    for (const Vertex& vertex : mesh.vertices) {
        if (std::abs(vertex.normal.y) > 0.5f) {
            // Caps are flat and lie at the ends.
            EXPECT_EQ(std::abs(vertex.normal.y), 1.0f);
            EXPECT_FLOAT_EQ(vertex.position.y, vertex.normal.y * 0.5f * height);
        } else {
            // Sides point straight away from the axis.
            EXPECT_EQ(vertex.normal.y, 0.0f);
            const glm::vec3 radial = glm::normalize(glm::vec3(vertex.position.x, 0.0f, vertex.position.z));
            EXPECT_NEAR(glm::dot(vertex.normal, radial), 1.0f, 1e-5f);
        }
    }
    const double cylinder = std::numbers::pi * radius * radius * height;
    EXPECT_GT(signedVolume(mesh), 0.99 * cylinder);
    EXPECT_LT(signedVolume(mesh), cylinder);
}

TEST(Primitives, TorusLiesInXzAndPointsAwayFromItsTube)
{
    const float radius = 2.0f;
    const float tube = 0.5f;
    const Mesh mesh = makeTorus(radius, tube);
    expectWellFormed(mesh);
    // Inside the tube is the nearest point of the ring that runs through it.
    expectOutward(mesh, [&](const glm::vec3& p) { return radius * glm::normalize(glm::vec3(p.x, 0.0f, p.z)); });
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 centre = radius * glm::normalize(glm::vec3(vertex.position.x, 0.0f, vertex.position.z));
        EXPECT_NEAR(glm::distance(vertex.position, centre), tube, 1e-5f);
    }
    const float outer = radius + tube;
    expectBounds(mesh, {-outer, -tube, -outer}, {outer, tube, outer});
    const double torus = 2.0 * std::numbers::pi * std::numbers::pi * radius * tube * tube;
    EXPECT_GT(signedVolume(mesh), 0.98 * torus);
    EXPECT_LT(signedVolume(mesh), torus);
}

// --- OBJ ----------------------------------------------------------------------------------

class ObjFiles : public ::testing::Test {
protected:
    void TearDown() override
    {
        std::error_code ignored;
        for (const auto& path : written_)
            std::filesystem::remove(path, ignored);
    }

    std::filesystem::path write(const std::string& name, const std::string& text)
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        const std::filesystem::path path =
            std::filesystem::path(::testing::TempDir()) / (std::string("ml_") + info->name() + "_" + name);
        std::ofstream(path, std::ios::binary) << text;
        written_.push_back(path);
        return path;
    }

    // Loading must throw an Error whose message names the file.
    void expectError(const std::filesystem::path& path, const std::string& fragment = "")
    {
        try {
            loadObjFile(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const Error& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(path.string()), std::string::npos) << message;
            EXPECT_NE(message.find(fragment), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
        }
    }

private:
    std::vector<std::filesystem::path> written_;
};

// A unit cube around the origin, triangles counter-clockwise seen from outside, no normals.
constexpr const char* kCube = R"(# cube
v -1 -1 -1
v  1 -1 -1
v  1  1 -1
v -1  1 -1
v -1 -1  1
v  1 -1  1
v  1  1  1
v -1  1  1
f 5 6 7
f 5 7 8
f 2 1 4
f 2 4 3
f 6 2 3
f 6 3 7
f 1 5 8
f 1 8 4
f 8 7 3
f 8 3 4
f 1 2 6
f 1 6 5
)";

TEST_F(ObjFiles, CubeWithoutNormalsGetsSmoothOutwardNormals)
{
    const auto path = write("cube.obj", kCube);
    const Mesh mesh = loadObjFile(path);
    EXPECT_EQ(mesh.name, path.string());
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-5);
    // Smooth: a corner's normal leans into all three faces around it.
    for (const Vertex& vertex : mesh.vertices) {
        EXPECT_GT(glm::dot(vertex.normal, glm::normalize(vertex.position)), 0.8f);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_GT(vertex.normal[axis] * vertex.position[axis], 0.0f);
    }
}

TEST_F(ObjFiles, QuadsAreTriangulated)
{
    const auto path = write("quads.obj", R"(
v -1 -1 -1
v  1 -1 -1
v  1  1 -1
v -1  1 -1
v -1 -1  1
v  1 -1  1
v  1  1  1
v -1  1  1
f 5 6 7 8
f 2 1 4 3
f 6 2 3 7
f 1 5 8 4
f 8 7 3 4
f 1 2 6 5
)");
    const Mesh mesh = loadObjFile(path);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.indices.size(), 36u);
    EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-5);
    for (const Vertex& vertex : mesh.vertices)
        EXPECT_GT(glm::dot(vertex.normal, glm::normalize(vertex.position)), 0.5f);
}

TEST_F(ObjFiles, NormalsAndTextureCoordinatesFromTheFileAreKept)
{
    // The file's normals lean away from the face normal (+Z) on purpose: they must survive.
    const auto path = write("normals.obj", R"(
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
vt 0 0
vt 1 0
vt 0 1
vt 1 1
vn 0.6 0 0.8
vn 0 0 1
f 1/1/1 2/2/1 3/3/1
f 2/2/2 4/4/2 3/3/2
)");
    const Mesh mesh = loadObjFile(path);
    expectWellFormed(mesh);
    // Shared positions with different normals are different vertices.
    EXPECT_EQ(mesh.vertices.size(), 6u);
    EXPECT_EQ(mesh.indices.size(), 6u);
    for (int k = 0; k < 3; ++k) {
        // Normalised on loading, which moves 0.6, 0.8 by a rounding step at most.
        EXPECT_NEAR(glm::distance(mesh.vertices[mesh.indices[k]].normal, glm::vec3(0.6f, 0.0f, 0.8f)), 0.0f, 1e-6f);
        EXPECT_EQ(mesh.vertices[mesh.indices[3 + k]].normal, glm::vec3(0.0f, 0.0f, 1.0f));
        const Vertex& vertex = mesh.vertices[mesh.indices[k]];
        EXPECT_EQ(vertex.uv, glm::vec2(vertex.position.x, vertex.position.y));
    }
}

TEST_F(ObjFiles, GroupsAreMergedAndUniqueVerticesShared)
{
    const auto path = write("groups.obj", R"(
o first
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
f 1 2 3
o second
f 2 4 3
)");
    const Mesh mesh = loadObjFile(path);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.indices.size(), 6u);
    for (const Vertex& vertex : mesh.vertices)
        EXPECT_NEAR(vertex.normal.z, 1.0f, 1e-6f);
}

TEST_F(ObjFiles, ZeroAreaTrianglesAreDropped)
{
    const auto path = write("degenerate.obj", R"(
v 0 0 0
v 1 0 0
v 0 1 0
v 2 0 0
f 1 2 3
f 1 2 4
f 1 1 3
)");
    const Mesh mesh = loadObjFile(path);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.indices.size(), 3u);
    EXPECT_EQ(mesh.vertices.size(), 3u);
}

TEST_F(ObjFiles, NegativeIndicesCountFromTheEnd)
{
    const auto path = write("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
    const Mesh mesh = loadObjFile(path);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.indices.size(), 3u);
}

TEST_F(ObjFiles, StreamUsesTheDisplayName)
{
    std::istringstream stream(kCube);
    const Mesh mesh = loadObjStream(stream, "memory.obj");
    EXPECT_EQ(mesh.name, "memory.obj");
    EXPECT_EQ(mesh.indices.size(), 36u);

    std::istringstream broken("v 0 0 0\n");
    try {
        loadObjStream(broken, "memory.obj");
        ADD_FAILURE() << "no error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("memory.obj"), std::string::npos);
    }
}

TEST_F(ObjFiles, MissingFileIsAnError)
{
    expectError(std::filesystem::path(::testing::TempDir()) / "ml_no_such_file.obj", "cannot open");
}

TEST_F(ObjFiles, DirectoryIsAnError) { expectError(std::filesystem::path(::testing::TempDir()), "cannot open"); }

TEST_F(ObjFiles, IndexOutOfRangeIsAnError)
{
    expectError(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n"), "out of range");
    expectError(write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"), "before the first");
    expectError(write("normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n"), "out of range");
    expectError(write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n"), "out of range");
    expectError(write("quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 9\n"), "out of range");
}

TEST_F(ObjFiles, IndexZeroIsAnError) { expectError(write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")); }

TEST_F(ObjFiles, NonFiniteNumbersAreErrors)
{
    expectError(write("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "line 1");
    expectError(write("inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n"), "line 2");
    expectError(write("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n"), "line 3");
    expectError(write("normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 nan\nf 1//1 2//1 3//1\n"), "normal");
    expectError(write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt -inf 0\nf 1/1 2/1 3/1\n"), "texture");
    expectError(write("word.obj", "v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "zero");
    expectError(write("short.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "line 1");
}

TEST_F(ObjFiles, FileWithoutFacesIsAnError)
{
    expectError(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no faces");
    expectError(write("empty.obj", ""), "no faces");
}

TEST_F(ObjFiles, GarbageIsAnError)
{
    expectError(write("garbage.obj", "this is not an OBJ file\n\x01\x02\xff binary junk\n"));
}

TEST_F(ObjFiles, OnlyDegenerateTrianglesIsAnError)
{
    expectError(write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n"), "zero area");
}

TEST_F(ObjFiles, CommentsAfterNumbersAreAllowed)
{
    const Mesh mesh = loadObjFile(write("comment.obj", "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(mesh.indices.size(), 3u);
}

TEST(ObjAssets, LowResolutionModelsLoadClosedAndOutward)
{
    for (const char* name : {"bunny-lowres.obj", "teapot-lowres.obj"}) {
        const Mesh mesh = loadObjFile(std::filesystem::path(MANYLIGHTS_SOURCE_DIR) / "assets/models" / name);
        // Every triangle's winding agrees with the smooth normals, except where a smooth
        // normal averages over a sharp feature; those stay rare.
        int against = 0;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const Vertex& a = mesh.vertices[mesh.indices[t]];
            const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
            const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            for (const Vertex* vertex : {&a, &b, &c})
                against += glm::dot(face, vertex->normal) <= 0.0f ? 1 : 0;
        }
        EXPECT_LT(against, static_cast<int>(mesh.indices.size() / 100)) << name;
        for (const Vertex& vertex : mesh.vertices)
            ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f) << name;
        EXPECT_GT(signedVolume(mesh), 0.0) << name;
    }
}

TEST(SmoothNormals, VertexOnNoFaceGetsUp)
{
    Mesh mesh;
    mesh.vertices = {{{0, 0, 0}, {}, {}}, {{1, 0, 0}, {}, {}}, {{0, 0, -1}, {}, {}}, {{5, 5, 5}, {}, {}}};
    mesh.indices = {0, 1, 2};
    computeSmoothNormals(mesh);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(mesh.vertices[i].normal, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(mesh.vertices[3].normal, glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(SmoothNormals, AreaWeighted)
{
    // Two faces meet at vertex 0: a large one facing +Z and a small one facing +X. The
    // larger face dominates in proportion to its area.
    Mesh mesh;
    mesh.vertices = {{{0, 0, 0}, {}, {}}, {{4, 0, 0}, {}, {}}, {{0, 4, 0}, {}, {}},
                     {{0, 0, 0}, {}, {}}, {{0, 1, 0}, {}, {}}, {{0, 0, 1}, {}, {}}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    computeSmoothNormals(mesh);
    // Shared by position: both copies of the origin get the same normal.
    const glm::vec3 expected = glm::normalize(glm::vec3(1.0f, 0.0f, 16.0f));
    EXPECT_NEAR(glm::distance(mesh.vertices[0].normal, expected), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(mesh.vertices[3].normal, expected), 0.0f, 1e-6f);
    EXPECT_EQ(mesh.vertices[1].normal, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(mesh.vertices[4].normal, glm::vec3(1.0f, 0.0f, 0.0f));
}

}  // namespace
}  // namespace manylights
