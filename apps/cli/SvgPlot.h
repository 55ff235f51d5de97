// Log-log line plots as a standalone SVG document, written by our own code: `manylights
// bench --plot` needs one chart per image size, and a plotting library (or Python) on every
// machine that benchmarks would be a heavy dependency for that.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace manylights {

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
    // Drawn as a vertical bar from low to high (the spread of the measurements); equal to y
    // for no bar.
    double low = 0.0;
    double high = 0.0;
    std::string note;  // shown when the pointer rests on the point; empty for none
};

struct PlotSeries {
    std::string name;               // in the legend
    std::string colour;             // any SVG colour; paletteColour gives distinguishable ones
    std::vector<PlotPoint> points;  // any order: drawn sorted by x
};

struct PlotPanel {
    std::string title;
    std::vector<PlotSeries> series;
};

struct LogLogPlot {
    std::string xLabel;
    std::string yLabel;
    std::vector<PlotPanel> panels;  // stacked top to bottom in one document
};

// The SVG document (starting with "<svg"): for each panel both axes on log scales spanning
// whole decades, a labelled major tick and grid line per decade and minor ticks at 2..9, one
// polyline and point markers per series, and a legend. Points with x or y ≤ 0 (not on a log
// scale) are left out.
std::string logLogSvg(const LogLogPlot& plot);

// The decades [first, last] (as powers of ten) that a log axis spans to show every value in
// [lo, hi], lo > 0; at least one decade, so a single value gets an axis.
struct DecadeRange {
    int first = 0;
    int last = 1;
};
DecadeRange decadeRange(double lo, double hi);

// The label of the tick at 10^exponent: "0.001" ... "1000" written out, beyond that "10k",
// "100k", "1M", ... and below it "1e-4", ...: short enough for any axis.
std::string decadeLabel(int exponent);

// The index-th of a fixed set of colours that stay distinguishable on white (Tableau 10
// without its yellow); cycles after the last.
std::string paletteColour(std::size_t index);

}  // namespace manylights
