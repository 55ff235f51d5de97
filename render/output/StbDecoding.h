// Decoding an image file's bytes with stb_image (Debian's libstb), refusing a file that is cut
// short (issue 48). stb_image reads past the end of its data as zeros and returns an image
// for many formats (a Radiance .hdr's missing scan lines come out black, a JPEG's missing
// blocks grey) without a failure to report, so every decode here reads through callbacks that
// note when the decoder asked for a byte the file does not hold; a PNG must also end with its
// complete IEND chunk, which stb_image does not read to the end, and a Radiance file's scan
// lines are walked before stb_image decodes them (its decoder loops for ever on a run of 0
// texels, which a cut file is full of). docs/scene-format.md
// ("Image files cut short") says what is refused and why.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace manylights {

// What the decoded samples are: 8-bit values (textures) or floats (radiance maps, which
// stb_image reads from Radiance files without a curve).
enum class StbSamples { Bytes, Floats };

struct StbImageFree {
    void operator()(void* pixels) const;
};

// The pixels of a decoded image, rows top to bottom, `components` samples per texel.
struct StbImage {
    int width = 0;
    int height = 0;
    std::unique_ptr<void, StbImageFree> pixels;

    const std::uint8_t* bytes() const { return static_cast<const std::uint8_t*>(pixels.get()); }
    const float* floats() const { return static_cast<const float*>(pixels.get()); }
};

// Called with the size the header states before anything is decoded: throws
// manylights::Error to refuse it (too large, not the shape wanted).
using StbHeaderCheck = std::function<void(int width, int height)>;

// Decodes `bytes` (named `name` in the messages, a path or an embedded image's key) as
// `kind` ("texture image", "Radiance .hdr image"). Throws manylights::Error, one line
// beginning "name: ": not an image stb_image reads, refused by `checkHeader`, "truncated"
// (the data ends before the image does), or broken (stb_image's reason).
StbImage decodeWithStb(const std::string& name, std::span<const unsigned char> bytes, const std::string& kind,
                       StbSamples samples, int components, const StbHeaderCheck& checkHeader);

}  // namespace manylights
