// libFuzzer target: the OBJ + MTL loader. The input is an OBJ file, optionally followed by a
// line "#MTL" and the text every `mtllib` of it reads, so one input exercises both parsers.
// Texture maps resolve into a directory that does not exist (a checked missing-file error).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "core/Error.h"
#include "scene/ObjLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::string separator = "\n#MTL\n";
    const std::size_t split = input.find(separator);
    const std::string obj = input.substr(0, split);
    const std::optional<std::string> mtl =
        split == std::string::npos ? std::nullopt : std::optional<std::string>(input.substr(split + separator.size()));
    try {
        manylights::Warnings warnings;
        manylights::loadObjModelText(
            obj, "fuzz.obj", "/nonexistent-manylights-fuzz", [&](const std::string&) { return mtl; }, warnings);
    } catch (const manylights::Error&) {
    }
    return 0;
}
