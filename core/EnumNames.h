// An enum's names for the command line and the files: one table of (value, name) pairs per enum,
// and the lookups both ways, so that an option's parser, its help and --stats read one list.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace manylights {

template <typename Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

template <typename Enum, std::size_t N>
std::optional<Enum> parseName(const EnumNames<Enum, N>& table, std::string_view name)
{
    for (const auto& [value, text] : table)
        if (text == name)
            return value;
    return std::nullopt;
}

// "?" for a value the table lacks.
template <typename Enum, std::size_t N>
std::string_view nameOf(const EnumNames<Enum, N>& table, Enum value)
{
    for (const auto& [entry, text] : table)
        if (entry == value)
            return text;
    return "?";
}

template <typename Enum, std::size_t N>
std::vector<std::string> namesOf(const EnumNames<Enum, N>& table)
{
    std::vector<std::string> names;
    for (const auto& entry : table)
        names.emplace_back(entry.second);
    return names;
}

}  // namespace manylights
