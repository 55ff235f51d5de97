// The uniform locations of shaders/lib/locations.glsl, read as C++: the numbers the C++ code
// sets (gl::Program::set) under the names the shaders use (locations::INSTANCE_BASE_LOCATION,
// ...), so a number cannot drift between a shader and its caller.
#pragma once

namespace manylights::locations {
#include "shaders/lib/locations.glsl"
}  // namespace manylights::locations
