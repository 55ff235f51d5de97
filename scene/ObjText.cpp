#include "scene/ObjText.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/Error.h"

namespace manylights::detail {

namespace {

// Appends code point `c` to `out` in UTF-8.
void appendUtf8(std::string& out, std::uint32_t c)
{
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

}  // namespace

void failIn(const std::string& displayName, const std::string& what) { throw Error(displayName + ": " + what); }

std::string firstLine(const std::string& text)
{
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == '.' || line.back() == ' '))
        line.pop_back();
    return line;
}

std::string decodedText(const std::string& bytes, FileWarnings& warnings)
{
    const auto starts = [&](const char* mark, std::size_t length) {
        return bytes.compare(0, length, mark, length) == 0;
    };
    if (starts("\xEF\xBB\xBF", 3)) {
        warnings.noteFile("bom", "a UTF-8 byte-order mark, skipped");
        return bytes.substr(3);
    }
    const bool bigEndian = starts("\xFE\xFF", 2);
    if (!bigEndian && !starts("\xFF\xFE", 2))
        return bytes;
    warnings.noteFile("utf16",
                      std::string("UTF-16 text (") + (bigEndian ? "big" : "little") + "-endian), read as such");
    const auto unit = [&](std::size_t i) {
        const auto hi = static_cast<unsigned char>(bytes[bigEndian ? i : i + 1]);
        const auto lo = static_cast<unsigned char>(bytes[bigEndian ? i + 1 : i]);
        return static_cast<std::uint32_t>(hi << 8 | lo);
    };
    std::string text;
    text.reserve(bytes.size() / 2);
    for (std::size_t i = 2; i + 1 < bytes.size(); i += 2) {
        std::uint32_t c = unit(i);
        if (c >= 0xD800 && c < 0xDC00 && i + 3 < bytes.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) < 0xE000) {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c < 0xE000) {
            c = 0xFFFD;
        }
        appendUtf8(text, c);
    }
    return text;
}

const std::set<std::string, std::less<>> kObjStatements{"v", "vn", "vt", "vp", "f",      "l",
                                                        "p", "g",  "o",  "s",  "usemtl", "mtllib"};
const std::set<std::string, std::less<>> kMtlStatements{
    "newmtl",   "Ka",    "Kd",     "Ks",     "Ke",     "Ns",     "Ni",        "d",      "Tr",
    "Tf",       "illum", "map_Ka", "map_Kd", "map_Ks", "map_Ke", "map_Ns",    "map_d",  "map_bump",
    "map_Bump", "bump",  "norm",   "disp",   "decal",  "refl",   "sharpness", "Pr",     "Pm",
    "Ps",       "Pc",    "Pcr",    "aniso",  "anisor", "map_Pr", "map_Pm",    "map_Ps", "Tw"};

const std::map<std::string, NumberKeyword, std::less<>> kObjNumberKeywords{
    {"v", {"vertex position", 3, false}}, {"vn", {"normal", 3, false}}, {"vt", {"texture coordinate", 1, false}}};

const std::map<std::string, NumberKeyword, std::less<>> kMtlNumberKeywords{{"Kd", {"Kd", 3, true}},
                                                                           {"Ks", {"Ks", 3, true}},
                                                                           {"Ke", {"Ke", 3, true}},
                                                                           {"Ka", {"Ka", 3, true}},
                                                                           {"Ns", {"Ns", 1, false}}};

// The text tinyobjloader is given: the numbers of the lines that carry them read here first,
// with the line number, since tinyobjloader reads "nan", "inf" and malformed numbers as 0
// without a word. Non-finite and unreadable numbers are errors; what other readers forgive
// is rewritten and noted: a leading '+', trailing characters after a number ("3.1+e2" reads
// as 3.1, as C's strtod and assimp read it), a one-value MTL colour. Unknown statements are
// noted once each. With `nonNegative` (material libraries) a number below zero is an error: a

