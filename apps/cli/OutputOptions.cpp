#include "apps/cli/OutputOptions.h"

#include <algorithm>

namespace manylights {

const std::vector<OutputOption>& outputOptions()
{
    // The display settings shape 8-bit pictures; the float outputs keep the linear values an
    // analysis reads (docs/display.md).
    constexpr std::string_view kLinear = ".pfm and .exr keep the linear values";
    static const std::vector<OutputOption> options{
        {"--exposure", {ImageFormat::Png}, kLinear},
        {"--tonemap", {ImageFormat::Png}, kLinear},
        {"--srgb", {ImageFormat::Png}, kLinear},
        {"--no-srgb", {ImageFormat::Png}, kLinear},
        {"--classic", {ImageFormat::Png}, kLinear},
        {"--aa", {ImageFormat::Png}, kLinear},
        {"--no-legend", {ImageFormat::Png}, "the legend is drawn into PNGs only; .pfm and .exr hold the counts"},
        {"--exr-float", {ImageFormat::Exr}, "only EXR has half and float channels to choose from"},
        {"--aovs", {ImageFormat::Exr}, "only EXR has layers"},
    };
    return options;
}

std::string_view formatExtension(ImageFormat format)
{
    switch (format) {
    case ImageFormat::Png: return ".png";
    case ImageFormat::Pfm: return ".pfm";
    case ImageFormat::Exr: return ".exr";
    }
    return "";
}

std::string outputOptionProblem(const std::function<bool(std::string_view option)>& given, ImageFormat format)
{
    for (const OutputOption& option : outputOptions()) {
        if (!given(option.name) ||
            std::find(option.formats.begin(), option.formats.end(), format) != option.formats.end())
            continue;
        std::string applies;
        for (ImageFormat each : option.formats)
            applies += (applies.empty() ? "" : " and ") + std::string(formatExtension(each));
        return std::string(option.name) + " applies to " + applies + " outputs, not " +
               std::string(formatExtension(format)) + ": " + std::string(option.reason);
    }
    return "";
}

}  // namespace manylights
