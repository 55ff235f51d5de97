// The lights on the GPU (render/scene/SceneLights.h): kept in Morton order of their rest positions,
// packed and uploaded once when at rest, and only the animated ones posed and uploaded again.
#include <vector>

#include <gtest/gtest.h>

#include "render/programs/Bindings.h"
#include "render/scene/SceneLights.h"
#include "scene/Animation.h"
#include "tests/gl/GlContextTest.h"

namespace manylights {
namespace {

class SceneLightsTest : public GlContextTest {};

Light pointLight(glm::vec3 position, float range)
{
    Light light;
    light.position = position;
    light.range = range;
    return light;
}

// What the shaders read: the storage buffer bind() binds.
std::vector<GpuLight> lightsOnTheGpu(const SceneLights& lights)
{
    lights.bind();
    GLint buffer = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, bindings::LIGHTS_BUFFER_BINDING, &buffer);
    std::vector<GpuLight> read(lights.count());
    glGetNamedBufferSubData(static_cast<GLuint>(buffer), 0, static_cast<GLsizeiptr>(read.size() * sizeof(GpuLight)),
                            read.data());
    return read;
}

void expectSameLights(const std::vector<GpuLight>& actual, const std::vector<GpuLight>& expected)
{
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_EQ(actual[i].positionRadius, expected[i].positionRadius) << "light " << i;
        EXPECT_EQ(actual[i].intensityExponent, expected[i].intensityExponent) << "light " << i;
    }
}

TEST_F(SceneLightsTest, LightsAreKeptInMortonOrderOfTheirRestPositions)
{
    // Drawn in an order that jumps across the box; the ranges tell them apart.
    const std::vector<Light> drawn{pointLight({10, 0, 10}, 1.0f), pointLight({0, 0, 0}, 2.0f),
                                   pointLight({10, 0, 0}, 3.0f), pointLight({0, 0, 10}, 4.0f)};
    const SceneLights lights(drawn, 0.01f, driverChoices(DriverProfile::Software));
    ASSERT_EQ(lights.count(), 4u);
    // Morton order over the box: (0,0) then x = 10 (bit 0), then z = 10 (bit 2), then both.
    EXPECT_EQ(lights.rest()[0].range, 2.0f);
    EXPECT_EQ(lights.rest()[1].range, 3.0f);
    EXPECT_EQ(lights.rest()[2].range, 4.0f);
    EXPECT_EQ(lights.rest()[3].range, 1.0f);
    expectSameLights(lightsOnTheGpu(lights), lights.packed());
}

TEST_F(SceneLightsTest, LightsAtRestAreNotPosedAgain)
{
    const std::vector<Light> drawn{pointLight({0, 0, 0}, 1.0f), pointLight({5, 0, 5}, 2.0f)};
    SceneLights lights(drawn, 0.01f, driverChoices(DriverProfile::Software));
    const auto version = lights.version();
    lights.pose(3.5);
    lights.pose(7.0);
    EXPECT_EQ(lights.version(), version) << "nothing moved, so nothing derived from the lights is stale";
    expectSameLights(lightsOnTheGpu(lights), lights.packed());
}

TEST_F(SceneLightsTest, OnlyTheAnimatedLightsMoveAndTheGpuHasTheirPose)
{
    // Many still lights with a few orbiting ones among them, far apart in the order, so that the
    // upload goes in several runs.
    std::vector<Light> drawn;
    for (int i = 0; i < 600; ++i) {
        Light light = pointLight({float(i % 30), 0.0f, float(i / 30)}, 0.5f + 0.001f * float(i));
        if (i % 97 == 0)
            light.animation = OrbitAnimation{.radius = 2.0f, .degreesPerSecond = 90.0f};
        drawn.push_back(light);
    }
    SceneLights lights(drawn, 0.01f, driverChoices(DriverProfile::Software));
    const std::vector<GpuLight> atZero = lights.packed();
    const auto version = lights.version();
    lights.pose(1.0);  // a quarter turn
    EXPECT_NE(lights.version(), version);
    int moved = 0;
    for (std::size_t i = 0; i < lights.count(); ++i) {
        const Light& rest = lights.rest()[i];
        const glm::vec3 expected = animatedPosition(rest.position, rest.animation, 1.0);
        EXPECT_EQ(glm::vec3(lights.packed()[i].positionRadius), expected) << "light " << i;
        if (rest.animation) {
            ++moved;
            EXPECT_NE(lights.packed()[i].positionRadius, atZero[i].positionRadius);
        } else {
            EXPECT_EQ(lights.packed()[i].positionRadius, atZero[i].positionRadius);
        }
    }
    EXPECT_EQ(moved, 7);
    expectSameLights(lightsOnTheGpu(lights), lights.packed());
    const auto posedVersion = lights.version();
    lights.pose(1.0);
    EXPECT_EQ(lights.version(), posedVersion) << "the same time poses nothing again";
}

}  // namespace
}  // namespace manylights
