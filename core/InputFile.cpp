#include "core/InputFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/Error.h"

namespace manylights {

std::string inputFileProblem(const std::filesystem::path& path)
{
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error)
        return error.message();
    if (std::filesystem::is_directory(status))
        return "it is a directory";
    if (!std::filesystem::is_regular_file(status))
        return "not a regular file";
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
        return error.message();
    if (size > kMaxInputFileBytes)
        return std::to_string(size) + " bytes, over the limit of " + std::to_string(kMaxInputFileBytes);
    return {};
}

namespace {

template <typename Bytes>
Bytes readWhole(const std::filesystem::path& path, const std::string& what)
{
    const auto fail = [&](const std::string& reason) {
        throw Error(path.string() + ": cannot open " + what + ": " + reason);
    };
    if (const std::string problem = inputFileProblem(path); !problem.empty())
        fail(problem);
    struct Close {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    const std::unique_ptr<std::FILE, Close> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        fail(std::strerror(errno));
    Bytes bytes;
    std::error_code ignored;
    bytes.reserve(static_cast<std::size_t>(std::filesystem::file_size(path, ignored)));
    char buffer[1 << 16];
    for (std::size_t read; (read = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;) {
        bytes.insert(bytes.end(), buffer, buffer + read);
        if (bytes.size() > kMaxInputFileBytes)  // grew while being read
            fail("over the limit of " + std::to_string(kMaxInputFileBytes) + " bytes");
    }
    if (std::ferror(file.get()))
        fail(std::strerror(errno));
    return bytes;
}

}  // namespace

std::string readInputFile(const std::filesystem::path& path, const std::string& what)
{
    return readWhole<std::string>(path, what);
}

std::vector<unsigned char> readInputBytes(const std::filesystem::path& path, const std::string& what)
{
    return readWhole<std::vector<unsigned char>>(path, what);
}

}  // namespace manylights
