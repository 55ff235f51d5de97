// Khronos PBR Neutral (2024) in double precision, typed from its specification
// (github.com/KhronosGroup/ToneMapping, PBR_Neutral), not from shaders/lib/display.glsl: the
// reference the display tests hold the pass to (tests/gl/DisplayPassTest.cpp, which also
// checks it against values worked by hand, and tests/image/DisplayOutputTest.cpp).
#pragma once

#include <algorithm>
#include <array>

namespace manylights::test {

// Linear RGB (≥ 0) to linear display RGB in [0, 1].
inline std::array<double, 3> pbrNeutral(std::array<double, 3> colour)
{
    const double compressionStart = 0.8 - 0.04;
    const double desaturation = 0.15;
    const double darkest = std::min({colour[0], colour[1], colour[2]});
    const double offset = darkest < 0.08 ? darkest - 6.25 * darkest * darkest : 0.04;
    for (double& c : colour)
        c -= offset;
    const double peak = std::max({colour[0], colour[1], colour[2]});
    if (peak < compressionStart)
        return colour;
    const double d = 1.0 - compressionStart;
    const double newPeak = 1.0 - d * d / (peak + d - compressionStart);
    const double g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    for (double& c : colour)
        c = (1.0 - g) * c * newPeak / peak + g * newPeak;
    return colour;
}

}  // namespace manylights::test
