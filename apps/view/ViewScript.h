// Scripted input for the viewer (`manylights view --script FILE`), so that tests and demos
// drive it without a person: one command per line, run in order, each after the frame
// before it has been drawn. docs/viewer.md lists the commands.
#pragma once

#include <string>
#include <vector>

namespace manylights {

// Limits of the script's numbers (docs/viewer.md): a window side (GL drivers' framebuffer
// limits are 16384 or more), and the animation speed factor.
inline constexpr double kMaxWindowDimension = 16384.0;
inline constexpr double kMaxSpeed = 1000.0;

struct ScriptCommand {
    enum class Kind {
        Frames,       // frames N: draw N frames
        Resize,       // resize W H: resize the window (and so every size-dependent resource)
        Technique,    // technique NAME
        View,         // view NAME
        Time,         // time SECONDS: set the animation time (and pause it there)
        Pause,        // pause
        Play,         // play
        Speed,        // speed FACTOR
        Toggle,       // toggle ambient|...|panel|panel-collapsed|panel-keys (docs/viewer.md)
        Key,          // key NAME: as if the key were pressed for one frame (docs/viewer.md)
        Screenshot,   // screenshot FILE.png: the window's image of the next frame, panel hidden
        ReportPanel,  // report-panel FILE: where the next frame draws the panel (docs/viewer.md)
        WaitFor,      // wait-for FILE: keep drawing frames until FILE exists (to pace a test)
        Quit,         // quit
    };
    Kind kind;
    std::vector<std::string> words;  // the arguments
    double number = 0.0;             // Frames, Time, Speed
    int width = 0;                   // Resize
    int height = 0;
    int line = 0;  // in the script file, for messages
};

// Parses the script's text; blank lines and lines starting with '#' are skipped. Throws
// manylights::Error "FILE:LINE: problem" on the first bad line (unknown command, wrong
// arguments, unknown technique or view, a number out of its range: frames up to
// kMaxFrameCount, time up to kMaxSceneSeconds, sizes up to kMaxWindowDimension).
std::vector<ScriptCommand> parseViewScript(const std::string& text, const std::string& displayName);

}  // namespace manylights
