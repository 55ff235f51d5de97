// The scene file's JSON text (scene/SceneLoader.h): parsing with positions and duplicate keys
// reported as one line naming the file, line and column, and the wording of every message
// about a value (its type, shape, a quoted and escaped copy, the JSON pointer of where it is,
// and "did you mean" hints for misspelt names). Kept apart from the loader, which reads the
// format's sections: these say nothing about what a scene contains.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace manylights::scene_json {

// Ordered, so that materials keep the order of the file and unknown keys are reported in the
// order the user wrote them.
using Json = nlohmann::ordered_json;

// Parses `text`; throws manylights::Error "<displayName>:<line>:<column>: <what>" for malformed
// JSON, a duplicate key or a number that no float can hold.
Json parseJson(const std::string& text, const std::string& displayName);

// Numbers as messages show them: the shortest text that reads back as the same value.
std::string formatFloat(float value);
std::string formatDouble(double value);
// `text` in single quotes, with control characters and quotes escaped: one line whatever it holds.
std::string quote(std::string_view text);
// "a string", "an array", ... for a value of the wrong type.
std::string describeType(const Json& value);
// An array's length in words ("an array of 2 elements"); other values as describeType.
std::string describeShape(const Json& value);
// The value itself, short, for messages that name it ("got 1.5", "got 'area'").
std::string describeValue(const Json& value);
// A key as one token of a JSON pointer (RFC 6901: ~ and / escaped).
std::string escapePointerToken(std::string_view token);
std::string toLower(std::string_view text);
// The candidate the user most likely meant by `word`, if any is close enough.
std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates);
// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);
// " (did you mean 'x'?)" or " (expected one of: ...)" for an unknown name among `names`.
std::string nameHint(std::string_view word, const std::vector<std::string>& names);
// `text` without line breaks: messages are one line.
std::string oneLine(std::string text);

}  // namespace manylights::scene_json
