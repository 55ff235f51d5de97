// The one check of every number a user types outside a scene file: command-line options of
// render, bench and view, and the viewer's script. CLI11's own checks let NaN through (every
// comparison with it is false) and print a limit of DBL_MAX with all its 309 digits; this one
// wants the whole text to be a finite number within the range and says so in one short line.
#pragma once

#include <string>
#include <string_view>

namespace manylights {

// Scene time (--time, --time-range, the viewer's `time`): beyond it float time loses the
// millisecond and animations stop moving.
inline constexpr double kMaxSceneSeconds = 1.0e6;
// Frames one command may render (a --time-range recording, the viewer's `frames`).
inline constexpr double kMaxFrameCount = 1.0e6;

// Parses `text` as a finite number in [min, max] into `value`. Returns "" when it is one, or
// the problem: "must be a number from MIN to MAX, got 'TEXT'" (limits printed with %g).
std::string checkNumber(std::string_view text, double min, double max, double& value);

// `value` printed as %g: 1e+06, 0.001, 32768.
std::string formatNumber(double value);

}  // namespace manylights
