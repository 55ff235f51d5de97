// Opaque draws go nearest first (render/scene/DrawList.cpp: DrawList::order), so a surface
// hidden behind one already drawn fails the depth test and is never shaded. Measured as a work
// count: the samples that pass the depth test in the geometry pass (GL_SAMPLES_PASSED), each of
// which runs the G-buffer fragment shader to the end. Exact, whatever the order in the file.
#include <gtest/gtest.h>

#include <string>

#include "GlContextTest.h"
#include "render/frame/GBuffer.h"
#include "render/scene/GpuScene.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

class DrawOrderTest : public GlContextTest {};

constexpr int kTargetWidth = 96;
constexpr int kTargetHeight = 64;

// Three equal boxes on the view axis, at z = zs[0], zs[1], zs[2] in the file's order, seen
// from `eyeZ` on the z axis: the nearest one hides the other two entirely.
std::string threeBoxes(const int zs[3], int eyeZ)
{
    std::string objects;
    for (int i = 0; i < 3; ++i) {
        objects += std::string(i ? "," : "") + R"({"mesh": {"primitive": "box", "size": [2, 2, 0.5]}, )" +
                   R"("transform": {"translate": [0, 0, )" + std::to_string(zs[i]) + "]}}";
    }
    return R"({"camera": {"eye": [0, 0, )" + std::to_string(eyeZ) + R"(], "look_at": [0, 0, 0], "fov_y": 40},
               "lights": [], "objects": [)" +
           objects + "]}";
}

// The samples that pass the geometry pass's depth test.
GLuint shadedSamples(const std::string& json)
{
    const Scene scene = parseScene(json, "<draw order test>", ".");
    const std::vector<Light> lights = expandLights(scene, std::nullopt);
    GpuScene gpuScene(scene, lights, resolveDriverChoices({.profile = DriverProfile::Auto}));
    gpuScene.setViewport(kTargetWidth, kTargetHeight);
    const gl::Texture2D depthStencil("depth", GL_DEPTH24_STENCIL8, kTargetWidth, kTargetHeight);
    const GBuffer gbuffer(kTargetWidth, kTargetHeight, depthStencil, kDefaultGBufferLayout);
    glViewport(0, 0, kTargetWidth, kTargetHeight);
    GLuint query = 0;
    glCreateQueries(GL_SAMPLES_PASSED, 1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    gbuffer.fill(gpuScene);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    glDeleteQueries(1, &query);
    return samples;
}

TEST_F(DrawOrderTest, HiddenSurfacesAreNotShadedWhateverTheFileOrder)
{
    const int nearFirstFromPlusZ[3] = {2, 0, -2};
    const int nearFirstFromMinusZ[3] = {-2, 0, 2};
    const int scattered[3] = {0, 2, -2};
    // Seen from +z, the file listing the boxes nearest first shades the box at z = 2 only (and
    // any of its own faces it draws before those in front of them: one box's triangles keep
    // their order); any other file order must shade exactly as much.
    const GLuint fromPlusZ = shadedSamples(threeBoxes(nearFirstFromPlusZ, 10));
    ASSERT_GT(fromPlusZ, 0u);
    EXPECT_EQ(shadedSamples(threeBoxes(nearFirstFromMinusZ, 10)), fromPlusZ);
    EXPECT_EQ(shadedSamples(threeBoxes(scattered, 10)), fromPlusZ);
    // From -z the order turns round with the camera.
    const GLuint fromMinusZ = shadedSamples(threeBoxes(nearFirstFromMinusZ, -10));
    ASSERT_GT(fromMinusZ, 0u);
    EXPECT_EQ(shadedSamples(threeBoxes(nearFirstFromPlusZ, -10)), fromMinusZ);
    EXPECT_EQ(shadedSamples(threeBoxes(scattered, -10)), fromMinusZ);
}

}  // namespace
}  // namespace manylights
