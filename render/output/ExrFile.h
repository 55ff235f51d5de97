// OpenEXR files (docs/cli.md): the scene-referred colour and, as further layers of the same
// file, the G-buffer quantities (--aovs), through the OpenEXR library. Written in memory and
// then whole or not at all (core/AtomicFile.h), like every other output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/output/Image.h"

namespace manylights {

// One layer: channels named `layer.channel` (just `channel` for the unnamed main layer,
// whose R, G, B every viewer shows), taken from the first channels.size() (1 to 3) of each
// pixel of `image`.
struct ExrLayer {
    std::string name;
    std::vector<std::string> channels;
    Image image;
};

enum class ExrPixels { Half, Float };

// The bytes of a scan-line EXR with every layer (all of one size), ZIP-compressed
// (lossless). Throws manylights::Error.
std::string encodeExr(const std::vector<ExrLayer>& layers, ExrPixels pixels);

// The channels `layer.channel…` of an EXR file as an Image (missing channels of the three
// stay 0), converted to float. Throws manylights::Error naming the file when it cannot be
// read or lacks a channel.
Image readExrLayer(const std::filesystem::path& path, const std::string& layer,
                   const std::vector<std::string>& channels);

// The full channel names of an EXR file, sorted as the file stores them.
std::vector<std::string> exrChannelNames(const std::filesystem::path& path);

}  // namespace manylights
