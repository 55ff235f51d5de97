// Reading OBJ and MTL text before tinyobjloader parses it (docs/scene-format.md, "OBJ and
// MTL"): decoding it to UTF-8, checking the numbers and element indices tinyobjloader would read
// wrongly without a word, and walking its lines. Shared by scene/ObjLoader.cpp (the OBJ and its
// libraries) and scene/MtlMaterials.cpp.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>

#include "scene/Warnings.h"

namespace manylights::detail {

// Throws Error("displayName: what").
[[noreturn]] void failIn(const std::string& displayName, const std::string& what);

// The first line of a message, without its trailing full stop.
std::string firstLine(const std::string& text);

inline std::string_view trim(std::string_view text)
{
    const std::size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos)
        return {};
    const std::size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

// Calls visit(lineNumber, line, isLast) for every line of `text` (without its '\n'). The
// views point into `text`: nothing is copied, which matters on the hot path of every OBJ load.
template <typename Visit>
void forEachRawLine(std::string_view text, Visit visit)
{
    std::size_t lineNumber = 0;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos)
            end = text.size();
        visit(++lineNumber, text.substr(begin, end - begin), end == text.size());
        begin = end + 1;
    }
}

// Calls visit(word) for each word of `line` (separated by spaces, tabs or a '\r'), stopping at
// a word that starts a '#' comment.
template <typename Visit>
void forEachWord(std::string_view line, Visit visit)
{
    for (std::size_t at = line.find_first_not_of(" \t\r"); at != std::string_view::npos;
         at = line.find_first_not_of(" \t\r", at)) {
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        const std::string_view word = line.substr(at, end - at);
        if (word.front() == '#')
            return;
        visit(word);
        at = end;
    }
}

// Calls visit(lineNumber, keyword, rest-of-line) for every line of `text` that is not blank.
template <typename Visit>
void forEachLine(std::string_view text, Visit visit)
{
    forEachRawLine(text, [&](std::size_t lineNumber, std::string_view line, bool) {
        const std::size_t keywordBegin = line.find_first_not_of(" \t");
        if (keywordBegin == std::string_view::npos)
            return;
        const std::size_t keywordEnd = std::min(line.find_first_of(" \t\r", keywordBegin), line.size());
        visit(lineNumber, line.substr(keywordBegin, keywordEnd - keywordBegin), line.substr(keywordEnd));
    });
}

// The file's text as UTF-8: a UTF-8 byte-order mark is dropped, UTF-16 text (either byte
// order, told by its mark) is converted; both noted. Unpaired surrogates become U+FFFD.
std::string decodedText(const std::string& bytes, FileWarnings& warnings);

// The statements this loader reads or knowingly passes over; any other is reported once.
extern const std::set<std::string, std::less<>> kObjStatements;
extern const std::set<std::string, std::less<>> kMtlStatements;

// What a keyword's numbers are, how many it needs, and whether one value stands for three (an
// MTL colour: "Ks 0.5" is grey, as the format allows).
struct NumberKeyword {
    const char* what;
    int needed;
    bool oneForThree;
};
extern const std::map<std::string, NumberKeyword, std::less<>> kObjNumberKeywords;
extern const std::map<std::string, NumberKeyword, std::less<>> kMtlNumberKeywords;

// negative reflectance has no meaning, and the scene format refuses it too.
std::string checkedNumbers(const std::string& text, const std::string& displayName,
                           const std::map<std::string, NumberKeyword, std::less<>>& keywords,
                           const std::set<std::string, std::less<>>& known, FileWarnings& warnings, bool nonNegative);

// tinyobjloader reads face indices with atoi, which wraps past 2^31: "f 1 2 4294967299" with
// three vertices drew a triangle. Every index of a face, line or point element must be an
// integer within int's range here first (the count of vertices is checked afterwards).
void checkElementIndices(const std::string& text, const std::string& displayName);

}  // namespace manylights::detail
