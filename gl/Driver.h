// What the GL implementation in use is, where that changes what is cheap.
#pragma once

#include <string_view>

namespace manylights::gl {

// True when GL_RENDERER names a rasteriser that runs on the CPU (Mesa's llvmpipe, softpipe or
// swrast), where texture filtering and shader arithmetic cost CPU time per pixel instead of
// running in fixed-function hardware. Only render/driver/DriverProfile.cpp asks (--driver-profile auto):
// the rest of the renderer follows its DriverChoices, so that a profile can override the driver.
bool isSoftwareRenderer();
bool isSoftwareRendererName(std::string_view renderer);

// One integer the implementation reports (glGetIntegerv): a limit such as
// GL_MAX_TEXTURE_SIZE.
int queryInteger(unsigned name);

}  // namespace manylights::gl
