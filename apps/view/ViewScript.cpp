#include "apps/view/ViewScript.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/view/Keymaps.h"
#include "core/Error.h"
#include "core/Numbers.h"
#include "render/TechniqueNames.h"
#include "render/Views.h"

namespace manylights {

namespace {

bool contains(const std::vector<std::string>& names, const std::string& name)
{
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string join(const std::vector<std::string>& names)
{
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

}  // namespace

std::vector<ScriptCommand> parseViewScript(const std::string& text, const std::string& displayName)
{
    std::vector<ScriptCommand> commands;
    std::istringstream lines(text);
    std::string lineText;
    int lineNumber = 0;
    while (std::getline(lines, lineText)) {
        ++lineNumber;
        std::istringstream wordStream(lineText);
        std::vector<std::string> words;
        for (std::string word; wordStream >> word;)
            words.push_back(word);
        if (words.empty() || words[0][0] == '#')
            continue;
        const auto fail = [&](const std::string& what) {
            throw Error(displayName + ":" + std::to_string(lineNumber) + ": " + what);
        };
        const std::string name = words[0];
        std::vector<std::string> args(words.begin() + 1, words.end());
        const auto expectArgs = [&](std::size_t count, const char* usage) {
            if (args.size() != count)
                fail("'" + name + "' takes " + usage);
        };
        ScriptCommand command{ScriptCommand::Kind::Quit, args, 0.0, 0, 0, lineNumber};
        // Every number through the one check of core/Numbers.h, with the limits the viewer can
        // honour (ViewScript.h): a window side drivers' framebuffers take, no more frames than a
        // recording may have, a scene time animations still resolve.
        const auto number = [&](const std::string& word, double lo, double hi, const char* what) {
            double value = 0.0;
            if (const std::string problem = checkNumber(word, lo, hi, value); !problem.empty())
                fail(std::string(what) + " " + problem);
            return value;
        };
        if (name == "frames") {
            expectArgs(1, "a frame count");
            command.kind = ScriptCommand::Kind::Frames;
            command.number = number(args[0], 1.0, kMaxFrameCount, "the frame count");
            if (command.number != std::floor(command.number))
                fail("the frame count must be a whole number, got '" + args[0] + "'");
        } else if (name == "resize") {
            expectArgs(2, "a width and a height");
            command.kind = ScriptCommand::Kind::Resize;
            command.width = static_cast<int>(number(args[0], 1.0, kMaxWindowDimension, "the width"));
            command.height = static_cast<int>(number(args[1], 1.0, kMaxWindowDimension, "the height"));
        } else if (name == "technique") {
            expectArgs(1, "a technique name");
            command.kind = ScriptCommand::Kind::Technique;
            if (!contains(techniqueNames(), args[0]))
                fail("unknown technique '" + args[0] + "' (expected one of: " + join(techniqueNames()) + ")");
        } else if (name == "view") {
            expectArgs(1, "a view name");
            command.kind = ScriptCommand::Kind::View;
            if (!parseViewMode(args[0]))
                fail("unknown view '" + args[0] + "' (expected one of: " + join(viewModeNames()) + ")");
        } else if (name == "time") {
            expectArgs(1, "a time in seconds");
            command.kind = ScriptCommand::Kind::Time;
            command.number = number(args[0], 0.0, kMaxSceneSeconds, "the time");
        } else if (name == "pause" || name == "play" || name == "quit") {
            expectArgs(0, "no arguments");
            command.kind = name == "pause"  ? ScriptCommand::Kind::Pause
                           : name == "play" ? ScriptCommand::Kind::Play
                                            : ScriptCommand::Kind::Quit;
        } else if (name == "speed") {
            expectArgs(1, "a speed factor");
            command.kind = ScriptCommand::Kind::Speed;
            command.number = number(args[0], 0.0, kMaxSpeed, "the speed");
        } else if (name == "toggle") {
            expectArgs(1, "what to toggle");
            command.kind = ScriptCommand::Kind::Toggle;
            const std::vector<std::string> toggles{"ambient",       "diffuse",         "specular",  "axes",
                                                   "wireframe",     "shadows",         "ssao",      "panel",
                                                   "auto-exposure", "panel-collapsed", "panel-keys"};
            if (!contains(toggles, args[0]))
                fail("cannot toggle '" + args[0] + "' (expected one of: " + join(toggles) + ")");
        } else if (name == "key") {
            expectArgs(1, "a key name");
            command.kind = ScriptCommand::Kind::Key;
            if (!contains(scriptKeyNames(), args[0]))
                fail("unknown key '" + args[0] + "' (expected one of: " + join(scriptKeyNames()) + ")");
        } else if (name == "screenshot") {
            expectArgs(1, "a .png file name");
            command.kind = ScriptCommand::Kind::Screenshot;
            if (args[0].size() < 5 || !args[0].ends_with(".png"))
                fail("the screenshot must be a .png file, got '" + args[0] + "'");
        } else if (name == "report-panel") {
            expectArgs(1, "a file name");
            command.kind = ScriptCommand::Kind::ReportPanel;
        } else if (name == "wait-for") {
            expectArgs(1, "a file name");
            command.kind = ScriptCommand::Kind::WaitFor;
        } else {
            fail("unknown command '" + name +
                 "' (expected one of: frames, resize, technique, view, time, pause, play, speed, toggle, key, "
                 "screenshot, report-panel, wait-for, quit)");
        }
        commands.push_back(std::move(command));
    }
    return commands;
}

}  // namespace manylights
