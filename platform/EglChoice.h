// The headless context's decisions that need no EGL call (issue 40): which EGL platforms the
// client extensions allow, the note printed when rendering falls back from the device
// platform, and which device --device names (an index or a UUID). Pure functions, so that the
// unit tests check them against the strings real libraries report (glvnd's on an NVIDIA
// server, Mesa's); platform/HeadlessContext.cpp makes the EGL calls.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace manylights {

// Whether the space-separated extension list `extensions` (null: none) has `name` as a whole
// token: "EGL_EXT_device_base" is not in "EGL_EXT_device_base_foo".
bool hasExtensionToken(const char* extensions, std::string_view name);

// What the client extensions (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)) allow.
// EGL_EXT_device_base is the older name of EGL_EXT_device_enumeration and EGL_EXT_device_query
// together, and glvnd lists only that name.
struct EglPlatformChoice {
    bool canEnumerateDevices = false;  // eglQueryDevicesEXT, and displays on EGL_PLATFORM_DEVICE_EXT
    bool canQueryDevices = false;      // eglQueryDeviceStringEXT: a device's extensions and DRM file
    bool canUseSurfaceless = false;    // Mesa's surfaceless platform
    // Why devices cannot be enumerated, "" when they can: "the client extensions lack ...".
    std::string reason;
};
// `clientExtensions` null: EGL has no client extensions (no EGL_EXT_client_extensions).
EglPlatformChoice chooseEglPlatforms(const char* clientExtensions);

// The line (without "manylights: ") saying why a context was made on `platform` ("Mesa's
// surfaceless platform") rather than on an EGL device: `choice` could not enumerate devices,
// or EGL listed `deviceCount` devices and none made a context (`deviceProblems` says why).
std::string platformFallbackNote(const EglPlatformChoice& choice, std::size_t deviceCount,
                                 const std::string& deviceProblems, const std::string& platform);

// A device's UUID (EGL_EXT_device_persistent_id's EGL_DEVICE_UUID_EXT): the one nvidia-smi -L
// prints after "GPU-".
using DeviceUuid = std::array<std::uint8_t, 16>;
// The canonical form: 32 lower-case hex digits grouped 8-4-4-4-12.
std::string formatUuid(const DeviceUuid& uuid);

// --device: an EGL device by its index in eglQueryDevicesEXT's list or by its UUID (EGL's order
// need not be nvidia-smi's, the UUID is the same in both). Exactly one of the two is set.
struct DeviceSelector {
    std::optional<int> index{};
    std::optional<DeviceUuid> uuid{};
};
// Parses --device's value: a whole number, or a UUID in the canonical form, in any case,
// optionally after "GPU-" (as nvidia-smi -L prints it). Returns the problem as one line without
// the option's name (CLI11 puts it in front), or "" when `text` is one; then `selector` holds it.
std::string parseDeviceSelector(std::string_view text, DeviceSelector& selector);
// The index, or the UUID in the canonical form: as messages name the device.
std::string formatDeviceSelector(const DeviceSelector& selector);

// The index of the device `selector` names among the devices whose UUIDs are `uuids` (in
// eglQueryDevicesEXT's order; none for a device without EGL_EXT_device_persistent_id). Throws
// manylights::Error, one line naming the index or the UUID, where no device matches, and
// saying why where `choice` cannot enumerate devices.
std::size_t selectDevice(const DeviceSelector& selector, const std::vector<std::optional<DeviceUuid>>& uuids,
                         const EglPlatformChoice& choice);

// Throws manylights::Error, one line naming `index` and `count`, unless 0 <= index < count.
void checkDeviceIndex(int index, std::size_t count);

}  // namespace manylights
