#include "render/output/ExrFile.h"

#include <cstring>
#include <exception>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include "core/Error.h"

namespace manylights {

namespace {

// An Imf::OStream into a string, so that the file is complete in memory before anything
// is written under its name.
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("<memory>") {}
    void write(const char bytes[], int count) override
    {
        if (position_ + static_cast<std::size_t>(count) > data_.size())
            data_.resize(position_ + static_cast<std::size_t>(count));
        std::memcpy(data_.data() + position_, bytes, static_cast<std::size_t>(count));
        position_ += static_cast<std::size_t>(count);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = static_cast<std::size_t>(position); }
    std::string take() { return std::move(data_); }

private:
    std::string data_;
    std::size_t position_ = 0;
};

std::string channelName(const std::string& layer, const std::string& channel)
{
    return layer.empty() ? channel : layer + "." + channel;
}

}  // namespace

std::string encodeExr(const std::vector<ExrLayer>& layers, ExrPixels pixels)
{
    ML_ASSERT(!layers.empty());
    const int width = layers.front().image.width;
    const int height = layers.front().image.height;
    const Imf::PixelType type = pixels == ExrPixels::Float ? Imf::FLOAT : Imf::HALF;
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        // The library writes a slice as the channel's own type only: half channels come from
        // half copies of the layers (rounded to nearest by Imath::half).
        std::vector<std::vector<Imath::half>> halves;
        for (const ExrLayer& layer : layers) {
            ML_ASSERT(layer.image.width == width && layer.image.height == height);
            ML_ASSERT(!layer.channels.empty() && layer.channels.size() <= 3);
            char* base = reinterpret_cast<char*>(const_cast<float*>(layer.image.rgb.data()));
            std::size_t valueBytes = sizeof(float);
            if (type == Imf::HALF) {
                halves.emplace_back(layer.image.rgb.begin(), layer.image.rgb.end());
                base = reinterpret_cast<char*>(halves.back().data());
                valueBytes = sizeof(Imath::half);
            }
            for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                const std::string name = channelName(layer.name, layer.channels[c]);
                header.channels().insert(name, Imf::Channel(type));
                frame.insert(name, Imf::Slice(type, base + c * valueBytes, 3 * valueBytes, 3 * valueBytes * width));
            }
        }
        MemoryStream stream;
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        }
        return stream.take();
    } catch (const std::exception& error) {
        throw Error(std::string("cannot encode an EXR image: ") + error.what());
    }
}

Image readExrLayer(const std::filesystem::path& path, const std::string& layer,
                   const std::vector<std::string>& channels)
{
    try {
        Imf::InputFile file(path.string().c_str());
        const Imath::Box2i window = file.header().dataWindow();
        Image image;
        image.width = window.max.x - window.min.x + 1;
        image.height = window.max.y - window.min.y + 1;
        image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0.0f);
        Imf::FrameBuffer frame;
        constexpr std::size_t kPixelBytes = 3 * sizeof(float);
        const std::size_t rowBytes = kPixelBytes * static_cast<std::size_t>(image.width);
        for (std::size_t c = 0; c < channels.size() && c < 3; ++c) {
            const std::string name = channelName(layer, channels[c]);
            if (!file.header().channels().findChannel(name))
                throw Error(path.string() + ": no channel '" + name + "'");
            // Slices are addressed from the data window's origin.
            char* origin = reinterpret_cast<char*>(image.rgb.data() + c) -
                           static_cast<std::ptrdiff_t>(window.min.x * kPixelBytes + window.min.y * rowBytes);
            frame.insert(name, Imf::Slice(Imf::FLOAT, origin, kPixelBytes, rowBytes));
        }
        // A scan line whose offset is missing from the file's table (a file cut inside it,
        // which OpenEXR reads past by rebuilding the table) would be read as nothing.
        if (!file.isComplete())
            throw Error(path.string() + ": truncated EXR image: some of its scan lines are missing");
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& error) {
        // OpenEXR's words when a read runs past the end of the file (Imf::StdIFStream): the
        // file was cut short, which is what a user needs to hear first.
        const std::string what = error.what();
        if (what.find("Early end of file") != std::string::npos)
            throw Error(path.string() + ": truncated EXR image: the file ends before its data does (OpenEXR: " + what +
                        ")");
        throw Error(path.string() + ": cannot read the EXR image: " + what);
    }
}

std::vector<std::string> exrChannelNames(const std::filesystem::path& path)
{
    try {
        Imf::InputFile file(path.string().c_str());
        std::vector<std::string> names;
        for (auto channel = file.header().channels().begin(); channel != file.header().channels().end(); ++channel)
            names.emplace_back(channel.name());
        return names;
    } catch (const std::exception& error) {
        throw Error(path.string() + ": cannot read the EXR image: " + error.what());
    }
}

}  // namespace manylights
