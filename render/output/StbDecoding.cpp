#include "render/output/StbDecoding.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>

// Debian's libstb ships stb_image compiled (-lstb): no STB_IMAGE_IMPLEMENTATION here.
#include <stb/stb_image.h>

#include "core/Error.h"

namespace manylights {

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& problem) { throw Error(name + ": " + problem); }

// The file's bytes as stb_image's callbacks, noting whether the decoder asked for bytes past
// their end. stb_image reads in two ways: it refills its own 128-byte buffer (a short answer
// is normal at the end of the file; an empty one means it needed a byte that is not there),
// and it copies a run of bytes straight into the caller's memory (stbi__getn), where any
// short answer means bytes are missing. The first read is always a refill, which tells the
// buffer's address.
class OverrunReader {
public:
    explicit OverrunReader(std::span<const unsigned char> bytes) : bytes_(bytes) {}

    bool overran() const { return overran_; }

    static int read(void* user, char* data, int size)
    {
        auto& reader = *static_cast<OverrunReader*>(user);
        if (reader.refillBuffer_ == nullptr)
            reader.refillBuffer_ = data;
        const std::size_t wanted = static_cast<std::size_t>(std::max(size, 0));
        const std::size_t given = std::min(wanted, reader.bytes_.size() - reader.position_);
        const bool isRefill = data == reader.refillBuffer_;
        if (wanted > 0 && (given == 0 || (!isRefill && given < wanted)))
            reader.overran_ = true;
        if (given > 0)  // an empty file's data() may be null, which memcpy may not be given
            std::memcpy(data, reader.bytes_.data() + reader.position_, given);
        reader.position_ += given;
        return static_cast<int>(given);
    }
    static void skip(void* user, int count)
    {
        auto& reader = *static_cast<OverrunReader*>(user);
        const std::size_t wanted = static_cast<std::size_t>(std::max(count, 0));
        if (wanted > reader.bytes_.size() - reader.position_)
            reader.overran_ = true;
        reader.position_ += std::min(wanted, reader.bytes_.size() - reader.position_);
    }
    static int atEnd(void* user)
    {
        const auto& reader = *static_cast<const OverrunReader*>(user);
        return reader.position_ >= reader.bytes_.size() ? 1 : 0;
    }

private:
    std::span<const unsigned char> bytes_;
    std::size_t position_ = 0;
    const char* refillBuffer_ = nullptr;
    bool overran_ = false;
};

constexpr stbi_io_callbacks kOverrunCallbacks{&OverrunReader::read, &OverrunReader::skip, &OverrunReader::atEnd};

constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t bigEndian32(const unsigned char* bytes)
{
    return (std::uint32_t(bytes[0]) << 24) | (std::uint32_t(bytes[1]) << 16) | (std::uint32_t(bytes[2]) << 8) |
           std::uint32_t(bytes[3]);
}

// Whether a PNG's chunks (length, type, data, checksum each) run whole from the signature
// to a complete IEND chunk. stb_image stops reading at IEND's type, so a file cut inside the
// chunk's checksum, or with IEND missing where nothing else reads past the end, needs this.
// Bytes after IEND are ignored, as libpng ignores them.
bool pngEndsWhole(std::span<const unsigned char> bytes)
{
    std::size_t position = kPngSignature.size();
    while (bytes.size() - position >= 8) {
        const std::uint64_t length = bigEndian32(bytes.data() + position);
        const bool isEnd = std::memcmp(bytes.data() + position + 4, "IEND", 4) == 0;
        const std::uint64_t chunkEnd = position + 12 + length;  // length, type, data, checksum
        if (chunkEnd > bytes.size())
            return false;
        if (isEnd)
            return true;
        position = static_cast<std::size_t>(chunkEnd);
    }
    return false;
}

bool isPng(std::span<const unsigned char> bytes)
{
    return bytes.size() >= kPngSignature.size() &&
           std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin());
}

enum class DataEnd { Whole, Truncated, Broken };

// Where a Radiance file's pixels begin: after the header's lines, the empty line that ends
// them and the resolution line (stb_image's reading of the header); 0 if the file ends first.
std::size_t radianceDataStart(std::span<const unsigned char> bytes)
{
    std::size_t position = 0;
    bool headerEnded = false;
    while (position < bytes.size()) {
        const auto lineEnd = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(position), bytes.end(), '\n');
        if (lineEnd == bytes.end())
            return 0;
        const std::size_t next = static_cast<std::size_t>(lineEnd - bytes.begin()) + 1;
        if (headerEnded)
            return next;  // the resolution line
        headerEnded = next == position + 1;
        position = next;
    }
    return 0;
}

