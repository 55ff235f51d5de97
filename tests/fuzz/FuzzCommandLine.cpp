// libFuzzer target: what a user types besides scene files. The first byte picks the parser,
// the rest is its text: the check of every numeric option (core/Numbers.h), --size, a
// --time-range with the frame count it gives at a --fps, a recording pattern, --shadow-lights,
// --shadow-pool-mib, and the viewer's script (apps/view/ViewScript.h). Each must either accept
// or explain (an empty problem or a manylights::Error), never crash, overflow or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "apps/cli/OptionText.h"
#include "apps/cli/Recording.h"
#include "apps/view/ViewScript.h"
#include "core/Error.h"
#include "core/Numbers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    using namespace manylights;
    switch (data[0] % 7) {
    case 0: {
        double value = 0.0;
        checkNumber(text, 0.001, 1000.0, value);
        break;
    }
    case 1: {
        ImageSize imageSize;
        parseSize(text, imageSize);
        break;
    }
    case 2: {
        // "RANGE FPS": the frame count is only computed once both passed their checks.
        const std::size_t space = text.find(' ');
        TimeRange range;
        double fps = 0.0;
        if (space != std::string::npos && parseTimeRange(text.substr(0, space), range).empty() &&
            checkNumber(text.substr(space + 1), 0.001, 1000.0, fps).empty() &&
            checkRecordingFrameCount(range, fps).empty()) {
            const int count = recordingFrameCount(range, fps);
            recordingFrameTime(range, fps, count - 1);
        }
        break;
    }
    case 3:
        if (checkFramePattern(text).empty())
            formatFramePath(text, 1234567);
        break;
    case 4: {
        int lights = 0;
        parseShadowLights(text, lights);
        break;
    }
    case 5: {
        int mib = 0;
        parseShadowPoolMiB(text, mib);
        break;
    }
    default: {
        try {
            parseViewScript(text, "fuzz.txt");
        } catch (const Error&) {
        }
        break;
    }
    }
    return 0;
}
