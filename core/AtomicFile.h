// Files that appear whole or not at all: images, statistics, CSV and plots are written to a
// temporary sibling, every write, the flush to disk and the close checked, and renamed into
// place only when all of that succeeded, so a failed run never leaves a partial file under
// the requested name and never destroys the file that was there (docs/cli.md). A command with
// several outputs stages them all and renames them together (AtomicFileSet).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace manylights {

// The temporary name beside `path`: hidden, unique to this process, and within NAME_MAX
// (255 bytes) whatever the length of the name.
std::filesystem::path temporarySibling(const std::filesystem::path& path);

// Files written together: stage() writes each to its temporary sibling, commit() renames them
// all into place. Destroyed before commit (an error, an exception), it removes its temporaries
// and every earlier file under the requested names is left as it was.
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;
    ~AtomicFileSet();

    // Writes `bytes` to the temporary of `path`. Throws manylights::Error "PATH: cannot write
    // WHAT: reason" (a short write, a full disk, a file size limit, fsync or close failing).
    void stage(const std::filesystem::path& path, const std::string& what, std::string_view bytes);
    // Renames every staged file into place. Throws manylights::Error as stage() does; the files
    // not yet renamed are removed.
    void commit();

private:
    void removeTemporaries();

    struct Staged {
        std::filesystem::path path;
        std::filesystem::path temporary;
        std::string what;
    };
    std::vector<Staged> staged_;
};

// One file, whole or not at all (an AtomicFileSet of one).
void writeFileAtomically(const std::filesystem::path& path, const std::string& what, std::string_view bytes);

// Throws manylights::Error "PATH: cannot write WHAT: reason" unless a file can be created
// beside `path` (a missing or read-only folder, a directory named `path`): commands check
// every output before the work that produces it.
void checkWritable(const std::filesystem::path& path, const std::string& what);

// Makes the folder `path` will be written in, with its parents, if it is missing (a recording's
// frames/%04d.png). Throws manylights::Error "FOLDER: cannot create folder: reason".
void createOutputFolder(const std::filesystem::path& path);

}  // namespace manylights
