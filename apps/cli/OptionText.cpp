#include "apps/cli/OptionText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <regex>

#include "scene/ShadowSelection.h"

namespace manylights {

std::string parseSize(const std::string& text, ImageSize& size)
{
    // At most 6 digits each, so std::stoi cannot overflow before the range check.
    static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern))
        return "--size must look like " + formatSize(kDefaultImageSize) + ", got '" + text + "'";
    const int width = std::stoi(match[1]);
    const int height = std::stoi(match[2]);
    if (width < 1 || height < 1 || width > kMaxImageDimension || height > kMaxImageDimension)
        return "--size must be between 1x1 and " + std::to_string(kMaxImageDimension) + "x" +
               std::to_string(kMaxImageDimension) + ", got " + text;
    size = {width, height};
    return {};
}

std::string formatSize(const ImageSize& size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

std::optional<unsigned long> wholeNumberIn(const std::string& text, unsigned long low, unsigned long high)
{
    if (text.empty() || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
        return std::nullopt;
    errno = 0;
    const unsigned long value = std::strtoul(text.c_str(), nullptr, 10);
    if (errno == ERANGE || value < low || value > high)
        return std::nullopt;
    return value;
}

std::string parseShadowLights(const std::string& text, int& lights)
{
    if (text == "all") {
        lights = kAllShadowLights;
        return {};
    }
    const std::optional<unsigned long> count = wholeNumberIn(text, 0, kAllShadowLights);
    if (!count)
        return "must be all or a whole number of lights from 0 to " + std::to_string(kAllShadowLights) + ", got '" +
               text + "'";
    lights = static_cast<int>(*count);
    return {};
}

std::string parseShadowPoolMiB(const std::string& text, int& mib)
{
    const std::optional<unsigned long> value = wholeNumberIn(text, kMinShadowPoolMiB, kMaxShadowPoolMiB);
    if (!value || *value % kShadowPoolGrainMiB != 0)
        return "must be a multiple of " + std::to_string(kShadowPoolGrainMiB) + " from " +
               std::to_string(kMinShadowPoolMiB) + " to " + std::to_string(kMaxShadowPoolMiB) + " (MiB), got '" + text +
               "'";
    mib = static_cast<int>(*value);
    return {};
}

}  // namespace manylights
