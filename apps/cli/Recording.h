// Recording an animation as an image sequence: `render --time-range START:END --fps N -o
// frames/%04d.png`. The parsing here is pure (tested without GL); RenderCommand drives it.
#pragma once

#include <string>

namespace manylights {

class ProgressLine;

struct TimeRange {
    double start = 0.0;
    double end = 0.0;
};

// "START:END" in seconds, 0 ≤ START < END ≤ kMaxSceneSeconds (core/Numbers.h). Returns the problem as one line
// (naming --time-range), or an empty string when `text` is a range; then `range` holds it.
std::string parseTimeRange(const std::string& text, TimeRange& range);

// The frames of [start, end) at `fps`: t_k = start + k / fps for k = 0 .. count − 1, the end
// excluded (so that a looping animation does not show its first frame twice).
// The count must first pass checkRecordingFrameCount.
int recordingFrameCount(const TimeRange& range, double fps);
// "" when the range at `fps` has at most kMaxFrameCount frames, else the problem as one line.
std::string checkRecordingFrameCount(const TimeRange& range, double fps);
double recordingFrameTime(const TimeRange& range, double fps, int frame);

// An output pattern holds exactly one frame-number conversion, %d or %0Nd (N ≤ 9), and may
// hold %% for a literal percent sign. Returns the problem as one line, or an empty string.
std::string checkFramePattern(const std::string& pattern);

// The pattern with its conversion replaced by `frame` (zero-padded to N digits for %0Nd).
std::string formatFramePath(const std::string& pattern, int frame);

// "[=======>      ] 12/48 frames" as `progress`'s status, the line ended after the last frame;
// in a log, "recorded 12/48 frames" at every tenth of the frames.
void printRecordingProgress(ProgressLine& progress, int done, int total);

}  // namespace manylights
