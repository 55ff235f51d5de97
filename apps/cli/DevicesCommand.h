// `manylights devices` (docs/cli.md, issue 30): the EGL devices a GPU server offers, with the
// index that --device takes.
#pragma once

namespace manylights {

// Prints one line per EGL device on stdout: index, vendor, renderer, whether it is a software
// rasteriser, and the DRM device file where there is one. Throws manylights::Error when EGL
// cannot list devices.
void printDevices();

}  // namespace manylights
