// The text of the option values that render, bench and view share and that need no CLI11, GL
// or scene: --size, --shadow-lights and --shadow-pool-mib, parsed and checked into plain
// values, each returning its problem as one line. CommandSupport.h wraps them in CLI11's
// options; apart from it so that the fuzz target of the command line
// (tests/fuzz/FuzzCommandLine.cpp) builds these files alone, not the renderer behind the rest.
#pragma once

#include <optional>
#include <string>

#include "render/DefaultImageSize.h"

namespace manylights {

// Far beyond any display, and small enough that width · height · bytes per pixel stays
// within 64-bit sizes; the GL implementation's own limit is checked when rendering.
inline constexpr int kMaxImageDimension = 32768;

struct ImageSize {
    int width = 0;
    int height = 0;
};

inline constexpr ImageSize kDefaultImageSize{kDefaultImageWidth, kDefaultImageHeight};  // --size

// "WxH" with both in 1..kMaxImageDimension. Returns the problem as one line (naming --size),
// or an empty string when `text` is a size; then `size` holds it.
std::string parseSize(const std::string& text, ImageSize& size);

// "1280x720".
std::string formatSize(const ImageSize& size);

// A whole number from `low` to `high`, all of `text` in decimal digits (no sign, no spaces,
// which strtoul would take); none for anything else.
std::optional<unsigned long> wholeNumberIn(const std::string& text, unsigned long low, unsigned long high);

// "all" (kAllShadowLights) or a whole number of lights from 0 to INT_MAX. Returns the problem as
// one line, without the option's name (CLI11 puts it in front), or an empty string when `text`
// is one; then `lights` holds it.
std::string parseShadowLights(const std::string& text, int& lights);
// A multiple of kShadowPoolGrainMiB from kMinShadowPoolMiB to kMaxShadowPoolMiB, the same way.
std::string parseShadowPoolMiB(const std::string& text, int& mib);

}  // namespace manylights
