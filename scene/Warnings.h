// Problems in model files that other tools forgive (an unknown material, a texture path with
// Windows separators, a one-value colour): loading goes on with a defined result and says what
// it did, one line each naming the file and line. The commands print them on stderr and count
// them in --stats (`warnings`); with --strict the first one is an error instead.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace manylights {

class Warnings {
public:
    explicit Warnings(bool strict = false) : strict_(strict) {}

    // Records `message`; when strict, throws manylights::Error with it instead.
    void add(const std::string& message);
    const std::vector<std::string>& messages() const { return messages_; }
    bool strict() const { return strict_; }

private:
    bool strict_;
    std::vector<std::string> messages_;
};

// One file's forgiven problems, gathered by kind so that a file with ten thousand lines of
// one oddity gives one warning: "FILE: line N: what (and K more lines)" at the first line.
class FileWarnings {
public:
    explicit FileWarnings(std::string displayName) : displayName_(std::move(displayName)) {}

    void note(std::size_t lineNumber, const std::string& kind, const std::string& message);
    // A warning about the whole file (no line).
    void noteFile(const std::string& kind, const std::string& message) { note(0, kind, message); }
    // One line per kind, in the order the kinds were first noted.
    void flushInto(Warnings& warnings) const;

private:
    struct Entry {
        std::size_t lineNumber;
        std::string message;
        std::size_t count;
    };
    std::string displayName_;
    std::map<std::string, Entry> byKind_;
    std::vector<std::string> order_;
};

}  // namespace manylights
