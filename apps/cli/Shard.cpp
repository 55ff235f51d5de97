#include "apps/cli/Shard.h"

#include <charconv>

namespace manylights {

namespace {

bool parsePositive(const std::string& text, int& value)
{
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    return !text.empty() && error == std::errc{} && stop == end;
}

}  // namespace

std::string parseShard(const std::string& text, Shard& shard)
{
    const std::size_t slash = text.find('/');
    Shard parsed;
    if (slash == std::string::npos || !parsePositive(text.substr(0, slash), parsed.index) ||
        !parsePositive(text.substr(slash + 1), parsed.count))
        return "--shard must be I/N (task I of N, e.g. 2/8), got '" + text + "'";
    if (parsed.count < 1 || parsed.count > kMaxShards)
        return "--shard's N must be 1 to " + std::to_string(kMaxShards) + ", got '" + text + "'";
    if (parsed.index < 1 || parsed.index > parsed.count)
        return "--shard's I must be 1 to N (" + std::to_string(parsed.count) + "), got '" + text + "'";
    shard = parsed;
    return {};
}

}  // namespace manylights
