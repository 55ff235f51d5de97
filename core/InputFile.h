// The one reader of every input file: scene files, OBJ and MTL, glTF and its buffers,
// textures. It reads regular files only (a FIFO would block for ever, /dev/zero would never
// end), refuses files over kMaxInputFileBytes before reading them, and checks every read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace manylights {

// 2 GiB − 1: stb_image and tinygltf take int and unsigned lengths; no input we accept is larger.
inline constexpr std::uintmax_t kMaxInputFileBytes = 2147483647;

// The whole file. Throws manylights::Error "PATH: cannot open WHAT: reason" (missing, not a
// regular file, larger than the limit, a read error).
std::string readInputFile(const std::filesystem::path& path, const std::string& what);
// The same as bytes, for the readers that take them (tinygltf, stb_image): no second copy.
std::vector<unsigned char> readInputBytes(const std::filesystem::path& path, const std::string& what);

// Why `path` cannot be read as an input file ("" when it is a regular file within the limit).
std::string inputFileProblem(const std::filesystem::path& path);

}  // namespace manylights
