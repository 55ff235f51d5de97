// The lights on the GPU (render/scene/SceneLights.h): kept in Morton order of their rest positions,
// packed and uploaded once, and the animated ones posed again on the GPU (shaders/pose_lights.comp),
// where they must agree with the CPU's pose (scene/Animation.h).
#include <vector>

#include <gtest/gtest.h>

#include "render/programs/Bindings.h"
#include "render/scene/SceneLights.h"
#include "scene/Animation.h"
#include "tests/gl/GlContextTest.h"

namespace manylights {
namespace {

class SceneLightsTest : public GlContextTest {};

Light scenePointLight(glm::vec3 position, float range)
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

// The GPU's pose against the CPU's: everything but the position the same bit for bit, and the
// position within the float sine's rounding. Both reduce the angle in double and take the
// sine and cosine in float; llvmpipe's and the C library's float sines differ by a few ulp
// (~2.4e-7 each), times the offset's reach (orbit radius or drift amplitude, here at most
// 3 m), plus the ulp of the sum (~2e-6 at 30 m): 1e-5 m is four times that, and a hundred
// times below what a wrong pose gives (a sign or a phase off moves a light by centimetres or more).
// Returns how many positions differ from the rest position.
int expectPosedAsOnTheCpu(const std::vector<GpuLight>& gpu, const SceneLights& lights)
{
    constexpr float kTolerance = 1e-5f;
    const std::vector<GpuLight>& cpu = lights.packed();
    EXPECT_EQ(gpu.size(), cpu.size());
    int moved = 0;
    int mismatches = 0;
    for (std::size_t i = 0; i < std::min(gpu.size(), cpu.size()) && mismatches < 10; ++i) {
        const glm::vec3 g(gpu[i].positionRadius);
        const glm::vec3 c(cpu[i].positionRadius);
        const bool close = glm::all(glm::lessThanEqual(glm::abs(g - c), glm::vec3(kTolerance)));
        const bool rest = gpu[i].positionRadius.w == cpu[i].positionRadius.w &&
                          gpu[i].intensityExponent == cpu[i].intensityExponent &&
                          gpu[i].attenuation == cpu[i].attenuation &&
                          gpu[i].spotAxisCosCutoff == cpu[i].spotAxisCosCutoff;
        EXPECT_TRUE(close) << "light " << i << ": GPU (" << g.x << ", " << g.y << ", " << g.z << "), CPU (" << c.x
                           << ", " << c.y << ", " << c.z << ")";
        EXPECT_TRUE(rest) << "light " << i << ": more than its position changed";
        mismatches += close && rest ? 0 : 1;
        moved += g != lights.rest()[i].position ? 1 : 0;
    }
    return moved;
}

TEST_F(SceneLightsTest, LightsAreKeptInMortonOrderOfTheirRestPositions)
{
    // Drawn in an order that jumps across the box; the ranges tell them apart.
    const std::vector<Light> drawn{scenePointLight({10, 0, 10}, 1.0f), scenePointLight({0, 0, 0}, 2.0f),
                                   scenePointLight({10, 0, 0}, 3.0f), scenePointLight({0, 0, 10}, 4.0f)};
    const SceneLights lights(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
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
    const std::vector<Light> drawn{scenePointLight({0, 0, 0}, 1.0f), scenePointLight({5, 0, 5}, 2.0f)};
    SceneLights lights(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    const auto version = lights.version();
    lights.pose(3.5);
    lights.pose(7.0);
    EXPECT_EQ(lights.version(), version) << "nothing moved, so nothing derived from the lights is stale";
    expectSameLights(lightsOnTheGpu(lights), lights.packed());
}

TEST_F(SceneLightsTest, OnlyTheAnimatedLightsMoveAndTheGpuHasTheirPose)
{
    // Many still lights with a few orbiting ones among them, far apart in the order.
    std::vector<Light> drawn;
    for (int i = 0; i < 600; ++i) {
        Light light = scenePointLight({float(i % 30), 0.0f, float(i / 30)}, 0.5f + 0.001f * float(i));
        if (i % 97 == 0)
            light.animation = OrbitAnimation{.radius = 2.0f, .degreesPerSecond = 90.0f};
        drawn.push_back(light);
    }
    SceneLights lights(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    const std::vector<GpuLight> atZero = lights.packed();
    expectSameLights(lightsOnTheGpu(lights), atZero);
    const auto version = lights.version();
    lights.pose(1.0);  // a quarter turn
    EXPECT_NE(lights.version(), version);
    EXPECT_TRUE(lights.posePending());
    expectSameLights(lightsOnTheGpu(lights), atZero);  // until the frame poses them
    lights.applyPose();
    EXPECT_FALSE(lights.posePending());
    int moved = 0;
    for (std::size_t i = 0; i < lights.count(); ++i) {
        const Light& rest = lights.rest()[i];
        const glm::vec3 expected = animatedPosition(rest.position, rest.animation, 1.0);
        EXPECT_EQ(glm::vec3(lights.packed()[i].positionRadius), expected) << "light " << i;
        EXPECT_EQ(lights.posedPosition(i), expected) << "light " << i;
        if (rest.animation) {
            ++moved;
            EXPECT_NE(lights.packed()[i].positionRadius, atZero[i].positionRadius);
        } else {
            EXPECT_EQ(lights.packed()[i].positionRadius, atZero[i].positionRadius);
        }
    }
    EXPECT_EQ(moved, 7);
    EXPECT_EQ(expectPosedAsOnTheCpu(lightsOnTheGpu(lights), lights), 7);
    const auto posedVersion = lights.version();
    lights.pose(1.0);
    EXPECT_EQ(lights.version(), posedVersion) << "the same time poses nothing again";
    EXPECT_FALSE(lights.posePending());
}

// The memory said in --stats (gpu_memory_bytes): the light buffer in whole windows, and a
// motion of 48 bytes for each moving light only.
TEST_F(SceneLightsTest, MemoryIsTheBufferAndTheMovingLightsMotions)
{
    std::vector<Light> drawn;
    for (int i = 0; i < 1500; ++i) {
        Light light = scenePointLight({float(i % 40), 0.0f, float(i / 40)}, 1.0f);
        if (i % 3 == 0)
            light.animation = DriftAnimation{};
        drawn.push_back(light);
    }
    const SceneLights moving(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    const std::size_t windows = (1500 + kLightsPerWindow - 1) / kLightsPerWindow;
    EXPECT_EQ(moving.memoryBytes(), windows * kLightWindowBytes + 500 * sizeof(GpuLightMotion));
    for (Light& light : drawn)
        light.animation.reset();
    const SceneLights still(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    EXPECT_EQ(still.memoryBytes(), windows * kLightWindowBytes);
}

// Every motion and setting the scene format has, at times where a float angle would be far
// off (t = 12,345.678 s: 30 degrees/s is 370,370 degrees), both ways round and with phases.
TEST_F(SceneLightsTest, TheGpuPosesEveryMotionAsTheCpuDoes)
{
    std::vector<Light> drawn;
    for (int i = 0; i < 1000; ++i) {
        Light light = scenePointLight({float(i % 40) - 20.0f, 0.5f + float(i % 3), float(i / 40) - 12.0f}, 1.0f);
        const float phase = 137.5f * float(i);
        if (i % 2 == 0)
            light.animation = OrbitAnimation{.radius = 0.5f + float(i % 5) * 0.5f,
                                             .degreesPerSecond = i % 4 == 0 ? 30.0f : -45.0f,
                                             .phaseDegrees = phase};
        else if (i % 7 != 0)
            light.animation = DriftAnimation{.amplitude = {1.0f + float(i % 3), 0.25f, 3.0f},
                                             .period = {7.0f, 5.0f + float(i % 4), 11.0f},
                                             .phaseDegrees = phase};
        drawn.push_back(light);
    }
    SceneLights lights(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    for (const double t : {0.25, 3.0, 12345.678, 0.0}) {
        lights.pose(t);
        lights.applyPose();
        const int moved = expectPosedAsOnTheCpu(lightsOnTheGpu(lights), lights);
        EXPECT_GT(moved, 800) << "at t = " << t;
    }
}

// Past 32,768 workgroups of 64 the dispatch goes on along z: the last light is posed too.
TEST_F(SceneLightsTest, TheGpuPosesLightsPastOneRowOfWorkgroups)
{
    constexpr std::size_t kLights = 32768 * 64 + 100;
    std::vector<Light> drawn(kLights, scenePointLight({0, 0, 0}, 1.0f));
    for (std::size_t i = 0; i < kLights; ++i) {
        drawn[i].position = {float(i % 2048) * 0.01f, 0.0f, float(i / 2048) * 0.01f};
        drawn[i].animation = OrbitAnimation{.radius = 0.001f * float(1 + i % 7)};
    }
    SceneLights lights(drawn, 0.01f, resolveDriverChoices({.profile = DriverProfile::Software}));
    lights.pose(2.0);
    lights.applyPose();
    EXPECT_EQ(expectPosedAsOnTheCpu(lightsOnTheGpu(lights), lights), static_cast<int>(kLights));
}

}  // namespace
}  // namespace manylights
