#include "apps/cli/SvgPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace manylights {

namespace {

// One panel's frame, in SVG user units (pixels at 100%). The legend sits right of the plot
// area, so the curves never hide under it.
constexpr double kPanelWidth = 800.0;
constexpr double kPanelHeight = 420.0;
constexpr double kPlotLeft = 80.0;
constexpr double kPlotRight = 590.0;
constexpr double kPlotTop = 44.0;
constexpr double kPlotBottom = 360.0;
constexpr double kLegendLeft = kPlotRight + 24.0;
constexpr double kLegendRowHeight = 20.0;
constexpr double kMajorTick = 7.0;
constexpr double kMinorTick = 4.0;

// Appends every part in turn. (Chains of "literal" + std::string temporaries trip GCC 12's
// -Wrestrict false positive at -O3, and appending also copies less.)
template <typename... Parts>
void append(std::string& out, const Parts&... parts)
{
    (out += ... += parts);
}

std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    return buffer;
}

std::string escapeXml(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

bool onLogScale(double value) { return value > 0.0 && std::isfinite(value); }

// Maps log10 of a value in [10^first, 10^last] linearly onto [from, to].
struct LogAxis {
    DecadeRange decades;
    double from = 0.0;
    double to = 0.0;

    double map(double value) const { return mapLog(std::log10(value)); }
    double mapLog(double logValue) const
    {
        const double t = (logValue - decades.first) / static_cast<double>(decades.last - decades.first);
        return from + t * (to - from);
    }
};

struct ValueRange {
    double lo = std::numeric_limits<double>::max();
    double hi = 0.0;
    void extend(double value)
    {
        if (!onLogScale(value))
            return;
        lo = std::min(lo, value);
        hi = std::max(hi, value);
    }
    bool empty() const { return hi == 0.0; }
};

void appendLine(std::string& svg, double x1, double y1, double x2, double y2, const std::string& attributes)
{
    append(svg, "<line x1=\"", number(x1), "\" y1=\"", number(y1), "\" x2=\"", number(x2), "\" y2=\"", number(y2),
           "\" ", attributes, "/>\n");
}

void appendText(std::string& svg, double x, double y, const std::string& text, const std::string& attributes = "")
{
    append(svg, "<text x=\"", number(x), "\" y=\"", number(y), "\"");
    if (!attributes.empty())
        append(svg, " ", attributes);
    append(svg, ">", escapeXml(text), "</text>\n");
}

// Grid lines, ticks and labels of both axes.
void appendAxes(std::string& svg, const LogAxis& xAxis, const LogAxis& yAxis)
{
    const std::string majorGrid = "stroke=\"#d0d0d0\" stroke-width=\"1\"";
    const std::string minorGrid = "stroke=\"#f0f0f0\" stroke-width=\"1\"";
    const std::string tick = "stroke=\"#444\" stroke-width=\"1\"";
    for (int decade = xAxis.decades.first; decade <= xAxis.decades.last; ++decade) {
        const double x = xAxis.mapLog(decade);
        appendLine(svg, x, kPlotTop, x, kPlotBottom, majorGrid);
        appendLine(svg, x, kPlotBottom, x, kPlotBottom + kMajorTick, tick);
        appendText(svg, x, kPlotBottom + 22.0, decadeLabel(decade), "text-anchor=\"middle\"");
        for (int m = 2; decade < xAxis.decades.last && m <= 9; ++m) {
            const double minor = xAxis.mapLog(decade + std::log10(m));
            appendLine(svg, minor, kPlotTop, minor, kPlotBottom, minorGrid);
            appendLine(svg, minor, kPlotBottom, minor, kPlotBottom + kMinorTick, tick);
        }
    }
    for (int decade = yAxis.decades.first; decade <= yAxis.decades.last; ++decade) {
        const double y = yAxis.mapLog(decade);
        appendLine(svg, kPlotLeft, y, kPlotRight, y, majorGrid);
        appendLine(svg, kPlotLeft - kMajorTick, y, kPlotLeft, y, tick);
        appendText(svg, kPlotLeft - 10.0, y + 4.0, decadeLabel(decade), "text-anchor=\"end\"");
        for (int m = 2; decade < yAxis.decades.last && m <= 9; ++m) {
            const double minor = yAxis.mapLog(decade + std::log10(m));
            appendLine(svg, kPlotLeft, minor, kPlotRight, minor, minorGrid);
            appendLine(svg, kPlotLeft - kMinorTick, minor, kPlotLeft, minor, tick);
        }
    }
}

void appendPanel(std::string& svg, const PlotPanel& panel, const std::string& xLabel, const std::string& yLabel,
                 double top)
{
    ValueRange xs;
    ValueRange ys;
    for (const PlotSeries& series : panel.series)
        for (const PlotPoint& point : series.points) {
            if (!onLogScale(point.x) || !onLogScale(point.y))
                continue;
            xs.extend(point.x);
            ys.extend(point.y);
            ys.extend(point.low);
            ys.extend(point.high);
        }
    const bool noData = xs.empty();
    // Without data the axes still show one decade each, so the panel keeps its shape.
    const LogAxis xAxis{noData ? DecadeRange{0, 1} : decadeRange(xs.lo, xs.hi), kPlotLeft, kPlotRight};
    const LogAxis yAxis{noData ? DecadeRange{0, 1} : decadeRange(ys.lo, ys.hi), kPlotBottom, kPlotTop};

    append(svg, "<g transform=\"translate(0 ", number(top), ")\">\n");
    appendText(svg, kPlotLeft, 26.0, panel.title, "font-size=\"15\" font-weight=\"bold\"");
    appendAxes(svg, xAxis, yAxis);
    append(svg, "<rect x=\"", number(kPlotLeft), "\" y=\"", number(kPlotTop), "\" width=\"",
           number(kPlotRight - kPlotLeft), "\" height=\"", number(kPlotBottom - kPlotTop),
           "\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\"/>\n");
    appendText(svg, 0.5 * (kPlotLeft + kPlotRight), kPlotBottom + 46.0, xLabel, "text-anchor=\"middle\"");
    const double yMiddle = 0.5 * (kPlotTop + kPlotBottom);
    std::string rotated = "text-anchor=\"middle\" transform=\"rotate(-90 24 ";
    append(rotated, number(yMiddle), ")\"");
    appendText(svg, 24.0, yMiddle, yLabel, rotated);
    if (noData)
        appendText(svg, 0.5 * (kPlotLeft + kPlotRight), yMiddle, "no data", "text-anchor=\"middle\" fill=\"#888\"");

    for (std::size_t s = 0; s < panel.series.size(); ++s) {
        const PlotSeries& series = panel.series[s];
        std::vector<PlotPoint> points;
        for (const PlotPoint& point : series.points)
            if (onLogScale(point.x) && onLogScale(point.y))
                points.push_back(point);
        std::stable_sort(points.begin(), points.end(),
                         [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
        const std::string colour = escapeXml(series.colour);
        // One polyline per series even with fewer than two points, so every series has its
        // element (and its name, in the title) in the document.
        append(svg, "<polyline fill=\"none\" stroke=\"", colour, "\" stroke-width=\"2\" points=\"");
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i)
                svg += ' ';
            append(svg, number(xAxis.map(points[i].x)), ",", number(yAxis.map(points[i].y)));
        }
        append(svg, "\"><title>", escapeXml(series.name), "</title></polyline>\n");
        const std::string thinStroke = "stroke=\"" + colour + "\" stroke-width=\"1.5\"";
        const std::string thickStroke = "stroke=\"" + colour + "\" stroke-width=\"2\"";
        for (const PlotPoint& point : points) {
            const double x = xAxis.map(point.x);
            if (onLogScale(point.low) && onLogScale(point.high) && point.high > point.low)
                appendLine(svg, x, yAxis.map(point.low), x, yAxis.map(point.high), thinStroke);
            append(svg, "<circle cx=\"", number(x), "\" cy=\"", number(yAxis.map(point.y)), "\" r=\"3.5\" fill=\"",
                   colour, "\">");
            if (!point.note.empty())
                append(svg, "<title>", escapeXml(point.note), "</title>");
            svg += "</circle>\n";
        }
        const double legendY = kPlotTop + 10.0 + kLegendRowHeight * static_cast<double>(s);
        appendLine(svg, kLegendLeft, legendY, kLegendLeft + 24.0, legendY, thickStroke);
        append(svg, "<circle cx=\"", number(kLegendLeft + 12.0), "\" cy=\"", number(legendY), "\" r=\"3.5\" fill=\"",
               colour, "\"/>\n");
        appendText(svg, kLegendLeft + 32.0, legendY + 4.0, series.name);
    }
    svg += "</g>\n";
}

}  // namespace

