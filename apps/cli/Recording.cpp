#include "apps/cli/Recording.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "apps/cli/Progress.h"
#include "core/Numbers.h"

namespace manylights {

namespace {

bool parseSeconds(const std::string& text, double& value)
{
    if (text.empty())
        return false;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    return error == std::errc{} && stop == end && std::isfinite(value);
}

// Where the conversion of a checked pattern is: [first, last) and its width (0: none).
struct Conversion {
    std::size_t first = 0;
    std::size_t last = 0;
    int width = 0;
};

// Scans `pattern`; returns the problem, or fills `conversion`.
std::string scanPattern(const std::string& pattern, Conversion& conversion)
{
    int conversions = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%')
            continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        int width = 0;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            if (j < pattern.size() && pattern[j] >= '1' && pattern[j] <= '9')
                width = pattern[j++] - '0';
            else
                return "the output pattern's %0 must be followed by a width 1-9 and 'd' (as in %04d), in '" + pattern +
                       "'";
        }
        if (j >= pattern.size() || pattern[j] != 'd')
            return "the output pattern may only hold %d, %0Nd or %%, in '" + pattern + "'";
        ++conversions;
        conversion = {i, j + 1, width};
        i = j;
    }
    if (conversions != 1)
        return "the output pattern needs exactly one frame number (%d or %0Nd, e.g. frames/%04d.png), got " +
               std::to_string(conversions) + " in '" + pattern + "'";
    return {};
}

}  // namespace

std::string parseTimeRange(const std::string& text, TimeRange& range)
{
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos || !parseSeconds(text.substr(0, colon), range.start) ||
        !parseSeconds(text.substr(colon + 1), range.end))
        return "--time-range must be START:END in seconds (e.g. 0:4), got '" + text + "'";
    if (range.start < 0.0)
        return "--time-range must start at 0 or later, got '" + text + "'";
    if (!(range.end > range.start))
        return "--time-range must end after it starts, got '" + text + "'";
    if (range.end > kMaxSceneSeconds)
        return "--time-range must end by " + formatNumber(kMaxSceneSeconds) + " seconds, got '" + text + "'";
    return {};
}

namespace {

// The frame count in double, where any range and fps fit: checked before it becomes an int.
// A hair below the product, so that 0:2 at 30 fps is exactly 60 frames despite rounding.
double frameCountOf(const TimeRange& range, double fps)
{
    return std::max(1.0, std::ceil((range.end - range.start) * fps - 1e-9));
}

}  // namespace

std::string checkRecordingFrameCount(const TimeRange& range, double fps)
{
    const double frames = frameCountOf(range, fps);
    if (!(frames <= kMaxFrameCount))
        return "--time-range at --fps " + formatNumber(fps) + " is " + formatNumber(frames) + " frames; at most " +
               formatNumber(kMaxFrameCount) + " can be recorded";
    return {};
}

int recordingFrameCount(const TimeRange& range, double fps) { return static_cast<int>(frameCountOf(range, fps)); }

double recordingFrameTime(const TimeRange& range, double fps, int frame) { return range.start + frame / fps; }

std::string checkFramePattern(const std::string& pattern)
{
    Conversion conversion;
    return scanPattern(pattern, conversion);
}

std::string formatFramePath(const std::string& pattern, int frame)
{
    Conversion conversion;
    scanPattern(pattern, conversion);
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < conversion.width)
        number.insert(0, static_cast<std::size_t>(conversion.width) - number.size(), '0');
    std::string path;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (i == conversion.first) {
            path += number;
            i = conversion.last - 1;
        } else if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') {
            path += '%';
            ++i;
        } else {
            path += pattern[i];
        }
    }
    return path;
}

void printRecordingProgress(ProgressLine& progress, int done, int total)
{
    const int step = std::max(1, total / 10);
    if (done > 0 && (done % step == 0 || done == total))
        progress.log("recorded " + std::to_string(done) + "/" + std::to_string(total) + " frames");
    constexpr int kBarWidth = 30;
    const int filled = total > 0 ? static_cast<int>(static_cast<long long>(done) * kBarWidth / total) : kBarWidth;
    std::string bar(static_cast<std::size_t>(filled), '=');
    if (filled < kBarWidth)
        bar += '>';
    bar.resize(kBarWidth, ' ');
    progress.show("[" + bar + "] " + std::to_string(done) + "/" + std::to_string(total) + " frames");
    if (done == total)
        progress.endLine();
}

}  // namespace manylights
