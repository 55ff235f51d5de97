// The glTF 2.0 loader (.gltf and .glb, docs/scene-format.md): tinygltf parses the file, after
// this file has checked its JSON's nesting and schema, and scene/GltfReader.h checks every
// accessor, buffer view and image against its buffer before reading it and turns meshes,
// materials and the node hierarchy into a Model. A malformed file is an Error naming the file
// and the JSON path.
#include "scene/GltfLoader.h"
// Before the tinygltf configuration below: it includes tiny_gltf.h's declarations, and the
// second include there adds only the implementation (which has no include guard).
#include "scene/GltfReader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

// tinygltf configuration (this is the one translation unit that holds its implementation; the
// three settings below are made in scene/GltfReader.h, included first, so that every file
// that includes tinygltf sees the same declarations):
// - no stb_image / stb_image_write: images stay encoded; the render layer decodes them. Our
//   image callback keeps data: URI bytes and leaves buffer-view images to be read (after the
//   buffer view is checked) by this file.
// - no external images: an image URI is only a path, checked to exist here.
// - JSON: Debian's tiny_gltf.h includes <nlohmann/json.hpp>, the same nlohmann json the scene
//   loader uses.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

#include "core/Error.h"
#include "core/InputFile.h"
#include "scene/GltfFieldChecks.h"

namespace manylights {

namespace fs = std::filesystem;

namespace {

using detail::oneLine;

// tinygltf image callback: keeps the still-encoded bytes of data: URI images. Buffer-view
// images are left alone here: tinygltf hands them over without checking that the view lies
// inside its buffer, so GltfReader reads them itself after that check.
bool keepEncodedImage(tinygltf::Image* image, const int /*index*/, std::string* /*error*/, std::string* /*warning*/,
                      int /*width*/, int /*height*/, const unsigned char* bytes, int size, void* /*user*/)
{
    if (image->bufferView < 0 && bytes != nullptr && size > 0)
        image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// File-system callbacks that refuse every file: memory loading without external files.
bool noFileExists(const std::string&, void*) { return false; }
std::string keepPath(const std::string& path, void*) { return path; }
bool noFileRead(std::vector<unsigned char>*, std::string* error, const std::string& path, void*)
{
    if (error)
        *error += "external file '" + path + "' not allowed when loading from memory\n";
    return false;
}
bool noFileWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }
// External buffers through the one input reader (core/InputFile.h): a FIFO or a device named
// as a buffer's uri is refused, not read for ever. Every file "exists" for tinygltf, so that it
// reads the path beside the model (not the one in the current directory it tries next) and the
// reader's message names the full path ("models/Sponza.bin: cannot open a buffer of
// models/Sponza.gltf: No such file or directory"), not tinygltf's "File not found : Sponza.bin".
struct ExternalFiles {
    std::string modelName;
    std::string firstError;  // the reader's message for the first file that could not be read
};
bool anyFileExists(const std::string&, void*) { return true; }
bool readExternalFile(std::vector<unsigned char>* bytes, std::string* error, const std::string& path, void* user)
{
    auto& files = *static_cast<ExternalFiles*>(user);
    try {
        *bytes = readInputBytes(path, "a buffer of " + files.modelName);
        return true;
    } catch (const Error& e) {
        if (files.firstError.empty())
            files.firstError = e.what();
        if (error)
            *error += std::string(e.what()) + "\n";
        return false;
    }
}

bool isBinaryGltf(const std::vector<unsigned char>& bytes)
{
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

// tinygltf parses extras and extensions recursively and overflows the stack somewhere past
// 10,000 levels; no real file nests deeper than a few dozen. Checked on the text first.
constexpr int kMaxGltfJsonDepth = 512;

void checkJsonNesting(std::string_view json, const std::string& displayName)
{
    int depth = 0;
    int line = 1;
    std::size_t lineStart = 0;
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (inString) {
            if (c == '\\')
                ++i;  // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxGltfJsonDepth)
                throw Error(displayName + ":" + std::to_string(line) + ":" + std::to_string(i - lineStart + 1) +
                            ": JSON nested deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

// The JSON text of a .gltf file, or of a .glb file's first chunk (empty if it has none).
std::string_view gltfJsonText(const std::vector<unsigned char>& bytes)
{
    const char* data = reinterpret_cast<const char*>(bytes.data());
    if (!isBinaryGltf(bytes))
        return {data, bytes.size()};
    constexpr std::size_t kChunkStart = 20;  // 12-byte header, chunk length and type
    if (bytes.size() < kChunkStart)
        return {};
    std::uint32_t length = 0;
    std::memcpy(&length, data + 12, sizeof length);  // little-endian, as the format and x86
    return {data + kChunkStart, std::min<std::size_t>(length, bytes.size() - kChunkStart)};
}

}  // namespace

Model loadGltfMemory(const std::vector<unsigned char>& bytes, const std::string& displayName,
                     const fs::path& baseDirectory, const GltfOptions& options)
{
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw Error(displayName + ": the file is too large (over 4 GiB)");
    // tinygltf reads the .glb container's version without checking it; version 1 (glTF 1.0)
    // and anything newer are laid out differently.
    if (isBinaryGltf(bytes) && bytes.size() >= 8) {
        std::uint32_t version = 0;
        std::memcpy(&version, bytes.data() + 4, sizeof version);
        if (version != 2)
            throw Error(displayName + ": a .glb container of version " + std::to_string(version) +
                        "; only version 2 (glTF 2.0) is read");
    }
    checkJsonNesting(gltfJsonText(bytes), displayName);
    FileWarnings warnings(displayName);
    checkGltfFields(gltfJsonText(bytes), warnings);
    tinygltf::TinyGLTF context;
    context.SetImageLoader(&keepEncodedImage, nullptr);
    ExternalFiles externalFiles{displayName, {}};
    if (options.allowExternalFiles)
        context.SetFsCallbacks({&anyFileExists, &keepPath, &readExternalFile, &noFileWrite, &externalFiles});
    else
        context.SetFsCallbacks({&noFileExists, &keepPath, &noFileRead, &noFileWrite, nullptr});
    tinygltf::Model gltf;
    std::string error;
    std::string warning;
    const auto length = static_cast<unsigned int>(bytes.size());
    // tinygltf wants a base directory string; "" would mean the current directory.
    const std::string base = baseDirectory.empty() ? std::string(".") : baseDirectory.string();
    bool ok = false;
    try {
        ok = isBinaryGltf(bytes)
                 ? context.LoadBinaryFromMemory(&gltf, &error, &warning, bytes.data(), length, base)
                 : context.LoadASCIIFromString(&gltf, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                               length, base);
    } catch (const std::exception& e) {
        // tinygltf's JSON library may still throw on values it cannot represent.
        throw Error(oneLine(displayName + ": " + e.what()));
    }
    if (!ok || !error.empty()) {
        if (!externalFiles.firstError.empty())
            throw Error(oneLine(externalFiles.firstError));
        std::string message = error.empty() ? std::string("cannot parse the file") : error;
        message = message.substr(0, message.find('\n'));
        throw Error(oneLine(displayName + ": " + message));
    }
    return detail::GltfReader(gltf, displayName, baseDirectory, options, std::move(warnings)).read();
}

Model loadGltfFile(const fs::path& path, const GltfOptions& options)
{
    return loadGltfMemory(readInputBytes(path, "the file"), path.string(), path.parent_path(), options);
}

}  // namespace manylights
