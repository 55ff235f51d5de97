#include "core/Numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace manylights {

std::string formatNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string checkNumber(std::string_view text, double min, double max, double& value)
{
    // A leading '+' is how some people write a positive number; from_chars does not take it.
    std::string_view digits = text;
    if (digits.size() > 1 && digits.front() == '+')
        digits.remove_prefix(1);
    double parsed = 0.0;
    const auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
    if (digits.empty() || error != std::errc{} || stop != digits.data() + digits.size() || !std::isfinite(parsed) ||
        parsed < min || parsed > max)
        return "must be a number from " + formatNumber(min) + " to " + formatNumber(max) + ", got '" +
               std::string(text) + "'";
    value = parsed;
    return {};
}

}  // namespace manylights
