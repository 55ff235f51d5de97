#include "scene/JsonText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <set>
#include <utility>

#include "core/Error.h"

namespace manylights::scene_json {

// ---------------------------------------------------------------------------------------
// Formatting for messages. Every message is one line, so user text is escaped.

std::string formatFloat(float value)
{
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

std::string formatDouble(double value)
{
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

// A user's string in single quotes, with JSON escapes for anything that would break the line.
std::string quote(std::string_view text)
{
    const std::string dumped = Json(std::string(text)).dump(-1, ' ', false, Json::error_handler_t::replace);
    // Appended piece by piece: GCC 12 at -O3 takes "'" + substr + "'" for an overlapping copy
    // (a false -Wrestrict) once this is inlined into another translation unit's callers.
    std::string quoted = "'";
    quoted.append(dumped, 1, dumped.size() - 2);  // without dump()'s double quotes
    quoted += '\'';
    return quoted;
}

std::string describeType(const Json& value)
{
    switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    default: return "a value";
    }
}

// The type, and for arrays the length, so that "expected an array of 3 numbers" is answered
// with what the file actually holds.
std::string describeShape(const Json& value)
{
    if (!value.is_array())
        return describeType(value);
    if (value.empty())
        return "an empty array";
    return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
}

std::string describeValue(const Json& value)
{
    if (value.is_number())
        return formatDouble(value.get<double>());
    if (value.is_string())
        return quote(value.get<std::string>());
    if (value.is_boolean())
        return value.get<bool>() ? "true" : "false";
    return describeType(value);
}

std::string escapePointerToken(std::string_view token)
{
    std::string escaped;
    for (char c : token) {
        if (c == '~')
            escaped += "~0";
        else if (c == '/')
            escaped += "~1";
        else
            escaped += c;
    }
    return escaped;
}

std::string toLower(std::string_view text)
{
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower;
}

namespace {
std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace
// The guess compares names of at most this many bytes, against at most this many candidates:
// the edit distance costs the product of the lengths, and a 600 KB file of long material
// names must fail at once, not after hours. A typo of a longer name goes unguessed.
constexpr std::size_t kMaxGuessedNameLength = 64;
constexpr std::size_t kMaxGuessCandidates = 4096;

// The candidate the user most likely meant: a small edit away (typos, British spellings,
// case) or sharing all but the last letter of the shorter word as a prefix.
std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates)
{
    if (word.size() > kMaxGuessedNameLength)
        return std::nullopt;
    const std::string lowerWord = toLower(word);
    std::optional<std::string> best;
    std::size_t bestDistance = 0;
    std::size_t compared = 0;
    for (const std::string& candidate : candidates) {
        if (candidate.size() > kMaxGuessedNameLength)
            continue;
        if (++compared > kMaxGuessCandidates)
            break;
        const std::string lowerCandidate = toLower(candidate);
        std::size_t distance = editDistance(lowerWord, lowerCandidate);
        const std::size_t shorter = std::min(lowerWord.size(), lowerCandidate.size());
        std::size_t common = 0;
        while (common < shorter && lowerWord[common] == lowerCandidate[common])
            ++common;
        // "pos" for "position", "rotate" for "rotation", "scale" for "scaling".
        const bool prefix = common >= 3 && common + 1 >= shorter;
        const std::size_t allowed = std::max<std::size_t>(1, std::max(lowerWord.size(), lowerCandidate.size()) / 3);
        if (distance > allowed && !prefix)
            continue;
        if (prefix)
            distance = std::min(distance, allowed);
        if (!best || distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

std::string joinNames(const std::vector<std::string>& names)
{
    std::string joined;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0)
            joined += ", ";
        joined += names[i];
    }
    return joined;
}

// The hint after an unknown name: the closest of `names`, or all of them.
std::string nameHint(std::string_view word, const std::vector<std::string>& names)
{
    if (const auto guess = closest(word, names))
        return " (did you mean " + quote(*guess) + "?)";
    return " (expected one of: " + joinNames(names) + ")";
}

// ---------------------------------------------------------------------------------------
// Syntax: nlohmann parses, we report positions as FILE:LINE:COLUMN.

namespace {
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};

// Line and column (1-based, columns counted in UTF-8 characters) of the byte at `offset`.
TextPosition positionOf(const std::string& text, std::size_t offset)
{
    TextPosition position;
    offset = std::min(offset, text.size());
    for (std::size_t i = 0; i < offset; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++position.line;
            position.column = 1;
        } else if ((c & 0xC0u) != 0x80u) {
            ++position.column;
        }
    }
    return position;
}

}  // namespace

std::string oneLine(std::string text)
{
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20u)
            c = ' ';
    return text;
}

