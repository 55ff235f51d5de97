// libFuzzer target: the glTF loader on arbitrary bytes (.gltf text or .glb, told apart by the
// magic), with external files refused so that nothing outside the input is read.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Error.h"
#include "scene/GltfLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::vector<unsigned char> bytes(data, data + size);
    manylights::GltfOptions options;
    options.allowExternalFiles = false;
    try {
        manylights::loadGltfMemory(bytes, "fuzz.gltf", "/nonexistent-manylights-fuzz", options);
    } catch (const manylights::Error&) {
    }
    return 0;
}
