// Files compiled into the binary by cmake/Embed.cmake: the shaders (by their path under
// shaders/, e.g. "lib/lighting.glsl") and the default scene's meshes ("assets/models/...").
#pragma once

#include <optional>
#include <string_view>

namespace manylights {

std::optional<std::string_view> embeddedFile(std::string_view name);

}  // namespace manylights