DecadeRange decadeRange(double lo, double hi)
{
    // The epsilon keeps an exact power of ten (log10 may return 2.9999999999999996 for 1000)
    // from widening the axis by a whole empty decade.
    constexpr double kEpsilon = 1e-9;
    DecadeRange range;
    range.first = static_cast<int>(std::floor(std::log10(lo) + kEpsilon));
    range.last = static_cast<int>(std::ceil(std::log10(hi) - kEpsilon));
    if (range.last <= range.first)
        range.last = range.first + 1;
    return range;
}

std::string decadeLabel(int exponent)
{
    if (exponent >= 0 && exponent <= 3)
        return std::to_string(static_cast<int>(std::pow(10, exponent)));
    if (exponent < 0 && exponent >= -3)
        return std::string("0.").append(static_cast<std::size_t>(-exponent - 1), '0').append("1");
    static const char* const suffixes[] = {"k", "M", "G"};
    if (exponent > 3 && exponent < 12) {
        const int group = exponent / 3;  // 1: k, 2: M, 3: G
        return std::to_string(static_cast<int>(std::pow(10, exponent % 3))) + suffixes[group - 1];
    }
    return std::string("1e").append(std::to_string(exponent));
}

std::string paletteColour(std::size_t index)
{
    static const char* const colours[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                          "#b07aa1", "#9c755f", "#ff9da7", "#bab0ac"};
    return colours[index % std::size(colours)];
}

std::string logLogSvg(const LogLogPlot& plot)
{
    const std::size_t panels = std::max<std::size_t>(plot.panels.size(), 1);
    const double height = kPanelHeight * static_cast<double>(panels);
    std::string svg;
    append(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"", number(kPanelWidth), "\" height=\"",
           number(height), "\" viewBox=\"0 0 ", number(kPanelWidth), " ", number(height),
           "\" font-family=\"sans-serif\" font-size=\"12\">\n");
    // An opaque background: viewers with a dark theme would otherwise show black text on black.
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (std::size_t p = 0; p < plot.panels.size(); ++p)
        appendPanel(svg, plot.panels[p], plot.xLabel, plot.yLabel, kPanelHeight * static_cast<double>(p));
    svg += "</svg>\n";
    return svg;
}

}  // namespace manylights