namespace {
// Drops nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 14: "
// (we compute and print the position ourselves) and keeps its explanation of what was
// found and what was expected.
std::string explainParseError(const std::string& what)
{
    std::string text = what;
    if (text.starts_with("[json.exception.")) {
        const std::size_t bracket = text.find("] ");
        if (bracket != std::string::npos)
            text.erase(0, bracket + 2);
    }
    if (text.starts_with("parse error")) {
        const std::size_t colon = text.find(": ");
        if (colon != std::string::npos)
            text.erase(0, colon + 2);
    }
    const std::size_t dash = text.find(" - ");
    if (dash != std::string::npos)
        text.replace(dash, 3, ": ");
    return oneLine(text);
}

// Where the number token `token` first occurs outside strings. nlohmann reports a number too
// large for a double without a position; the first such token is the one it stopped at.
std::optional<std::size_t> findNumberToken(const std::string& text, const std::string& token)
{
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\')
                    ++i;
            ++i;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            const std::size_t start = i;
            while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '-' ||
                                       text[i] == '+' || text[i] == '.' || text[i] == 'e' || text[i] == 'E'))
                ++i;
            if (text.compare(start, i - start, token) == 0)
                return start;
        } else {
            ++i;
        }
    }
    return std::nullopt;
}

// nlohmann keeps the last of two equal keys in an object; a silently ignored first value is
// the kind of typo the strict format exists to catch, so a first pass over the text rejects
// it, naming the JSON path of the repeated key. A SAX pass, linear in the text: nlohmann
// 3.11's parser callback rescans the enclosing container after every value, which made
// 400,000 inline lights take 50 s to load (docs/performance.md).
class DuplicateKeyCheck : public nlohmann::json_sax<Json> {
public:
    explicit DuplicateKeyCheck(const std::string& displayName) : displayName_(displayName) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override
    {
        stack_.push_back({true, {}, {}, 0});
        return true;
    }
    bool key(string_t& name) override
    {
        Frame& top = stack_.back();
        top.key = name;
        if (!top.keys.insert(top.key).second)
            throw Error(displayName_ + ": " + currentPath() + ": duplicate key " + quote(top.key));
        return true;
    }
    bool end_object() override { return end(); }
    bool start_array(std::size_t) override
    {
        stack_.push_back({false, {}, {}, 0});
        return true;
    }
    bool end_array() override { return end(); }
    // Rethrown as its own type (a syntax error, or a number out of range), so that the one
    // handler in parseJson formats the errors of both passes.
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override
    {
        if (const auto* syntax = dynamic_cast<const Json::parse_error*>(&e))
            throw *syntax;
        if (const auto* range = dynamic_cast<const Json::out_of_range*>(&e))
            throw *range;
        throw Error(displayName_ + ": " + e.what());
    }

private:
    struct Frame {
        bool isObject;
        std::set<std::string> keys;
        std::string key;
        std::size_t index;
    };

    // A finished value moves an enclosing array on to its next index.
    bool value()
    {
        if (!stack_.empty() && !stack_.back().isObject)
            ++stack_.back().index;
        return true;
    }
    bool end()
    {
        stack_.pop_back();
        return value();
    }

    std::string currentPath() const
    {
        std::string path;
        for (const Frame& frame : stack_) {
            path += '/';  // appended apart: "/" + a temporary trips GCC 12's false -Wrestrict here
            path += frame.isObject ? escapePointerToken(frame.key) : std::to_string(frame.index);
        }
        return path;
    }

    const std::string& displayName_;
    std::vector<Frame> stack_;
};

}  // namespace
Json parseJson(const std::string& text, const std::string& displayName)
{
    try {
        DuplicateKeyCheck duplicates(displayName);
        Json::sax_parse(text, &duplicates);
        return Json::parse(text);
    } catch (const Json::parse_error& e) {
        // e.byte is the 1-based index of the last character read: the one that was wrong.
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        const TextPosition at = positionOf(text, offset);
        // Comments are the most common non-JSON in hand-written scenes; say so plainly.
        const bool comment =
            offset + 1 < text.size() && text[offset] == '/' && (text[offset + 1] == '/' || text[offset + 1] == '*');
        throw Error(displayName + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
                    (comment ? std::string("comments are not allowed in JSON") : explainParseError(e.what())));
    } catch (const Json::out_of_range& e) {
        const std::string what = e.what();
        const std::size_t open = what.find('\'');
        const std::size_t close = what.rfind('\'');
        if (open != std::string::npos && close > open) {
            const std::string token = what.substr(open + 1, close - open - 1);
            if (const auto offset = findNumberToken(text, token)) {
                const TextPosition at = positionOf(text, *offset);
                throw Error(displayName + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                            ": number out of range: " + oneLine(token));
            }
        }
        throw Error(displayName + ": " + explainParseError(what));
    } catch (const Json::exception& e) {
        throw Error(displayName + ": " + explainParseError(e.what()));
    }
}

}  // namespace manylights::scene_json
