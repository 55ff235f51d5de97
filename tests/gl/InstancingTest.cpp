// Instanced drawing of the scene (render/scene/DrawList.cpp, shaders/lib/instances.glsl): the
// default scene's draw items collapse into a few instanced draws, and the GL really draws
// every item (a primitives-generated query counts the triangles). Work counts, so exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "GlContextTest.h"
#include "gl/Program.h"
#include "render/programs/Bindings.h"
#include "render/scene/GpuScene.h"
#include "scene/DefaultScene.h"
#include "scene/LightSets.h"

namespace manylights {
namespace {

class InstancingTest : public GlContextTest {};

std::size_t triangleCount(const Mesh& mesh, const SubMesh* sub)
{
    return (sub ? sub->indexCount : mesh.indices.size()) / 3;
}

// The triangles GL_PRIMITIVES_GENERATED counts while `draw` runs, with rasterisation off (the
// count is taken before the rasteriser). The headless context has no default framebuffer and
// a draw needs a complete one: a framebuffer without attachments is, given a default size.
template <typename Draw>
GLuint primitivesGenerated(const Draw& draw)
{
    GLuint framebuffer = 0;
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferParameteri(framebuffer, GL_FRAMEBUFFER_DEFAULT_WIDTH, 64);
    glNamedFramebufferParameteri(framebuffer, GL_FRAMEBUFFER_DEFAULT_HEIGHT, 64);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    GLuint query = 0;
    glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    draw();
    glEndQuery(GL_PRIMITIVES_GENERATED);
    glDisable(GL_RASTERIZER_DISCARD);
    GLuint primitives = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &primitives);
    glDeleteQueries(1, &query);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    return primitives;
}

TEST_F(InstancingTest, DefaultSceneIsAFewInstancedDraws)
{
    const Scene scene = makeDefaultScene();
    const std::vector<Light> lights = expandLights(scene);
    ASSERT_TRUE(scene.lightMarkerRadius.has_value());
    GpuScene gpuScene(scene, lights, resolveDriverChoices({.profile = DriverProfile::Auto}));

    // What the scene asks for: one item per object sub-mesh and per light marker. Items that
    // cannot be instanced (material maps, a vertex-shader surface of revolution) are one draw
    // each; every other item shares its draw with all items of its mesh range.
    std::size_t objectItems = 0;
    std::size_t objectTriangles = 0;
    std::size_t singleItems = 0;
    std::set<std::pair<std::size_t, std::size_t>> instancedRanges;  // (mesh, sub-mesh)
    for (const Object& object : scene.objects) {
        const Mesh& mesh = scene.meshes[object.mesh];
        const std::size_t subMeshes = std::max<std::size_t>(1, mesh.subMeshes.size());
        for (std::size_t sub = 0; sub < subMeshes; ++sub) {
            const SubMesh* subMesh = mesh.subMeshes.empty() ? nullptr : &mesh.subMeshes[sub];
            const Material& material =
                scene.materials[object.materialOverridesMesh || !subMesh || !subMesh->material ? object.material
                                                                                               : *subMesh->material];
            const bool maps = !material.diffuseMap.empty() || !material.specularMap.empty() ||
                              !material.normalMap.empty() || !material.emissiveMap.empty();
            if (maps || object.revolution)
                ++singleItems;
            else
                instancedRanges.insert({object.mesh, sub});
            ++objectItems;
            objectTriangles += triangleCount(mesh, subMesh);
        }
    }
    const std::size_t markers = lights.size();
    EXPECT_EQ(markers, 256u);  // the "at least 200 lights drawn as small spheres"
    EXPECT_EQ(gpuScene.drawItemCount(), objectItems + markers);

    // The batches cover every item exactly once, in order.
    std::size_t next = 0;
    for (const GpuScene::DrawBatch& batch : gpuScene.batches()) {
        EXPECT_EQ(batch.firstItem, next);
        EXPECT_GE(batch.itemCount, 1u);
        next += batch.itemCount;
    }
    EXPECT_EQ(next, gpuScene.drawItemCount());
    RecordProperty("draw_items", static_cast<int>(gpuScene.drawItemCount()));
    RecordProperty("draw_calls", static_cast<int>(gpuScene.batches().size()));
    // One draw per instanced mesh range, one for all the markers, one per single item.
    EXPECT_EQ(gpuScene.batches().size(), instancedRanges.size() + 1 + singleItems);
    EXPECT_LE(gpuScene.batches().size(), 20u);  // against 399 items: the point of instancing
    EXPECT_EQ(gpuScene.batches().back().itemCount, markers);

    // The GL draws every instance: every object's triangles and every marker's.
    const LightingProgram programs("geometry pass",
                                   {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                                   TechniqueVariant{.gbufferLayout = GBufferLayout::Seed});
    const auto programFor = [&](MaterialVariant maps) -> const gl::Program& {
        return programs.variant(LightingFeatures{}, LightSource::StorageBuffer, maps);
    };
    gpuScene.setViewport(64, 64);
    gpuScene.bind();
    const std::size_t markerTriangles = GpuScene::lightMarkerMesh().indices.size() / 3;
    EXPECT_EQ(primitivesGenerated([&] { gpuScene.drawObjects(programFor); }),
              objectTriangles + markers * markerTriangles);

    // Shadow casters: every object and no marker, with or without culling splitting batches.
    gl::Program depthProgram("shadow depth",
                             {{GL_VERTEX_SHADER, "shadow_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_depth.frag"}});
    const auto depthProgramFor = [&](MaterialVariant) -> const gl::Program& { return depthProgram; };
    std::size_t drawn = 0;
    EXPECT_EQ(primitivesGenerated(
                  [&] { drawn = gpuScene.drawObjectsDepthOnly(depthProgramFor, [](const Bounds&) { return true; }); }),
              objectTriangles);
    EXPECT_EQ(drawn, objectItems);
    // Every other kept item: the culled items' triangles are not drawn.
    std::size_t asked = 0;
    const GLuint halfPrimitives = primitivesGenerated([&] {
        drawn = gpuScene.drawObjectsDepthOnly(depthProgramFor, [&](const Bounds&) { return asked++ % 2 == 0; });
    });
    EXPECT_EQ(asked, objectItems);
    EXPECT_EQ(drawn, (objectItems + 1) / 2);
    EXPECT_LT(halfPrimitives, objectTriangles);
    EXPECT_GT(halfPrimitives, 0u);
}

// The light markers' instance records follow their lights at any time: the CPU poses the
// lights for them (SceneLights::posed) though the GPU poses the lights' buffer, so a marker
// left at its rest position or at an earlier time would show here. Exact: a marker's model
// is a translation to its light's position and a scale.
TEST_F(InstancingTest, LightMarkersFollowTheirMovingLights)
{
    const Scene scene = makeDefaultScene();
    GpuScene gpuScene(scene, expandLights(scene), resolveDriverChoices({.profile = DriverProfile::Auto}));
    const LightingProgram programs("geometry pass",
                                   {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                                   TechniqueVariant{.gbufferLayout = GBufferLayout::Seed});
    const auto programFor = [&](MaterialVariant maps) -> const gl::Program& {
        return programs.variant(LightingFeatures{}, LightSource::StorageBuffer, maps);
    };
    gpuScene.setViewport(64, 64);
    const auto byCoordinates = [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::vector<glm::vec3> atZero;
    for (const double t : {0.0, 2.5, 7.0}) {
        gpuScene.setTime(t);
        gpuScene.bind();
        primitivesGenerated([&] { gpuScene.drawObjects(programFor); });  // binds the instance records
        GLint buffer = 0;
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, bindings::INSTANCES_BUFFER_BINDING, &buffer);
        const GpuScene::DrawBatch markers = gpuScene.batches().back();
        std::vector<GpuInstance> records(markers.itemCount);
        glGetNamedBufferSubData(static_cast<GLuint>(buffer),
                                static_cast<GLintptr>(markers.firstItem * sizeof(GpuInstance)),
                                static_cast<GLsizeiptr>(records.size() * sizeof(GpuInstance)), records.data());
        std::vector<glm::vec3> markerPositions;
        for (const GpuInstance& record : records)
            markerPositions.emplace_back(record.model[3]);
        std::vector<glm::vec3> lightPositions;
        for (const GpuLight& light : gpuScene.packedLights())
            lightPositions.emplace_back(light.positionRadius);
        std::sort(markerPositions.begin(), markerPositions.end(), byCoordinates);
        std::sort(lightPositions.begin(), lightPositions.end(), byCoordinates);
        EXPECT_EQ(markerPositions, lightPositions) << "at t = " << t;
        if (t == 0.0)
            atZero = markerPositions;
        else
            EXPECT_NE(markerPositions, atZero) << "the default scene's lights move: at t = " << t;
    }
}

}  // namespace
}  // namespace manylights
