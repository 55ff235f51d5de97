// Float RGB images and their files: PFM (unclamped linear floats, SPEC.md §3) and PNG.
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

// Writes to a temporary file next to `path` and renames it into place, so a failed write
// never leaves a partial image under the requested name. Throws manylights::Error.
void writePfm(const Image& image, const std::filesystem::path& path);
// 8-bit RGB PNG of round(255 · clamp(v, 0, 1)) per channel, no gamma curve.
void writePng(const Image& image, const std::filesystem::path& path);

// Reads a PFM written by writePfm (or any colour "PF" file). Throws manylights::Error.
Image readPfm(const std::filesystem::path& path);

// round(255 · clamp(v, 0, 1)): the PNG encoding of one channel.
unsigned char toByte(float value);

}  // namespace manylights
