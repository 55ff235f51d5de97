#include "scene/SceneFileReader.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace manylights::scene_file {

using namespace scene_json;  // the wording of messages (scene/JsonText.h)

std::string Reader::located(const Node& node, const std::string& what) const
{
    // The root has the empty pointer, which reads badly in a message.
    const std::string where = node.path.empty() ? "" : node.path + ": ";
    return oneLine(displayName_ + ": " + where + what);
}

// --- structure -----------------------------------------------------------------------

std::optional<Node> Reader::member(const Node& object, std::string_view key)
{
    const auto it = object.json->find(std::string(key));
    if (it == object.json->end())
        return std::nullopt;
    return Node{&*it, object.path + "/" + escapePointerToken(key)};
}

Node Reader::required(const Node& object, std::string_view key) const
{
    auto node = member(object, key);
    if (!node)
        fail(object, "missing required key " + quote(key));
    return *node;
}

Node Reader::element(const Node& array, std::size_t index)
{
    return Node{&(*array.json)[index], array.path + "/" + std::to_string(index)};
}

void Reader::expectObject(const Node& node) const
{
    if (!node.json->is_object())
        fail(node, "expected an object, got " + describeType(*node.json));
}

void Reader::expectArray(const Node& node, std::size_t maxSize, const char* what) const
{
    if (!node.json->is_array())
        fail(node, "expected an array, got " + describeType(*node.json));
    if (node.json->size() > maxSize)
        fail(node, "too many " + std::string(what) + ": " + std::to_string(node.json->size()) + " (at most " +
                       std::to_string(maxSize) + ")");
}

void Reader::expectKeys(const Node& object, Keys known) const
{
    expectObject(object);
    for (const auto& item : object.json->items()) {
        const std::string& key = item.key();
        if (std::find(known.begin(), known.end(), key) != known.end())
            continue;
        fail(Node{&item.value(), object.path + "/" + escapePointerToken(key)},
             "unknown key " + quote(key) + nameHint(key, std::vector<std::string>(known.begin(), known.end())));
    }
}

// --- scalars -------------------------------------------------------------------------

float Reader::number(const Node& node) const
{
    if (!node.json->is_number())
        fail(node, "expected a number, got " + describeType(*node.json));
    const double value = node.json->get<double>();
    const auto single = static_cast<float>(value);
    if (!std::isfinite(single))
        fail(node, "number out of range: " + formatDouble(value) + " does not fit in a 32-bit float");
    return single;
}

float Reader::positive(const Node& node) const
{
    const float value = number(node);
    if (!(value > 0.0f))
        fail(node, "must be > 0, got " + describeValue(*node.json));
    return value;
}

float Reader::nonNegative(const Node& node) const
{
    const float value = number(node);
    if (!(value >= 0.0f))
        fail(node, "must be >= 0, got " + describeValue(*node.json));
    return value;
}

float Reader::nonZero(const Node& node) const
{
    const float value = number(node);
    if (value == 0.0f)
        fail(node, "must be non-zero, got " + describeValue(*node.json));
    return value;
}

float Reader::shininess(const Node& node) const
{
    const float value = number(node);
    if (!(value >= 1.0f))
        fail(node, "must be >= 1, got " + describeValue(*node.json));
    return value;
}

float Reader::cutoff(const Node& node) const
{
    const float value = number(node);
    if (!(value > 0.0f && value <= 180.0f))
        fail(node, "must be in (0, 180], got " + describeValue(*node.json));
    return value;
}

float Reader::fraction(const Node& node) const
{
    const float value = number(node);
    if (!(value >= 0.0f && value < 1.0f))
        fail(node, "must be in [0, 1), got " + describeValue(*node.json));
    return value;
}

std::int64_t Reader::integer(const Node& node, std::int64_t lo, std::int64_t hi) const
{
    const Json& json = *node.json;
    if (!json.is_number())
        fail(node, "expected an integer, got " + describeType(json));
    // Appended piece by piece: GCC 12 sees an overlapping memcpy in "[" + std::to_string(lo)
    // once this function is compiled on its own (a false -Wrestrict, GCC bug 105651).
    std::string range = "[";
    range += std::to_string(lo);
    range += ", ";
    range += std::to_string(hi);
    range += "]";
    if (json.is_number_unsigned()) {
        const auto value = json.get<std::uint64_t>();
        // nlohmann stores 0 and every positive literal as unsigned, so lo applies here too.
        if (value > static_cast<std::uint64_t>(hi) || static_cast<std::int64_t>(value) < lo)
            fail(node, "must be in " + range + ", got " + std::to_string(value));
        return static_cast<std::int64_t>(value);
    }
    if (json.is_number_integer()) {
        const auto value = json.get<std::int64_t>();
        if (value < lo || value > hi)
            fail(node, "must be in " + range + ", got " + std::to_string(value));
        return value;
    }
    // A float with an integral value (1e3) is accepted: JSON does not distinguish them.
    const double value = json.get<double>();
    if (value != std::floor(value))
        fail(node, "expected an integer, got " + formatDouble(value));
    if (value < static_cast<double>(lo) || value > static_cast<double>(hi))
        fail(node, "must be in " + range + ", got " + formatDouble(value));
    return static_cast<std::int64_t>(value);
}

