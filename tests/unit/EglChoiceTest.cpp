// The headless context's EGL decisions without EGL (platform/EglChoice.h, issue 40): the
// platforms that glvnd's client extensions on an NVIDIA server and Mesa's allow, the note of a
// fallback, and --device's index or UUID.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ErrorOf.h"
#include "platform/EglChoice.h"

namespace manylights {
namespace {

using test::errorThrownBy;

// glvnd 1.6 with NVIDIA's driver on an H100 server (issue 40): device enumeration only under
// its older name, EGL_EXT_device_base.
constexpr const char* kGlvndNvidia =
    "EGL_EXT_platform_base EGL_EXT_device_base EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions "
    "EGL_KHR_debug EGL_KHR_platform_x11 EGL_EXT_platform_x11 EGL_EXT_platform_device EGL_MESA_platform_surfaceless "
    "EGL_EXT_explicit_device";
// Mesa 22.3 (Debian 12) through glvnd, on a machine without a GPU.
constexpr const char* kMesa =
    "EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query EGL_EXT_platform_base "
    "EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions EGL_KHR_debug EGL_EXT_platform_device "
    "EGL_EXT_platform_wayland EGL_KHR_platform_wayland EGL_EXT_platform_x11 EGL_KHR_platform_x11 "
    "EGL_EXT_platform_xcb EGL_MESA_platform_gbm EGL_KHR_platform_gbm EGL_MESA_platform_surfaceless";

// nvidia-smi -L's "GPU-3f2a...": the bytes of kUuidText.
constexpr const char* kUuidText = "3f2a0c4e-9b1d-4e7a-8c55-0123456789ab";
constexpr DeviceUuid kUuid = {0x3f, 0x2a, 0x0c, 0x4e, 0x9b, 0x1d, 0x4e, 0x7a,
                              0x8c, 0x55, 0x01, 0x23, 0x45, 0x67, 0x89, 0xab};

TEST(ExtensionTokens, MatchWholeNamesOnly)
{
    EXPECT_TRUE(hasExtensionToken("EGL_EXT_device_base", "EGL_EXT_device_base"));
    EXPECT_TRUE(hasExtensionToken("A EGL_EXT_device_base B", "EGL_EXT_device_base"));
    EXPECT_TRUE(hasExtensionToken("A EGL_EXT_device_base", "EGL_EXT_device_base"));
    EXPECT_TRUE(hasExtensionToken("A EGL_EXT_device_base ", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("EGL_EXT_device_base_foo", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("EGL_EXT_device_base_foo EGL_X", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("MY_EGL_EXT_device_base", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("EGL_EXT_device", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("", "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken(nullptr, "EGL_EXT_device_base"));
    EXPECT_FALSE(hasExtensionToken("A B", ""));
}

TEST(EglPlatforms, GlvndOnAnNvidiaServerEnumeratesDevicesThroughDeviceBase)
{
    const EglPlatformChoice choice = chooseEglPlatforms(kGlvndNvidia);
    EXPECT_TRUE(choice.canEnumerateDevices);
    EXPECT_TRUE(choice.canQueryDevices);
    EXPECT_TRUE(choice.canUseSurfaceless);
    EXPECT_EQ(choice.reason, "");
}

TEST(EglPlatforms, MesaEnumeratesDevices)
{
    const EglPlatformChoice choice = chooseEglPlatforms(kMesa);
    EXPECT_TRUE(choice.canEnumerateDevices);
    EXPECT_TRUE(choice.canQueryDevices);
    EXPECT_TRUE(choice.canUseSurfaceless);
    EXPECT_EQ(choice.reason, "");
}

TEST(EglPlatforms, EitherNameOfEnumerationAndQuery)
{
    const std::string platforms = "EGL_EXT_platform_base EGL_EXT_platform_device ";
    const EglPlatformChoice split = chooseEglPlatforms((platforms + "EGL_EXT_device_enumeration").c_str());
    EXPECT_TRUE(split.canEnumerateDevices);
    EXPECT_FALSE(split.canQueryDevices);
    EXPECT_TRUE(
        chooseEglPlatforms((platforms + "EGL_EXT_device_enumeration EGL_EXT_device_query").c_str()).canQueryDevices);
    EXPECT_FALSE(chooseEglPlatforms((platforms + "EGL_EXT_device_base_foo").c_str()).canEnumerateDevices);
    EXPECT_FALSE(chooseEglPlatforms((platforms + "EGL_EXT_device_base_foo").c_str()).canQueryDevices);
}

TEST(EglPlatforms, WhatIsLackingIsTheReason)
{
    const EglPlatformChoice noDevices = chooseEglPlatforms(
        "EGL_EXT_platform_base EGL_EXT_client_extensions EGL_EXT_platform_device EGL_MESA_platform_surfaceless");
    EXPECT_FALSE(noDevices.canEnumerateDevices);
    EXPECT_TRUE(noDevices.canUseSurfaceless);
    EXPECT_EQ(noDevices.reason, "the client extensions lack EGL_EXT_device_enumeration (or EGL_EXT_device_base)");

    const EglPlatformChoice noPlatform = chooseEglPlatforms("EGL_EXT_device_base EGL_EXT_platform_base");
    EXPECT_FALSE(noPlatform.canEnumerateDevices);
    EXPECT_TRUE(noPlatform.canQueryDevices);
    EXPECT_FALSE(noPlatform.canUseSurfaceless);
    EXPECT_EQ(noPlatform.reason, "the client extensions lack EGL_EXT_platform_device");

    EXPECT_EQ(chooseEglPlatforms("EGL_MESA_platform_surfaceless").reason,
              "the client extensions lack EGL_EXT_device_enumeration (or EGL_EXT_device_base), "
              "EGL_EXT_platform_base and EGL_EXT_platform_device");
    EXPECT_FALSE(chooseEglPlatforms("EGL_MESA_platform_surfaceless").canUseSurfaceless);

    const EglPlatformChoice none = chooseEglPlatforms(nullptr);
    EXPECT_FALSE(none.canEnumerateDevices);
    EXPECT_FALSE(none.canUseSurfaceless);
    EXPECT_EQ(none.reason, "EGL has no client extensions (EGL_EXT_client_extensions)");
}

TEST(EglPlatforms, FallbackNoteSaysWhyAndThroughWhat)
{
    const EglPlatformChoice noDevices =
        chooseEglPlatforms("EGL_EXT_platform_base EGL_EXT_platform_device EGL_MESA_platform_surfaceless");
    EXPECT_EQ(platformFallbackNote(noDevices, 0, "", "Mesa's surfaceless platform"),
              "EGL cannot enumerate devices (the client extensions lack EGL_EXT_device_enumeration (or "
              "EGL_EXT_device_base)): rendering through Mesa's surfaceless platform");
    const EglPlatformChoice mesa = chooseEglPlatforms(kMesa);
    EXPECT_EQ(platformFallbackNote(mesa, 0, "", "Mesa's surfaceless platform"),
              "EGL lists no devices: rendering through Mesa's surfaceless platform");
    EXPECT_EQ(platformFallbackNote(mesa, 1, "EGL device 0: eglInitialize failed", "EGL's default display"),
              "no EGL device made an OpenGL 4.5 core context (EGL device 0: eglInitialize failed): rendering "
              "through EGL's default display");
}

TEST(DeviceUuids, FormattedAsNvidiaSmiPrintsThem)
{
    EXPECT_EQ(formatUuid(kUuid), kUuidText);
    EXPECT_EQ(formatUuid(DeviceUuid{}), "00000000-0000-0000-0000-000000000000");
}

DeviceSelector parsed(const std::string& text)
{
    DeviceSelector selector;
    const std::string problem = parseDeviceSelector(text, selector);
    EXPECT_EQ(problem, "") << text;
    return selector;
}

std::string problemOf(const std::string& text)
{
    DeviceSelector selector;
    return parseDeviceSelector(text, selector);
}

TEST(DeviceSelectors, AnIndex)
{
    EXPECT_EQ(parsed("0").index, 0);
    EXPECT_EQ(parsed("3").index, 3);
    EXPECT_EQ(parsed("3").uuid, std::nullopt);
    EXPECT_EQ(parsed("999999999").index, 999999999);
    EXPECT_EQ(formatDeviceSelector(parsed("3")), "3");
}

TEST(DeviceSelectors, AUuidWithOrWithoutNvidiasPrefixInAnyCase)
{
    const std::vector<std::string> texts = {kUuidText, "GPU-" + std::string(kUuidText),
                                            "gpu-3F2A0C4E-9B1D-4E7A-8C55-0123456789AB",
                                            "Gpu-3f2a0c4e-9b1d-4e7a-8C55-0123456789ab"};
    for (const std::string& text : texts) {
        const DeviceSelector selector = parsed(text);
        EXPECT_EQ(selector.index, std::nullopt) << text;
        EXPECT_EQ(selector.uuid, kUuid) << text;
        EXPECT_EQ(formatDeviceSelector(selector), kUuidText);
    }
}

TEST(DeviceSelectors, ProblemsAreOneLineEach)
{
    EXPECT_EQ(problemOf("-1"), "must be a device's index (0 or more) or UUID, got -1");
    EXPECT_EQ(problemOf("garbage"), "must be a device's index or UUID (manylights devices lists both), got 'garbage'");
    EXPECT_EQ(problemOf(""), "must be a device's index or UUID (manylights devices lists both), got ''");
    EXPECT_EQ(problemOf("1.5"), "must be a device's index or UUID (manylights devices lists both), got '1.5'");
    EXPECT_EQ(problemOf("1234567890"),
              "must be a device's index or UUID (manylights devices lists both), got '1234567890'");
    EXPECT_EQ(problemOf("GPU-3f2a0c4e-9b1d"), "must be a device's index or UUID (manylights devices lists both), "
                                              "got 'GPU-3f2a0c4e-9b1d', which has 12 hex digits where a UUID has 32");
    EXPECT_EQ(problemOf("3f2a0c4e-9b1d-4e7a-8c55-0123456789abc"),
              "must be a device's index or UUID (manylights devices lists both), got "
              "'3f2a0c4e-9b1d-4e7a-8c55-0123456789abc', which has 33 hex digits where a UUID has 32");
    EXPECT_EQ(problemOf("3f2a0c4e9b1d4e7a8c550123456789ab"),
              "must be a device's index or UUID (manylights devices lists both), got "
              "'3f2a0c4e9b1d4e7a8c550123456789ab', whose hex digits are not grouped 8-4-4-4-12");
    EXPECT_EQ(problemOf("GPU-3f2a0c4e-9b1d-4e7a-8c55-0123456789ag"),
              "must be a device's index or UUID (manylights devices lists both), got "
              "'GPU-3f2a0c4e-9b1d-4e7a-8c55-0123456789ag'");
    EXPECT_EQ(problemOf("0\n1"), "must be a device's index or UUID (manylights devices lists both), got '0\\n1'");
}

TEST(DeviceSelectors, ChooseAmongTheDevices)
{
    const EglPlatformChoice mesa = chooseEglPlatforms(kMesa);
    const std::vector<std::optional<DeviceUuid>> uuids = {std::nullopt, kUuid};
    EXPECT_EQ(selectDevice(parsed("1"), uuids, mesa), 1u);
    EXPECT_EQ(selectDevice(parsed("GPU-" + std::string(kUuidText)), uuids, mesa), 1u);
    EXPECT_EQ(errorThrownBy([&] { selectDevice(parsed("2"), uuids, mesa); }),
              "--device 2: no such EGL device (there are 2; manylights devices lists them)");
    EXPECT_EQ(errorThrownBy([&] { selectDevice(parsed("00000000-0000-0000-0000-000000000001"), uuids, mesa); }),
              "--device 00000000-0000-0000-0000-000000000001: no EGL device has this UUID (1 of 2 report one, "
              "through EGL_EXT_device_persistent_id; manylights devices lists them)");
    EXPECT_EQ(errorThrownBy([&] { selectDevice(parsed("0"), {}, chooseEglPlatforms("EGL_EXT_platform_base")); }),
              "--device 0: EGL cannot enumerate devices (the client extensions lack EGL_EXT_device_enumeration (or "
              "EGL_EXT_device_base) and EGL_EXT_platform_device)");
}

}  // namespace
}  // namespace manylights
