#include "render/HeatMapLegend.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "render/Techniques.h"
#include "render/Views.h"

namespace manylights {

namespace {

constexpr int kGlyphWidth = kLegendGlyphWidth;
constexpr int kGlyphHeight = kLegendGlyphHeight;
constexpr int kGlyphAdvance = kLegendGlyphAdvance;

// The heat map's stops (render/Views.h, heatMapColour): stop k ≥ 1 at count 4^(k−1), the last
// (white) at 1024 and above.
constexpr int kStops = 7;
constexpr const char* kStopLabels[kStops] = {"0", "1", "4", "16", "64", "256", "1024+"};

// The layout in units of the scale (image pixels at scale 1): the title, the bar with the
// maximum's mark above it and "MAX N" beside it, the stops' labels under it.
constexpr int kMargin = 4;      // from the image's edges
constexpr int kPadding = 3;     // inside the panel
constexpr int kTitleGap = 2;    // between the title and the mark
constexpr int kBarWidth = 168;  // 28 per stop interval: room for "1024+" under the last stop
constexpr int kBarHeight = 8;
constexpr int kMarkHeight = 3;      // the frame maximum's mark above the bar
constexpr int kLabelGap = 2;        // between the bar and the labels
constexpr int kMaxLabelChars = 11;  // "MAX " and up to 7 digits
constexpr int kPanelWidth = kPadding + kBarWidth + 3 * kGlyphAdvance + kGlyphAdvance * kMaxLabelChars + kPadding;
constexpr int kMarkY = kPadding + kGlyphHeight + kTitleGap;
constexpr int kBarY = kMarkY + kMarkHeight;
constexpr int kPanelHeight = kBarY + kBarHeight + kLabelGap + kGlyphHeight + kPadding;
// The title's characters that fit between the paddings: 56.
constexpr int kMaxTitleChars = (kPanelWidth - 2 * kPadding + 1) / kGlyphAdvance;
// Rows of the image per unit of the scale: 1 up to 719 rows, 2 at 720p, 3 at 1080p.
constexpr int kRowsPerScale = 360;

constexpr float kPanelGrey = 0.12f;  // dark, so that the white labels and every bar colour stand out

struct Canvas {
    Image& image;
    int originX;
    int originY;
    int scale;

    void fill(int x, int y, int width, int height, const float rgb[3]) const
    {
        for (int py = originY + y * scale; py < originY + (y + height) * scale && py < image.height; ++py)
            for (int px = originX + x * scale; px < originX + (x + width) * scale && px < image.width; ++px)
                std::copy(rgb, rgb + 3, image.pixel(px, py));
    }
    void text(int x, int y, const std::string& label) const
    {
        static const float kWhite[3] = {1.0f, 1.0f, 1.0f};
        for (std::size_t i = 0; i < label.size(); ++i) {
            const auto rows = legendGlyph(label[i]);
            for (int row = 0; row < kGlyphHeight; ++row)
                for (int column = 0; column < kGlyphWidth; ++column)
                    if ((rows[static_cast<std::size_t>(row)] >> (kGlyphWidth - 1 - column)) & 1)
                        fill(x + static_cast<int>(i) * kGlyphAdvance + column, y + row, 1, 1, kWhite);
        }
    }
};

int textWidth(const std::string& label) { return static_cast<int>(label.size()) * kGlyphAdvance - 1; }

// The bar's position (0 .. 1) of a count on the heat map's scale.
float scalePosition(float count)
{
    const float stop = count <= 0.0f ? 0.0f : 1.0f + std::log2(count) / 2.0f;
    return std::clamp(stop, 0.0f, float(kStops - 1)) / float(kStops - 1);
}

}  // namespace

std::array<unsigned char, kLegendGlyphHeight> legendGlyph(char c)
{
    switch (c) {
    case '0': return {7, 5, 5, 5, 7};
    case '1': return {2, 6, 2, 2, 7};
    case '2': return {7, 1, 7, 4, 7};
    case '3': return {7, 1, 7, 1, 7};
    case '4': return {5, 5, 7, 1, 1};
    case '5': return {7, 4, 7, 1, 7};
    case '6': return {7, 4, 7, 5, 7};
    case '7': return {7, 1, 1, 1, 1};
    case '8': return {7, 5, 7, 5, 7};
    case '9': return {7, 5, 7, 1, 7};
    case '+': return {0, 2, 7, 2, 0};
    case ':': return {0, 2, 0, 2, 0};
    case '\'': return {2, 2, 0, 0, 0};
    case 'A': return {2, 5, 7, 5, 5};
    case 'B': return {6, 5, 6, 5, 6};
    case 'C': return {3, 4, 4, 4, 3};
    case 'D': return {6, 5, 5, 5, 6};
    case 'E': return {7, 4, 6, 4, 7};
    case 'F': return {7, 4, 6, 4, 4};
    case 'G': return {3, 4, 5, 5, 3};
    case 'H': return {5, 5, 7, 5, 5};
    case 'I': return {7, 2, 2, 2, 7};
    case 'J': return {1, 1, 1, 5, 2};
    case 'K': return {5, 5, 6, 5, 5};
    case 'L': return {4, 4, 4, 4, 7};
    case 'M': return {5, 7, 7, 5, 5};
    case 'N': return {6, 5, 5, 5, 5};
    case 'O': return {2, 5, 5, 5, 2};
    case 'P': return {6, 5, 6, 4, 4};
    case 'Q': return {2, 5, 5, 6, 3};
    case 'R': return {6, 5, 6, 5, 5};
    case 'S': return {3, 4, 2, 1, 6};
    case 'T': return {7, 2, 2, 2, 2};
    case 'U': return {5, 5, 5, 5, 7};
    case 'V': return {5, 5, 5, 5, 2};
    case 'W': return {5, 5, 7, 7, 5};
    case 'X': return {5, 5, 2, 5, 5};
    case 'Y': return {5, 5, 2, 2, 2};
    case 'Z': return {7, 1, 2, 4, 7};
    default: return {0, 0, 0, 0, 0};  // a space
    }
}

std::string_view legendCharacters() { return "0123456789+:'ABCDEFGHIJKLMNOPQRSTUVWXYZ"; }

std::string heatMapLegendTitle(std::string_view technique)
{
    std::string title = "LIGHT EVALUATIONS PER PIXEL: " + std::string(countedLights(technique));
    std::transform(title.begin(), title.end(), title.begin(),
                   [](char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); });
    return title;
}

