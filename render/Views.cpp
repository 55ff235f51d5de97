#include "render/Views.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/EnumNames.h"

namespace manylights {

namespace {
constexpr EnumNames<ViewMode, 13> kViews = {{
    {ViewMode::Final, "final"},
    {ViewMode::Position, "position"},
    {ViewMode::Normal, "normal"},
    {ViewMode::Diffuse, "diffuse"},
    {ViewMode::Specular, "specular"},
    {ViewMode::Emissive, "emissive"},
    {ViewMode::Depth, "depth"},
    {ViewMode::LightCount, "light-count"},
    {ViewMode::Volumes, "volumes"},
    {ViewMode::VolumeCorners, "volume-corners"},
    {ViewMode::Shadow, "shadow"},
    {ViewMode::Ssao, "ssao"},
    {ViewMode::ShadowResolution, "shadow-resolution"},
}};

using ColourStops = std::array<std::array<float, 3>, 7>;

// The heat maps' stops: `first`, then blue, cyan, green, yellow, red and white.
ColourStops heatMapStops(const std::array<float, 3>& first)
{
    return {{first,
             {0.0f, 0.0f, 1.0f},
             {0.0f, 1.0f, 1.0f},
             {0.0f, 1.0f, 0.0f},
             {1.0f, 1.0f, 0.0f},
             {1.0f, 0.0f, 0.0f},
             {1.0f, 1.0f, 1.0f}}};
}

// The colour at `position` (0 to 6) between the stops, linearly.
void interpolateStops(const ColourStops& stops, float position, float rgb[3])
{
    const auto below = static_cast<std::size_t>(position);
    const std::size_t above = std::min(below + 1, stops.size() - 1);
    const float t = position - static_cast<float>(below);
    for (int c = 0; c < 3; ++c)
        rgb[c] = stops[below][c] + t * (stops[above][c] - stops[below][c]);
}
}  // namespace

std::optional<ViewMode> parseViewMode(std::string_view name) { return parseName(kViews, name); }

std::string_view viewModeName(ViewMode mode) { return nameOf(kViews, mode); }

const std::vector<std::string>& viewModeNames()
{
    static const std::vector<std::string> names = namesOf(kViews);
    return names;
}

void heatMapColour(float count, float rgb[3])
{
    static const ColourStops kStops = heatMapStops({0.0f, 0.0f, 0.0f});
    // Stop k (k ≥ 1) sits at count 4^(k-1): the scale is logarithmic, two bits a stop.
    float position = count <= 0.0f ? 0.0f : 1.0f + std::log2(count) / 2.0f;
    position = std::clamp(position, 0.0f, static_cast<float>(kStops.size() - 1));
    interpolateStops(kStops, position, rgb);
}

void shadowResolutionColour(float texelsPerPixel, float rgb[3])
{
    static const ColourStops kStops = heatMapStops({0.6f, 0.0f, 1.0f});
    if (!(texelsPerPixel > 0.0f)) {
        std::fill_n(rgb, 3, 0.0f);
        return;
    }
    // Stop k sits at 2^(k-3) texels per pixel: a level a stop, 1 in the middle.
    const float position = std::clamp(3.0f + std::log2(texelsPerPixel), 0.0f, static_cast<float>(kStops.size() - 1));
    interpolateStops(kStops, position, rgb);
}

Image displayableView(const Image& raw, ViewMode mode, const std::vector<bool>& covered)
{
    Image shown = raw;
    const std::size_t pixels = static_cast<std::size_t>(raw.width) * raw.height;
    if (mode == ViewMode::LightCount) {
        for (std::size_t i = 0; i < pixels; ++i)
            heatMapColour(raw.rgb[i * 3], &shown.rgb[i * 3]);
    } else if (mode == ViewMode::ShadowResolution) {
        for (std::size_t i = 0; i < pixels; ++i)
            shadowResolutionColour(raw.rgb[i * 3], &shown.rgb[i * 3]);
    } else if (mode == ViewMode::Normal) {
        for (std::size_t i = 0; i < pixels; ++i)
            if (covered[i])
                for (int c = 0; c < 3; ++c)
                    shown.rgb[i * 3 + c] = 0.5f * raw.rgb[i * 3 + c] + 0.5f;
    } else if (mode == ViewMode::Position || mode == ViewMode::Depth) {
        // Per channel range over the covered pixels, so the scene fills the grey scale.
        std::array<float, 3> low;
        std::array<float, 3> high;
        low.fill(std::numeric_limits<float>::max());
        high.fill(std::numeric_limits<float>::lowest());
        for (std::size_t i = 0; i < pixels; ++i)
            if (covered[i])
                for (int c = 0; c < 3; ++c) {
                    low[c] = std::min(low[c], raw.rgb[i * 3 + c]);
                    high[c] = std::max(high[c], raw.rgb[i * 3 + c]);
                }
        for (std::size_t i = 0; i < pixels; ++i) {
            if (!covered[i])
                continue;
            for (int c = 0; c < 3; ++c) {
                const float span = high[c] - low[c];
                const float t = span > 0.0f ? (raw.rgb[i * 3 + c] - low[c]) / span : 0.0f;
                // Depth: near is bright, and the farthest surface stays visible against the
                // black background.
                shown.rgb[i * 3 + c] = mode == ViewMode::Depth ? 1.0f - 0.9f * t : t;
            }
        }
    }
    return shown;
}

}  // namespace manylights
