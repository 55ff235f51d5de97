// The legends of the heat-map views: the light-count view's (issue 33, docs/cli.md "Views") and
// the shadow-resolution view's (issue 47, docs/shadows.md). A labelled colour bar drawn
// into the 8-bit image after read-back, as engines' light-complexity views carry one, so that
// a colour can be read as a count: a title naming what is counted (issue 43: light evaluations
// per pixel, and which lights the technique evaluates), the heat map's stops (0, 1, 4, ...
// 1024+) under the bar, the frame's maximum marked on it and written beside it. `render
// --no-legend` leaves it out; the viewer's views show it too.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "render/Views.h"
#include "render/output/Image.h"

namespace manylights {

// The legend's font: 3 x 5 pixels a character, advancing 4.
inline constexpr int kLegendGlyphWidth = 3;
inline constexpr int kLegendGlyphHeight = 5;
inline constexpr int kLegendGlyphAdvance = kLegendGlyphWidth + 1;
// A character's rows, top first, 3 bits each with the high bit on the left; all zero for a
// space or a character the font lacks.
std::array<unsigned char, kLegendGlyphHeight> legendGlyph(char c);
// The characters the font has, a space aside.
std::string_view legendCharacters();

// The title of the light-count legend for `technique`: "LIGHT EVALUATIONS PER PIXEL: " and the
// lights it counts (countedLights, render/Techniques.h), in capitals.
std::string heatMapLegendTitle(std::string_view technique);

// The rectangle the legend covers (pixels, rows top to bottom); empty when it does not fit.
struct LegendArea {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool isEmpty() const { return width == 0 || height == 0; }
};

// Where the legend goes in an image of `width` x `height`: the bottom-left corner, scaled by
// one pixel per 360 rows (at least 1). Empty when the image is too small to hold it (at scale
// 1: narrower than 238 pixels, or lower than 124, four times the legend's height).
LegendArea heatMapLegendArea(int width, int height);

// Where the title's first character starts (its top-left pixel), and the image pixels per
// font pixel: for reading the title back.
struct LegendTitlePlace {
    int x = 0;
    int y = 0;
    int scale = 1;
};
LegendTitlePlace heatMapLegendTitlePlace(int width, int height);

// Draws the legend into `shown` (the heat map, displayableView) for the frame whose counts
// reached `maximum`, under `title` (56 characters at most). Only the pixels of
// heatMapLegendArea change.
void drawHeatMapLegend(Image& shown, float maximum, std::string_view title);

// The shadow-resolution view's title (docs/shadows.md: the geometric mean over a pixel's
// shadowed lights of the texels per pixel their lookups read).
inline constexpr std::string_view kShadowResolutionLegendTitle = "SHADOW TEXELS PER PIXEL: GEOMETRIC MEAN OF LIGHTS";

// The shadow-resolution view's legend for the frame whose figures (the view's raw image, the
// texels per pixel in red, 0 where no shadowed light reaches) are `texelsPerPixel`: its colour
// bar from 1/8 to 8, a stop per level, the frame's least and greatest figure marked on it and
// written beside it (`MIN 0.5`, `MAX 2.3`; `NONE` where no pixel has one).
void drawShadowResolutionLegend(Image& shown, const Image& texelsPerPixel);

// The legend of `view`'s frame of raw values `raw` (displayableView's input) for `technique`,
// where the view has one (hasLegend: light-count's, shadow-resolution's); what `render` and the
// viewer draw.
void drawViewLegend(Image& shown, const Image& raw, ViewMode view, std::string_view technique);

// The legend of `technique`'s light-count frame whose counts (the view's raw image, a count
// per pixel in red) are `counts`: what `render --view light-count` and the viewer draw.
void drawLightCountLegend(Image& shown, const Image& counts, std::string_view technique);

}  // namespace manylights