LegendTitlePlace heatMapLegendTitlePlace(int width, int height)
{
    const LegendArea area = heatMapLegendArea(width, height);
    const int scale = std::max(1, height / kRowsPerScale);
    return {area.x + kPadding * scale, area.y + kPadding * scale, scale};
}

LegendArea heatMapLegendArea(int width, int height)
{
    const int scale = std::max(1, height / kRowsPerScale);
    const LegendArea area{kMargin * scale, height - (kMargin + kPanelHeight) * scale, kPanelWidth * scale,
                          kPanelHeight * scale};
    if (area.x + area.width + kMargin * scale > width || area.height * 4 > height)
        return {};
    return area;
}

void drawHeatMapLegend(Image& shown, float maximum, std::string_view title)
{
    ML_ASSERT(static_cast<int>(title.size()) <= kMaxTitleChars);
    const LegendArea area = heatMapLegendArea(shown.width, shown.height);
    if (area.isEmpty())
        return;
    const int scale = std::max(1, shown.height / kRowsPerScale);
    const Canvas canvas{shown, area.x, area.y, scale};
    const float grey[3] = {kPanelGrey, kPanelGrey, kPanelGrey};
    canvas.fill(0, 0, kPanelWidth, kPanelHeight, grey);

    canvas.text(kPadding, kPadding, std::string(title));

    // The bar, sampled at each column's centre on the heat map's logarithmic scale.
    const int barX = kPadding;
    const int barY = kBarY;
    for (int column = 0; column < kBarWidth; ++column) {
        const float stop = (static_cast<float>(column) + 0.5f) / kBarWidth * float(kStops - 1);
        const float count = std::exp2(2.0f * (stop - 1.0f));  // the inverse of scalePosition
        float rgb[3];
        heatMapColour(count, rgb);
        canvas.fill(barX + column, barY, 1, kBarHeight, rgb);
    }

    // The stops' labels, centred under their places and kept inside the panel.
    const int labelY = barY + kBarHeight + kLabelGap;
    for (int k = 0; k < kStops; ++k) {
        const int centre = barX + k * (kBarWidth - 1) / (kStops - 1);
        const std::string label = kStopLabels[k];
        const int x = std::clamp(centre - textWidth(label) / 2, kPadding, kPanelWidth - kPadding - textWidth(label));
        canvas.text(x, labelY, label);
    }

    // The frame's maximum: a white mark just above the bar at its place, and "MAX N" beside the bar.
    const float white[3] = {1.0f, 1.0f, 1.0f};
    const int markX = barX + static_cast<int>(std::lround(scalePosition(maximum) * float(kBarWidth - 1)));
    canvas.fill(markX, kMarkY, 1, kMarkHeight, white);
    const long long rounded = std::llround(std::min(maximum, 9'999'999.0f));
    canvas.text(barX + kBarWidth + 3 * kGlyphAdvance, barY + (kBarHeight - kGlyphHeight) / 2,
                "MAX " + std::to_string(std::max(0LL, rounded)));
}

void drawLightCountLegend(Image& shown, const Image& counts, std::string_view technique)
{
    float maximum = 0.0f;
    for (std::size_t i = 0; i < counts.rgb.size(); i += 3)
        maximum = std::max(maximum, counts.rgb[i]);
    drawHeatMapLegend(shown, maximum, heatMapLegendTitle(technique));
}

}  // namespace manylights
