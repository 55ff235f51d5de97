// libFuzzer target: the scene JSON loader on arbitrary text. Any input must end in a scene or
// a manylights::Error; a crash, sanitizer report, assertion or other exception is a bug.
// Relative mesh and texture paths resolve into a directory that does not exist, so every
// file reference is a (checked) missing-file error and nothing outside the input is read.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/Error.h"
#include "scene/SceneLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        manylights::parseScene(text, "fuzz.json", "/nonexistent-manylights-fuzz");
    } catch (const manylights::Error&) {
    }
    return 0;
}
