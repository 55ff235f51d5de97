// Float RGB images and their files: PFM (unclamped linear floats, docs/cli.md) and PNG.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace manylights {

// Linear float RGB, rows top to bottom (the order people read; PFM stores them reversed).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width · height · 3

    float* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
    const float* pixel(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

// The bytes of a PFM file (little-endian floats, rows bottom to top).
std::string encodePfm(const Image& image);
// The bytes of an 8-bit RGB PNG of round(255 · clamp(v, 0, 1)) per channel, no gamma curve.
std::string encodePng(const Image& image);

// Encodes and writes whole or not at all (core/AtomicFile.h). Throws manylights::Error.
void writePfm(const Image& image, const std::filesystem::path& path);
void writePng(const Image& image, const std::filesystem::path& path);

// Reads a PFM written by writePfm (or any colour "PF" file). Throws manylights::Error.
Image readPfm(const std::filesystem::path& path);

// `image` with each `factor` x `factor` block averaged in linear light (a box filter; the
// sizes must be multiples of `factor`): supersampled frames down to their output size, in the
// box the display pass averages (shaders/display.frag), so both agree to rounding.
// A factor of 1 returns `image` as it is.
Image boxDownsample(Image image, int factor);

// round(255 · clamp(v, 0, 1)): the PNG encoding of one channel.
unsigned char toByte(float value);

}  // namespace manylights
