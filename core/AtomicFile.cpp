#include "core/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <system_error>
#include <unistd.h>

#include "core/Error.h"

namespace manylights {

namespace {

// NAME_MAX on Linux and most POSIX systems.
constexpr std::size_t kMaxNameBytes = 255;

[[noreturn]] void cannotWrite(const std::filesystem::path& path, const std::string& what, const std::string& reason)
{
    throw Error(path.string() + ": cannot write " + what + ": " + reason);
}

std::string errnoText(int error) { return error != 0 ? std::strerror(error) : "write failed"; }

// Writes all of `bytes` to `file`, then fsync and close; each checked. Returns 0 or the errno
// of the first failure (the descriptor is closed either way).
int writeWholeFile(int file, std::string_view bytes)
{
    int failure = 0;
    std::size_t written = 0;
    while (written < bytes.size() && failure == 0) {
        const ssize_t n = ::write(file, bytes.data() + written, bytes.size() - written);
        if (n > 0)
            written += static_cast<std::size_t>(n);
        else if (n < 0 && errno == EINTR)
            continue;
        else
            failure = n < 0 ? errno : ENOSPC;  // a write of 0 bytes: the device is full
    }
    if (failure == 0 && ::fsync(file) != 0 && errno != EINVAL && errno != EROFS)
        failure = errno;  // EINVAL/EROFS: a special file (/dev/null) that cannot be synced
    if (::close(file) != 0 && failure == 0)
        failure = errno;
    return failure;
}

}  // namespace

std::filesystem::path temporarySibling(const std::filesystem::path& path)
{
    std::string suffix = ".tmp";
    suffix += std::to_string(::getpid());
    std::string name = ".";
    name += path.filename().string();
    // Keep the name and its suffix within NAME_MAX: a 254-byte name is legal, its temporary
    // must be too. Two names cut to the same prefix cannot collide within one process, which
    // writes each output once.
    if (name.size() + suffix.size() > kMaxNameBytes)
        name.resize(kMaxNameBytes - suffix.size());
    return path.parent_path() / (name + suffix);
}

AtomicFileSet::~AtomicFileSet() { removeTemporaries(); }

void AtomicFileSet::removeTemporaries()
{
    for (const Staged& file : staged_) {
        std::error_code ignored;
        std::filesystem::remove(file.temporary, ignored);
    }
    staged_.clear();
}

void AtomicFileSet::stage(const std::filesystem::path& path, const std::string& what, std::string_view bytes)
{
    const std::filesystem::path temporary = temporarySibling(path);
    const int file = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (file < 0)
        cannotWrite(path, what, errnoText(errno));
    staged_.push_back({path, temporary, what});
    if (const int failure = writeWholeFile(file, bytes); failure != 0)
        cannotWrite(path, what, errnoText(failure));  // the destructor removes the temporary
}

void AtomicFileSet::commit()
{
    while (!staged_.empty()) {
        const Staged& file = staged_.front();
        std::error_code error;
        std::filesystem::rename(file.temporary, file.path, error);
        if (error) {
            const Staged failed = file;
            removeTemporaries();
            cannotWrite(failed.path, failed.what, error.message());
        }
        staged_.erase(staged_.begin());
    }
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& what, std::string_view bytes)
{
    AtomicFileSet file;
    file.stage(path, what, bytes);
    file.commit();
}

void checkWritable(const std::filesystem::path& path, const std::string& what)
{
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        cannotWrite(path, what, "is a directory");
    const std::filesystem::path temporary = temporarySibling(path);
    const int file = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (file < 0)
        cannotWrite(path, what, errnoText(errno));
    ::close(file);
    std::filesystem::remove(temporary, error);
}

void createOutputFolder(const std::filesystem::path& path)
{
    const std::filesystem::path folder = path.parent_path();
    std::error_code error;
    if (folder.empty() || std::filesystem::is_directory(folder, error))
        return;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw Error(folder.string() + ": cannot create folder: " + error.message());
}

}  // namespace manylights
