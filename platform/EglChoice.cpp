#include "platform/EglChoice.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/Error.h"

namespace manylights {

namespace {

// The canonical UUID's groups of hex digits, as RFC 4122 writes them and nvidia-smi prints them.
constexpr std::array<std::size_t, 5> kUuidGroups = {8, 4, 4, 4, 12};
constexpr std::size_t kUuidDigits = 32;
constexpr std::size_t kUuidLength = kUuidDigits + kUuidGroups.size() - 1;
constexpr std::string_view kNvidiaUuidPrefix = "GPU-";
// At most 9 decimal digits, so that an index fits an int before the range check.
constexpr std::size_t kMaxIndexDigits = 9;

bool isDecimal(std::string_view text)
{
    return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

int hexValue(char c)
{
    const int lower = std::tolower(static_cast<unsigned char>(c));
    if (lower >= '0' && lower <= '9')
        return lower - '0';
    if (lower >= 'a' && lower <= 'f')
        return lower - 'a' + 10;
    return -1;
}

bool startsWithIgnoringCase(std::string_view text, std::string_view prefix)
{
    if (text.size() < prefix.size())
        return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != std::tolower(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

// The UUID in canonical form, or none.
std::optional<DeviceUuid> parseUuid(std::string_view text)
{
    if (text.size() != kUuidLength)
        return std::nullopt;
    DeviceUuid uuid{};
    std::size_t position = 0;
    std::size_t digit = 0;
    for (std::size_t g = 0; g < kUuidGroups.size(); ++g) {
        if (g > 0 && text[position++] != '-')
            return std::nullopt;
        for (std::size_t i = 0; i < kUuidGroups[g]; ++i, ++digit) {
            const int value = hexValue(text[position++]);
            if (value < 0)
                return std::nullopt;
            uuid[digit / 2] = static_cast<std::uint8_t>(uuid[digit / 2] | (digit % 2 == 0 ? value << 4 : value));
        }
    }
    return uuid;
}

}  // namespace

bool hasExtensionToken(const char* extensions, std::string_view name)
{
    if (!extensions || name.empty())
        return false;
    const std::string_view list(extensions);
    for (std::size_t begin = 0; begin < list.size();) {
        const std::size_t end = std::min(list.find(' ', begin), list.size());
        if (list.substr(begin, end - begin) == name)
            return true;
        begin = end + 1;
    }
    return false;
}

EglPlatformChoice chooseEglPlatforms(const char* clientExtensions)
{
    EglPlatformChoice choice;
    if (!clientExtensions) {
        choice.reason = "EGL has no client extensions (EGL_EXT_client_extensions)";
        return choice;
    }
    const auto has = [clientExtensions](std::string_view name) { return hasExtensionToken(clientExtensions, name); };
    const bool deviceBase = has("EGL_EXT_device_base");
    const bool enumeration = deviceBase || has("EGL_EXT_device_enumeration");
    // eglGetPlatformDisplayEXT, which the device and surfaceless platforms both go through.
    const bool platformBase = has("EGL_EXT_platform_base");
    const bool platformDevice = has("EGL_EXT_platform_device");
    choice.canEnumerateDevices = enumeration && platformBase && platformDevice;
    choice.canQueryDevices = deviceBase || has("EGL_EXT_device_query");
    choice.canUseSurfaceless = platformBase && has("EGL_MESA_platform_surfaceless");
    std::vector<std::string> lacking;
    if (!enumeration)
        lacking.push_back("EGL_EXT_device_enumeration (or EGL_EXT_device_base)");
    if (!platformBase)
        lacking.push_back("EGL_EXT_platform_base");
    if (!platformDevice)
        lacking.push_back("EGL_EXT_platform_device");
    for (std::size_t i = 0; i < lacking.size(); ++i)
        choice.reason += (i == 0                    ? "the client extensions lack "
                          : i + 1 == lacking.size() ? " and "
                                                    : ", ") +
                         lacking[i];
    return choice;
}

std::string platformFallbackNote(const EglPlatformChoice& choice, std::size_t deviceCount,
                                 const std::string& deviceProblems, const std::string& platform)
{
    const std::string through = ": rendering through " + platform;
    if (!choice.canEnumerateDevices)
        return "EGL cannot enumerate devices (" + choice.reason + ")" + through;
    if (deviceCount == 0)
        return "EGL lists no devices" + through;
    return "no EGL device made an OpenGL 4.5 core context (" + deviceProblems + ")" + through;
}

std::string formatUuid(const DeviceUuid& uuid)
{
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    std::size_t digit = 0;
    for (std::size_t g = 0; g < kUuidGroups.size(); ++g) {
        if (g > 0)
            text += '-';
        for (std::size_t i = 0; i < kUuidGroups[g]; ++i, ++digit)
            text += kDigits[digit % 2 == 0 ? uuid[digit / 2] >> 4 : uuid[digit / 2] & 0xf];
    }
    return text;
}

std::string parseDeviceSelector(std::string_view text, DeviceSelector& selector)
{
    const std::string expected =
        "must be a device's index or UUID (manylights devices lists both), got '" + printableLine(text) + "'";
    if (isDecimal(text)) {
        if (text.size() > kMaxIndexDigits)
            return expected;
        selector = {.index = std::stoi(std::string(text)), .uuid = std::nullopt};
        return {};
    }
    if (text.size() > 1 && text[0] == '-' && isDecimal(text.substr(1)))
        return "must be a device's index (0 or more) or UUID, got " + std::string(text);
    std::string_view uuidText = text;
    if (startsWithIgnoringCase(uuidText, kNvidiaUuidPrefix))
        uuidText.remove_prefix(kNvidiaUuidPrefix.size());
    if (const std::optional<DeviceUuid> uuid = parseUuid(uuidText)) {
        selector = {.index = std::nullopt, .uuid = uuid};
        return {};
    }
    // Only hex digits and hyphens: meant as a UUID, so say what is wrong with it.
    const auto digits = static_cast<std::size_t>(
        std::count_if(uuidText.begin(), uuidText.end(), [](char c) { return hexValue(c) >= 0; }));
    if (digits == 0 || digits + std::size_t(std::count(uuidText.begin(), uuidText.end(), '-')) != uuidText.size())
        return expected;
    if (digits != kUuidDigits)
        return expected + ", which has " + std::to_string(digits) + " hex digits where a UUID has " +
               std::to_string(kUuidDigits);
    return expected + ", whose hex digits are not grouped 8-4-4-4-12";
}

std::string formatDeviceSelector(const DeviceSelector& selector)
{
    return selector.uuid ? formatUuid(*selector.uuid) : std::to_string(selector.index.value_or(0));
}

std::size_t selectDevice(const DeviceSelector& selector, const std::vector<std::optional<DeviceUuid>>& uuids,
                         const EglPlatformChoice& choice)
{
    if (!choice.canEnumerateDevices)
        throw Error("--device " + formatDeviceSelector(selector) + ": EGL cannot enumerate devices (" + choice.reason +
                    ")");
    if (!selector.uuid) {
        const int index = selector.index.value_or(0);
        checkDeviceIndex(index, uuids.size());
        return static_cast<std::size_t>(index);
    }
    for (std::size_t i = 0; i < uuids.size(); ++i)
        if (uuids[i] == selector.uuid)
            return i;
    const auto withUuid = std::count_if(uuids.begin(), uuids.end(), [](const auto& uuid) { return uuid.has_value(); });
    throw Error("--device " + formatUuid(*selector.uuid) + ": no EGL device has this UUID (" +
                std::to_string(withUuid) + " of " + std::to_string(uuids.size()) +
                " report one, through EGL_EXT_device_persistent_id; manylights devices lists them)");
}

void checkDeviceIndex(int index, std::size_t count)
{
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        throw Error("--device " + std::to_string(index) + ": no such EGL device (there " +
                    (count == 1 ? std::string("is 1") : "are " + std::to_string(count)) +
                    "; manylights devices lists them)");
}

}  // namespace manylights
