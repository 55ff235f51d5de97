// --driver-profile (issue 30): `auto` keeps the choice by GL_RENDERER, and the named profiles
// make theirs on any driver, so that llvmpipe runs the GPU's code paths (the image tests run
// them under both profiles: docs/testing.md). And the EGL devices `manylights devices` lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <epoxy/gl.h>

#include "GlContextTest.h"
#include "core/Error.h"
#include "gl/Driver.h"
#include "platform/EglChoice.h"
#include "platform/HeadlessContext.h"
#include "render/Renderer.h"
#include "render/driver/DriverProfile.h"
#include "render/programs/LightingPrograms.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

TEST(DriverProfileNames, RoundTrip)
{
    for (const DriverProfile profile : {DriverProfile::Auto, DriverProfile::Software, DriverProfile::Gpu})
        EXPECT_EQ(parseDriverProfile(driverProfileName(profile)), profile);
    EXPECT_EQ(parseDriverProfile("hardware"), std::nullopt);
    for (const PassTiming timing : {PassTiming::Wall, PassTiming::Gpu, PassTiming::Frame})
        EXPECT_EQ(parsePassTiming(passTimingName(timing)), timing);
    for (const LightingStage stage : {LightingStage::Fragment, LightingStage::Compute})
        EXPECT_EQ(parseLightingStage(lightingStageName(stage)), stage);
}

class DriverProfileTest : public GlContextTest {};

// The overrides replace the one choice each names, under either profile, and nothing else.
TEST_F(DriverProfileTest, OverridesReplaceOneChoiceEach)
{
    for (const DriverProfile profile : {DriverProfile::Software, DriverProfile::Gpu}) {
        const DriverChoices plain = resolveDriverChoices({.profile = profile});
        DriverChoices expected = plain;
        expected.passTiming = PassTiming::Frame;
        EXPECT_EQ(resolveDriverChoices({.profile = profile, .passTiming = PassTiming::Frame}), expected);
        expected = plain;
        expected.lightingStage =
            plain.lightingStage == LightingStage::Compute ? LightingStage::Fragment : LightingStage::Compute;
        EXPECT_EQ(resolveDriverChoices({.profile = profile, .lightingStage = expected.lightingStage}), expected);
    }
}

TEST_F(DriverProfileTest, AutoFollowsTheRendererAndTheOthersAreFixed)
{
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const DriverChoices automatic = resolveDriverChoices({.profile = DriverProfile::Auto});
    EXPECT_EQ(automatic.profile, gl::isSoftwareRendererName(renderer) ? DriverProfile::Software : DriverProfile::Gpu)
        << renderer;
    const DriverChoices software = resolveDriverChoices({.profile = DriverProfile::Software});
    EXPECT_EQ(software.profile, DriverProfile::Software);
    EXPECT_TRUE(software.multipliedSpecularPowers);
    EXPECT_TRUE(software.lightTexelsBeforeWindows);
    EXPECT_EQ(software.autoAnisotropy, 1);
    EXPECT_EQ(software.passTiming, PassTiming::Wall);
    EXPECT_EQ(software.lightingStage, LightingStage::Fragment);
    EXPECT_FALSE(software.branchOnLightReach);
    const DriverChoices gpu = resolveDriverChoices({.profile = DriverProfile::Gpu});
    EXPECT_EQ(gpu.profile, DriverProfile::Gpu);
    EXPECT_FALSE(gpu.multipliedSpecularPowers);
    EXPECT_FALSE(gpu.lightTexelsBeforeWindows);
    EXPECT_EQ(gpu.autoAnisotropy, kHardwareAnisotropy);
    EXPECT_EQ(gpu.passTiming, PassTiming::Gpu);
    EXPECT_EQ(gpu.lightingStage, LightingStage::Compute);
    EXPECT_TRUE(gpu.branchOnLightReach);
}