// Whether a Radiance file holds all its scan lines, following stb_image's decoder: widths
// below 8 or from 32768 are stored flat (4 bytes a texel); otherwise each scan line is
// 2, 2, its width in two bytes, then its four channels run-length encoded (a count above 128
// repeats one byte count − 128 times, a count up to 128 is followed by that many bytes), and
// a scan line without that start begins the rest of the image stored flat. stb_image cannot
// be asked: it reads past the end as zeros, and a count of 0 (a cut file gives endless ones)
// makes it loop for ever, so a count of 0, or a run past the scan line's end, is Broken.
DataEnd radianceDataEnd(std::span<const unsigned char> bytes, int width, int height)
{
    std::size_t position = radianceDataStart(bytes);
    if (position == 0)
        return DataEnd::Truncated;
    const auto has = [&](std::uint64_t count) { return position + count <= bytes.size(); };
    const std::uint64_t flatBytes = std::uint64_t(width) * std::uint64_t(height) * 4;
    if (width < 8 || width >= 32768)
        return has(flatBytes) ? DataEnd::Whole : DataEnd::Truncated;
    for (int line = 0; line < height; ++line) {
        if (!has(4))
            return DataEnd::Truncated;
        const unsigned char* start = bytes.data() + position;
        if (start[0] != 2 || start[1] != 2 || (start[2] & 0x80) != 0)
            return has(flatBytes) ? DataEnd::Whole : DataEnd::Truncated;
        if (((start[2] << 8) | start[3]) != width)
            return DataEnd::Broken;
        position += 4;
        for (int channel = 0; channel < 4; ++channel)
            for (int texel = 0; texel < width;) {
                if (!has(1))
                    return DataEnd::Truncated;
                const int count = bytes[position++];
                const bool isRun = count > 128;
                const int length = isRun ? count - 128 : count;
                if (length == 0 || length > width - texel)
                    return DataEnd::Broken;
                const int dataBytes = isRun ? 1 : length;
                if (!has(static_cast<std::uint64_t>(dataBytes)))
                    return DataEnd::Truncated;
                position += static_cast<std::size_t>(dataBytes);
                texel += length;
            }
    }
    return DataEnd::Whole;
}

}  // namespace

void StbImageFree::operator()(void* pixels) const { stbi_image_free(pixels); }

StbImage decodeWithStb(const std::string& name, std::span<const unsigned char> bytes, const std::string& kind,
                       StbSamples samples, int components, const StbHeaderCheck& checkHeader)
{
    // stb_image takes an int length: anything larger is no image we would accept anyway.
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        fail(name, kind + " file too large");
    int width = 0;
    int height = 0;
    int channels = 0;
    // The header first: an absurd size is refused before anything is allocated for it.
    {
        OverrunReader header(bytes);
        const bool known = stbi_info_from_callbacks(&kOverrunCallbacks, &header, &width, &height, &channels);
        if (header.overran())
            fail(name, "truncated " + kind + ": the file ends inside its header");
        if (!known)
            fail(name, "not a " + kind + " stb_image can read (" + stbi_failure_reason() + ")");
    }
    checkHeader(width, height);
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (isPng(bytes) && !pngEndsWhole(bytes))
        fail(name, "truncated " + kind + ": the file ends before the PNG's end chunk (IEND)");
    if (stbi_is_hdr_from_memory(bytes.data(), static_cast<int>(bytes.size()))) {
        const DataEnd end = radianceDataEnd(bytes, width, height);
        if (end == DataEnd::Truncated)
            fail(name, "truncated " + kind + ": the file ends before its " + size + " texels do");
        if (end == DataEnd::Broken)
            fail(name, "broken " + kind + " (bad run-length data: a run of 0 texels, or past its scan line's end)");
    }
    OverrunReader data(bytes);
    StbImage image;
    image.pixels.reset(samples == StbSamples::Floats
                           ? static_cast<void*>(stbi_loadf_from_callbacks(&kOverrunCallbacks, &data, &width, &height,
                                                                          &channels, components))
                           : static_cast<void*>(stbi_load_from_callbacks(&kOverrunCallbacks, &data, &width, &height,
                                                                         &channels, components)));
    if (data.overran())
        fail(name, "truncated " + kind + ": the file ends before its " + size + " texels do");
    if (!image.pixels)
        fail(name, "broken " + kind + " (" + stbi_failure_reason() + ")");
    image.width = width;
    image.height = height;
    return image;
}

}  // namespace manylights
