#include "render/culling/ScreenBounds.h"

#include <algorithm>
#include <cmath>

namespace manylights {

std::pair<double, double> projectedPixels(double lateral, double depth, double radius, double tanHalf, int pixels)
{
    // Tangent slopes k solve (lateral − k·depth)² = radius² (1 + k²).
    const double denominator = (depth - radius) * (depth + radius);
    const double root = radius * std::sqrt(lateral * lateral + denominator);
    const double low = (lateral * depth - root) / denominator;
    const double high = (lateral * depth + root) / denominator;
    const auto toPixels = [&](double slope) { return (slope / tanHalf + 1.0) * 0.5 * pixels; };
    return {toPixels(low) - kRectanglePaddingPixels, toPixels(high) + kRectanglePaddingPixels};
}

std::pair<int, int> tileSpan(double low, double high, int tileSize, int tiles)
{
    if (std::isnan(low) || std::isnan(high))
        return {0, tiles - 1};  // nothing proved: every tile
    const double first = std::floor(low / tileSize);
    const double last = std::floor(high / tileSize);
    if (last < 0.0 || first > tiles - 1)
        return {1, 0};
    return {static_cast<int>(std::max(first, 0.0)), static_cast<int>(std::min(last, tiles - 1.0))};
}

}  // namespace manylights