TEST_F(DriverProfileTest, RendererMakesTheProfilesChoices)
{
    const Scene scene = parseScene(R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
        "lights": [{"type": "point", "pos": [0, 1, 1], "intensity": [1, 1, 1], "range": 5}],
        "materials": {"a": {"specular": [0.5, 0.5, 0.5], "shininess": 16}},
        "objects": [{"mesh": {"primitive": "sphere", "radius": 1}, "material": "a"}]})",
                                   "<driver profile test>", ".");
    const std::vector<Light> lights = expandLights(scene);
    Renderer software(scene, lights, {.width = 32, .height = 32, .driver = {.profile = DriverProfile::Software}});
    Renderer gpu(scene, lights, {.width = 32, .height = 32, .driver = {.profile = DriverProfile::Gpu}});
    EXPECT_EQ(software.driverChoices().profile, DriverProfile::Software);
    EXPECT_EQ(gpu.driverChoices().profile, DriverProfile::Gpu);
    // Both scenes hold the one integer shininess; only llvmpipe's policy raises to it by
    // multiplications.
    EXPECT_EQ(software.gpuScene().lightingFeatures().scene.specularExponents, (SpecularExponents{16}));
    EXPECT_EQ(gpu.gpuScene().lightingFeatures().scene.specularExponents, (SpecularExponents{16}));
    EXPECT_TRUE(software.gpuScene().lightingFeatures().policy.multipliedSpecularPowers);
    EXPECT_FALSE(gpu.gpuScene().lightingFeatures().policy.multipliedSpecularPowers);
    const auto definesName = [](const gl::Defines& defines, const std::string& name) {
        return std::any_of(defines.begin(), defines.end(), [&](const auto& define) { return define.first == name; });
    };
    EXPECT_TRUE(definesName(ShaderVariant{.lighting = software.gpuScene().lightingFeatures()}.toDefines({}),
                            "SPECULAR_EXPONENTS"));
    EXPECT_FALSE(
        definesName(ShaderVariant{.lighting = gpu.gpuScene().lightingFeatures()}.toDefines({}), "SPECULAR_EXPONENTS"));
    EXPECT_TRUE(
        definesName(ShaderVariant{.lighting = gpu.gpuScene().lightingFeatures()}.toDefines({}), "BRANCH_ON_REACH"));
    // With light texels, a GPU reads the uniform windows and llvmpipe the texels.
    if (software.gpuScene().indexedLightSource() == LightSource::TexelBuffer) {
        EXPECT_EQ(software.gpuScene().walkedLightSource(), LightSource::TexelBuffer);
        EXPECT_EQ(gpu.gpuScene().walkedLightSource(), LightSource::UniformWindow);
    }
    // The driver's choices are fixed when the renderer is made.
    RendererDesc desc = gpu.desc();
    desc.driver = {.profile = DriverProfile::Software, .passTiming = PassTiming::Frame};
    gpu.apply(desc);
    EXPECT_EQ(gpu.desc().driver.profile, DriverProfile::Gpu);
    EXPECT_EQ(gpu.driverChoices().passTiming, PassTiming::Gpu);
    EXPECT_EQ(gpu.passTiming(), PassTiming::Gpu);
}

TEST(EglDevices, ListedWithTheirRendererAndIndex)
{
    const EglPlatformChoice choice = eglPlatformChoice();
    if (!choice.canEnumerateDevices)
        GTEST_SKIP() << "EGL cannot enumerate devices here: " << choice.reason;
    const std::vector<EglDeviceInfo> devices = listDevices();
    ASSERT_FALSE(devices.empty()) << "EGL enumerates devices but lists none";
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EXPECT_EQ(devices[i].index, static_cast<int>(i));
        if (devices[i].problem.empty()) {
            EXPECT_FALSE(devices[i].renderer.empty()) << i;
        }
    }
    EXPECT_THROW(HeadlessContext({.device = DeviceSelector{.index = static_cast<int>(devices.size())}}), Error);
    const HeadlessContext first({.device = DeviceSelector{.index = 0}});
    EXPECT_NE(first.description().find("via EGL device 0"), std::string::npos) << first.description();
}

// A device with EGL_EXT_device_persistent_id is found by its UUID (issue 40: EGL's order need
// not be nvidia-smi's), and a UUID that no device has is an error naming it.
TEST(EglDevices, ChosenByTheirUuid)
{
    if (!eglPlatformChoice().canEnumerateDevices)
        GTEST_SKIP() << "EGL cannot enumerate devices here: " << eglPlatformChoice().reason;
    const std::vector<EglDeviceInfo> devices = listDevices();
    // Every byte 0xee: not a UUID any driver hands out (RFC 4122's variant bits are 10xx).
    DeviceUuid absent{};
    absent.fill(0xee);
    try {
        const HeadlessContext none({.device = DeviceSelector{.uuid = absent}});
        ADD_FAILURE() << "a context on " << none.description();
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find(formatUuid(absent)), std::string::npos) << error.what();
    }
    const auto withUuid = std::find_if(devices.begin(), devices.end(), [](const EglDeviceInfo& device) {
        return device.uuid && device.problem.empty();
    });
    if (withUuid == devices.end())
        GTEST_SKIP() << "no EGL device here makes a context and has EGL_EXT_device_persistent_id";
    const HeadlessContext chosen({.device = DeviceSelector{.uuid = withUuid->uuid}});
    EXPECT_NE(chosen.description().find("via EGL device " + std::to_string(withUuid->index)), std::string::npos)
        << chosen.description();
}

}  // namespace
}  // namespace manylights
