#include "core/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <unistd.h>

#include "core/Error.h"

namespace manylights {

std::filesystem::path temporarySibling(const std::filesystem::path& path)
{
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(::getpid());
    return temporary;
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& what,
                         const std::function<bool(const std::filesystem::path& temporary)>& write)
{
    const std::filesystem::path temporary = temporarySibling(path);
    errno = 0;
    if (!write(temporary)) {
        const std::string reason = errno != 0 ? std::strerror(errno) : "write failed";
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Error(path.string() + ": cannot write " + what + ": " + reason);
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Error(path.string() + ": cannot write " + what + ": " + error.message());
    }
}

void writeTextFileAtomically(const std::filesystem::path& path, const std::string& what, const std::string& text)
{
    writeFileAtomically(path, what, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        return static_cast<bool>(out);
    });
}

}  // namespace manylights
