// The light-count view's legend (issue 33, docs/cli.md "Views"): a labelled colour bar drawn
// into the 8-bit image after read-back, as engines' light-complexity views carry one, so that
// a colour can be read as a count: the heat map's stops (0, 1, 4, ... 1024+) under the bar,
// the frame's maximum marked on it and written beside it. `render --no-legend` leaves it out.
#pragma once

#include "render/output/Image.h"

namespace manylights {

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
// 1: narrower than 238 pixels, or lower than 96, four times the legend's height).
LegendArea heatMapLegendArea(int width, int height);

// Draws the legend into `shown` (the heat map, displayableView) for the frame whose counts
// reached `maximum`. Only the pixels of heatMapLegendArea change.
void drawHeatMapLegend(Image& shown, float maximum);

}  // namespace manylights
