#include "render/Image.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace manylights {

unsigned char toByte(float value)
{
    // NaN would otherwise be undefined in the conversion; it shows as black.
    if (!(value > 0.0f))
        return 0;
    return static_cast<unsigned char>(std::lround(255.0f * std::min(value, 1.0f)));
}

void writePfm(const Image& image, const std::filesystem::path& path)
{
    writeFileAtomically(path, "image", [&](const std::filesystem::path& file) {
        std::ofstream out(file, std::ios::binary);
        // Scale −1: little-endian floats. Rows run bottom to top.
        out << "PF\n" << image.width << " " << image.height << "\n-1\n";
        for (int y = image.height - 1; y >= 0; --y)
            out.write(reinterpret_cast<const char*>(image.pixel(0, y)),
                      static_cast<std::streamsize>(sizeof(float) * 3 * image.width));
        out.close();
        return static_cast<bool>(out);
    });
}

void writePng(const Image& image, const std::filesystem::path& path)
{
    std::vector<unsigned char> bytes(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(), toByte);
    writeFileAtomically(path, "image", [&](const std::filesystem::path& file) {
        return stbi_write_png(file.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3) != 0;
    });
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
        in.read(reinterpret_cast<char*>(image.pixel(0, y)), static_cast<std::streamsize>(sizeof(float) * 3 * image.width));
    if (!in)
        throw Error(path.string() + ": truncated PFM");
    return image;
}

}  // namespace manylights
