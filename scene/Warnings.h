// Problems in model files that other tools forgive (an unknown material, a texture path with
// Windows separators, a one-value colour): loading goes on with a defined result and says what
// it did, one line each naming the file and line. The commands print them on stderr and count
// them in --stats (`warnings`); with --strict the first one is an error instead.
#pragma once

#include <string>
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

}  // namespace manylights