// negative reflectance has no meaning, and the scene format refuses it too.
std::string checkedNumbers(const std::string& text, const std::string& displayName,
                           const std::map<std::string, NumberKeyword, std::less<>>& keywords,
                           const std::set<std::string, std::less<>>& known, FileWarnings& warnings, bool nonNegative)
{
    std::string out;
    out.reserve(text.size());
    std::vector<std::string_view> numbers;  // reused: no allocation per line
    forEachRawLine(text, [&](std::size_t lineNumber, std::string_view line, bool lastLine) {
        const auto emit = [&](std::string_view written) {
            out += written;
            if (!lastLine)
                out += '\n';
        };
        const std::size_t keywordBegin = line.find_first_not_of(" \t\r");
        const std::string_view keyword =
            keywordBegin == std::string_view::npos || line[keywordBegin] == '#'
                ? std::string_view()
                : line.substr(keywordBegin,
                              std::min(line.find_first_of(" \t\r", keywordBegin), line.size()) - keywordBegin);
        const auto found = keyword.empty() ? keywords.end() : keywords.find(keyword);
        if (found == keywords.end()) {
            if (!keyword.empty() && !known.contains(keyword))
                warnings.note(lineNumber, "statement " + std::string(keyword),
                              "unknown statement '" + std::string(keyword) + "' ignored");
            return emit(line);
        }
        const NumberKeyword& spec = found->second;
        const auto failHere = [&](const std::string& what) {
            failIn(displayName, "line " + std::to_string(lineNumber) + ": " + spec.what + " " + what);
        };
        numbers.clear();
        bool rewritten = false;
        forEachWord(line.substr(keywordBegin + keyword.size()), [&](std::string_view token) {
            std::string_view digits = token;
            if (digits.size() > 1 && digits.front() == '+') {
                digits.remove_prefix(1);
                rewritten = true;
                warnings.note(lineNumber, "plus", "numbers with a leading '+' read without it");
            }
            float value = 0.0f;
            const auto [next, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
            if (error != std::errc{} || !std::isfinite(value))
                failHere("has a non-finite or malformed number '" + std::string(token) + "'");
            const std::string_view read(digits.data(), static_cast<std::size_t>(next - digits.data()));
            if (read.size() != digits.size()) {
                rewritten = true;
                warnings.note(lineNumber, "trailing",
                              "the number '" + std::string(token) + "' read as " + std::string(read) +
                                  " (the characters after it ignored)");
            }
            if (nonNegative && value < 0.0f)
                failHere("must not be negative, got '" + std::string(token) + "'");
            numbers.push_back(read);
        });
        if (spec.oneForThree && numbers.size() == 1) {
            numbers.resize(3, numbers.front());
            rewritten = true;
            warnings.note(lineNumber, "one value",
                          std::string(spec.what) + " with one value taken for all three channels");
        }
        if (static_cast<int>(numbers.size()) < spec.needed)
            failHere("needs " + std::to_string(spec.needed) + " numbers, has " + std::to_string(numbers.size()));
        if (!rewritten)
            return emit(line);
        std::string written(keyword);
        for (const std::string_view number : numbers) {
            written += ' ';
            written += number;
        }
        emit(written);
    });
    return out;
}

// tinyobjloader reads face indices with atoi, which wraps past 2^31: "f 1 2 4294967299" with
// three vertices drew a triangle. Every index of a face, line or point element must be an
// integer within int's range here first (the count of vertices is checked afterwards).
void checkElementIndices(const std::string& text, const std::string& displayName)
{
    forEachLine(text, [&](std::size_t lineNumber, std::string_view keyword, std::string_view rest) {
        if (keyword != "f" && keyword != "l" && keyword != "p")
            return;
        forEachWord(rest, [&](std::string_view corner) {
            // "1/2/3", "1//3" (no texture coordinate), "1": each present index in int's range.
            for (std::size_t begin = 0; begin <= corner.size();) {
                const std::size_t slash = std::min(corner.find('/', begin), corner.size());
                const std::string_view part = corner.substr(begin, slash - begin);
                long long index = 0;
                const auto [next, error] = std::from_chars(part.data(), part.data() + part.size(), index);
                if (!part.empty() && (error != std::errc{} || next != part.data() + part.size() ||
                                      index > std::numeric_limits<int>::max() ||
                                      index < -static_cast<long long>(std::numeric_limits<int>::max())))
                    failIn(displayName, "line " + std::to_string(lineNumber) + ": the index '" + std::string(part) +
                                            "' is not an integer within ±2147483647");
                begin = slash + 1;
            }
        });
    });
}

}  // namespace manylights::detail
