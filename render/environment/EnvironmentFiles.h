// The environment's map as radiance (scene/Environment.h): a Radiance .hdr file (stb_image), an
// OpenEXR file (the OpenEXR library, its R, G and B channels) or the built-in studio, checked to
// be equirectangular and to hold radiance (docs/scene-format.md, "environment").
#pragma once

#include <string>

#include "scene/Environment.h"

namespace manylights {

// The height of the built-in studio map (its width twice that): its soft-edged lights need no
// more.
inline constexpr int kStudioEnvironmentHeight = 256;
// The largest map side accepted: a 16384x8192 float map already takes 1.5 GiB to hold, and is
// shown at half that (EnvironmentLight::kMaxMapWidth).
inline constexpr int kMaxEnvironmentWidth = 16384;

// The map `map` names (Environment::map: a path, or a built-in's name). Throws
// manylights::Error, one line naming the file: missing or unreadable, not a .hdr or .exr image,
// not twice as wide as high ("not equirectangular"), wider than kMaxEnvironmentWidth or than
// `maxTextureSize`, or a texel that is negative or not finite.
EnvironmentImage loadEnvironmentImage(const std::string& map, int maxTextureSize);

}  // namespace manylights