std::string Reader::string(const Node& node) const
{
    if (!node.json->is_string())
        fail(node, "expected a string, got " + describeType(*node.json));
    return node.json->get<std::string>();
}

std::string Reader::oneOf(const Node& node, const std::vector<std::string>& names) const
{
    const std::string value = string(node);
    if (std::find(names.begin(), names.end(), value) == names.end())
        fail(node, "unknown value " + quote(value) + nameHint(value, names));
    return value;
}

bool Reader::boolean(const Node& node) const
{
    if (!node.json->is_boolean())
        fail(node, "expected true or false, got " + describeType(*node.json));
    return node.json->get<bool>();
}

float Reader::optionalNumber(const Node& node, std::string_view key, float fallback, NumberReader reader) const
{
    const auto found = member(node, key);
    return found ? (this->*reader)(*found) : fallback;
}

// --- vectors and intervals -----------------------------------------------------------

void Reader::expectNumberArray(const Node& node, std::size_t count) const
{
    if (!node.json->is_array() || node.json->size() != count)
        fail(node, "expected an array of " + std::to_string(count) + " numbers, got " + describeShape(*node.json));
}

glm::vec3 Reader::vec3(const Node& node, NumberReader component) const
{
    expectNumberArray(node, 3);
    glm::vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = (this->*component)(element(node, static_cast<std::size_t>(i)));
    return v;
}

glm::vec3 Reader::direction(const Node& node) const
{
    const glm::vec3 v = vec3(node);
    const float lengthSquared = glm::dot(v, v);
    if (v == glm::vec3(0.0f))
        fail(node, "must be a non-zero vector");
    if (!(lengthSquared > 0.0f) || !std::isfinite(lengthSquared))
        fail(node, "cannot be normalised in float precision; scale it to a length near 1");
    return v;
}

Interval Reader::interval(const Node& node, NumberReader bound) const
{
    if (!node.json->is_array() || node.json->size() != 2)
        fail(node, "expected an interval [lo, hi] of 2 numbers, got " + describeShape(*node.json));
    const Interval result{(this->*bound)(element(node, 0)), (this->*bound)(element(node, 1))};
    if (result.lo > result.hi)
        fail(node, "interval must have lo <= hi, got [" + describeValue((*node.json)[0]) + ", " +
                       describeValue((*node.json)[1]) + "]");
    return result;
}

Interval Reader::numberOrInterval(const Node& node, NumberReader bound) const
{
    if (node.json->is_number()) {
        const float value = (this->*bound)(node);
        return {value, value};
    }
    if (!node.json->is_array())
        fail(node, "expected a number or an interval [lo, hi], got " + describeType(*node.json));
    return interval(node, bound);
}

// --- files ---------------------------------------------------------------------------

fs::path Reader::resolve(const Node& node) const
{
    const std::string text = string(node);
    if (text.empty())
        fail(node, "expected a file path, got an empty string");
    return (base_ / fs::path(text)).lexically_normal();
}

std::string Reader::packageHint(const fs::path& path)
{
    static const std::pair<const char*, const char*> kPackageFolders[] = {
        {"/usr/share/assimp/models/", "assimp-testmodels"},
    };
    for (const auto& [folder, package] : kPackageFolders)
        if (path.string().starts_with(folder))
            return std::string(" (installed by the Debian package ") + package + ": apt-get install " + package +
                   ", or scripts/setup.sh)";
    return {};
}

void Reader::expectRegularFile(const Node& node, const fs::path& path) const
{
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status))
        fail(node, "file not found: " + path.string() + packageHint(path));
    if (!fs::is_regular_file(status))
        fail(node, "not a regular file: " + path.string());
}

// --- animation -----------------------------------------------------------------------

std::pair<std::string, Node> Reader::animationKind(const Node& node, const std::vector<std::string>& kinds) const
{
    expectObject(node);
    if (node.json->size() != 1)
        fail(node, "expected exactly one animation kind (one of: " + joinNames(kinds) + "), got " +
                       std::to_string(node.json->size()) + " keys");
    const std::string kind = node.json->begin().key();
    const Node settings{&node.json->begin().value(), node.path + "/" + escapePointerToken(kind)};
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
        fail(settings, "unknown animation " + quote(kind) + nameHint(kind, kinds));
    return {kind, settings};
}

}  // namespace manylights::scene_file
