#include "render/output/Image.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace manylights {

Image boxDownsample(Image image, int factor)
{
    ML_ASSERT(factor >= 1 && image.width % factor == 0 && image.height % factor == 0);
    if (factor == 1)
        return image;
    Image small;
    small.width = image.width / factor;
    small.height = image.height / factor;
    small.rgb.resize(static_cast<std::size_t>(small.width) * small.height * 3);
    const auto area = static_cast<float>(factor * factor);
    for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float sum = 0.0f;
                for (int dy = 0; dy < factor; ++dy)
                    for (int dx = 0; dx < factor; ++dx)
                        sum += image.pixel(x * factor + dx, y * factor + dy)[c];
                small.pixel(x, y)[c] = sum / area;
            }
    return small;
}

unsigned char toByte(float value)
{
    // NaN would otherwise be undefined in the conversion; it shows as black.
    if (!(value > 0.0f))
        return 0;
    return static_cast<unsigned char>(std::lround(255.0f * std::min(value, 1.0f)));
}

std::string encodePfm(const Image& image)
{
    // Scale −1: little-endian floats. Rows run bottom to top.
    std::string bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1\n";
    const std::size_t rowBytes = sizeof(float) * 3 * static_cast<std::size_t>(image.width);
    for (int y = image.height - 1; y >= 0; --y)
        bytes.append(reinterpret_cast<const char*>(image.pixel(0, y)), rowBytes);
    return bytes;
}

std::string encodePng(const Image& image)
{
    std::vector<unsigned char> pixels(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), pixels.begin(), toByte);
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    // Encoding to memory cannot fail but for memory, which throws; the file is written by
    // one checked writer (core/AtomicFile.h).
    if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, pixels.data(), image.width * 3) == 0)
        throw Error("cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " PNG");
    return bytes;
}

void writePfm(const Image& image, const std::filesystem::path& path)
{
    writeFileAtomically(path, "image", encodePfm(image));
}

void writePng(const Image& image, const std::filesystem::path& path)
{
    writeFileAtomically(path, "image", encodePng(image));
}

Image readPfm(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(path.string() + ": cannot open");
    std::string magic;
    Image image;
    double scale = 0.0;
    in >> magic >> image.width >> image.height >> scale;
    in.get();  // the single whitespace character that ends the header
    if (!in || magic != "PF" || image.width <= 0 || image.height <= 0 || scale >= 0.0)
        throw Error(path.string() + ": not a little-endian colour PFM");
    image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = image.height - 1; y >= 0; --y)
        in.read(reinterpret_cast<char*>(image.pixel(0, y)),
                static_cast<std::streamsize>(sizeof(float) * 3 * image.width));
    if (!in)
        throw Error(path.string() + ": truncated PFM");
    return image;
}

}  // namespace manylights
