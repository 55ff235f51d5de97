#include "render/HeatMapLegend.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/Error.h"
#include "render/Techniques.h"
#include "render/Views.h"

namespace manylights {

namespace {

constexpr int kGlyphWidth = kLegendGlyphWidth;
constexpr int kGlyphHeight = kLegendGlyphHeight;
constexpr int kGlyphAdvance = kLegendGlyphAdvance;

// A legend's scale: seven stops, evenly spaced on the bar, labelled under it; the colour and
// the bar's position (0 .. 1) of a value.
constexpr int kStops = 7;
struct LegendScale {
    const char* labels[kStops];
    void (*colour)(float value, float rgb[3]);
    float (*position)(float value);
    float (*valueAt)(float position);  // the inverse of position, for sampling the bar
};

// The light-count heat map's (render/Views.h, heatMapColour): stop k ≥ 1 at count 4^(k−1), the
// last (white) at 1024 and above.
float countPosition(float count)
{
    const float stop = count <= 0.0f ? 0.0f : 1.0f + std::log2(count) / 2.0f;
    return std::clamp(stop, 0.0f, float(kStops - 1)) / float(kStops - 1);
}
float countAt(float position) { return std::exp2(2.0f * (position * float(kStops - 1) - 1.0f)); }
constexpr LegendScale kCountScale{{"0", "1", "4", "16", "64", "256", "1024+"}, heatMapColour, countPosition, countAt};

// The shadow-resolution view's (render/Views.h, shadowResolutionColour): a stop per level,
// 1/8 to 8 texels per pixel, 1 in the middle.
float resolutionPosition(float texelsPerPixel)
{
    const float stop = texelsPerPixel <= 0.0f ? 0.0f : 3.0f + std::log2(texelsPerPixel);
    return std::clamp(stop, 0.0f, float(kStops - 1)) / float(kStops - 1);
}
float resolutionAt(float position) { return std::exp2(position * float(kStops - 1) - 3.0f); }
constexpr LegendScale kResolutionScale{
    {"1/8", "1/4", "1/2", "1", "2", "4", "8"}, shadowResolutionColour, resolutionPosition, resolutionAt};

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

// A figure as the legend writes it, in the font's characters (no exponent): two significant
// digits below 10 (0.31, 5.2), whole from 10 (12, 150); at least 0.01.
std::string shortNumber(float value)
{
    char text[32];
    const double shown = std::max(static_cast<double>(value), 0.01);
    std::snprintf(text, sizeof text, shown >= 10.0 ? "%.0f" : "%.2g", shown);
    return text;
}

// The legend in the bottom-left corner: the panel, `title`, the bar of `scale` with its stops'
// labels, a white mark above the bar at each of `marks`, and `beside` (one or two lines: by the
// bar, by the labels) to the bar's right.
void drawLegend(Image& shown, const LegendScale& scale, const std::vector<float>& marks,
                const std::vector<std::string>& beside, std::string_view title);

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
    case '/': return {1, 1, 2, 4, 4};
    case '.': return {0, 0, 0, 0, 2};
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

std::string_view legendCharacters() { return "0123456789+:'/.ABCDEFGHIJKLMNOPQRSTUVWXYZ"; }

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

namespace {
void drawLegend(Image& shown, const LegendScale& scale, const std::vector<float>& marks,
                const std::vector<std::string>& beside, std::string_view title)
{
    ML_ASSERT(static_cast<int>(title.size()) <= kMaxTitleChars && beside.size() <= 2);
    const LegendArea area = heatMapLegendArea(shown.width, shown.height);
    if (area.isEmpty())
        return;
    const int pixelsPerUnit = std::max(1, shown.height / kRowsPerScale);
    const Canvas canvas{shown, area.x, area.y, pixelsPerUnit};
    const float grey[3] = {kPanelGrey, kPanelGrey, kPanelGrey};
    canvas.fill(0, 0, kPanelWidth, kPanelHeight, grey);

    canvas.text(kPadding, kPadding, std::string(title));

    // The bar, sampled at each column's centre on the scale.
    const int barX = kPadding;
    const int barY = kBarY;
    for (int column = 0; column < kBarWidth; ++column) {
        float rgb[3];
        scale.colour(scale.valueAt((static_cast<float>(column) + 0.5f) / kBarWidth), rgb);
        canvas.fill(barX + column, barY, 1, kBarHeight, rgb);
    }

    // The stops' labels, centred under their places and kept inside the panel.
    const int labelY = barY + kBarHeight + kLabelGap;
    for (int k = 0; k < kStops; ++k) {
        const int centre = barX + k * (kBarWidth - 1) / (kStops - 1);
        const std::string label = scale.labels[k];
        const int x = std::clamp(centre - textWidth(label) / 2, kPadding, kPanelWidth - kPadding - textWidth(label));
        canvas.text(x, labelY, label);
    }

    // The marks just above the bar at their places, and the lines beside the bar.
    const float white[3] = {1.0f, 1.0f, 1.0f};
    for (const float value : marks) {
        const int markX = barX + static_cast<int>(std::lround(scale.position(value) * float(kBarWidth - 1)));
        canvas.fill(markX, kMarkY, 1, kMarkHeight, white);
    }
    const int besideX = barX + kBarWidth + 3 * kGlyphAdvance;
    const int besideY[2] = {barY + (kBarHeight - kGlyphHeight) / 2, labelY};
    for (std::size_t line = 0; line < beside.size(); ++line) {
        ML_ASSERT(static_cast<int>(beside[line].size()) <= kMaxLabelChars);
        canvas.text(besideX, besideY[line], beside[line]);
    }
}
}  // namespace

void drawHeatMapLegend(Image& shown, float maximum, std::string_view title)
{
    // The frame's maximum: marked on the bar and written beside it.
    const long long rounded = std::llround(std::min(maximum, 9'999'999.0f));
    drawLegend(shown, kCountScale, {maximum}, {"MAX " + std::to_string(std::max(0LL, rounded))}, title);
}

void drawShadowResolutionLegend(Image& shown, const Image& texelsPerPixel)
{
    // The frame's least and greatest figure over the pixels that have one.
    float least = 0.0f;
    float greatest = 0.0f;
    for (std::size_t i = 0; i < texelsPerPixel.rgb.size(); i += 3) {
        const float value = texelsPerPixel.rgb[i];
        if (value <= 0.0f)
            continue;
        least = least == 0.0f ? value : std::min(least, value);
        greatest = std::max(greatest, value);
    }
    std::vector<float> marks;
    std::vector<std::string> beside{"NONE"};
    if (greatest > 0.0f) {
        marks = {least, greatest};
        beside = {"MIN " + shortNumber(least), "MAX " + shortNumber(std::min(greatest, 9'999'999.0f))};
    }
    drawLegend(shown, kResolutionScale, marks, beside, kShadowResolutionLegendTitle);
}

void drawLightCountLegend(Image& shown, const Image& counts, std::string_view technique)
{
    float maximum = 0.0f;
    for (std::size_t i = 0; i < counts.rgb.size(); i += 3)
        maximum = std::max(maximum, counts.rgb[i]);
    drawHeatMapLegend(shown, maximum, heatMapLegendTitle(technique));
}

void drawViewLegend(Image& shown, const Image& raw, ViewMode view, std::string_view technique)
{
    if (view == ViewMode::LightCount)
        drawLightCountLegend(shown, raw, technique);
    else if (view == ViewMode::ShadowResolution)
        drawShadowResolutionLegend(shown, raw);
}

}  // namespace manylights
