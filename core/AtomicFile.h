// Files that appear whole or not at all: images, statistics, CSV and plots are written to a
// temporary sibling and renamed into place, so a failed run never leaves a partial file
// under the requested name (SPEC.md §3).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace manylights {

// The temporary name beside `path` that writeFileAtomically uses.
std::filesystem::path temporarySibling(const std::filesystem::path& path);

// Calls `write` with the temporary path (it returns false on failure, leaving errno set),
// then renames the result over `path`. Throws manylights::Error "PATH: cannot write WHAT:
// reason" on failure, with the temporary removed.
void writeFileAtomically(const std::filesystem::path& path, const std::string& what,
                         const std::function<bool(const std::filesystem::path& temporary)>& write);

// writeFileAtomically for a text.
void writeTextFileAtomically(const std::filesystem::path& path, const std::string& what, const std::string& text);

}  // namespace manylights
