// The `view` subcommand's command line; main.cpp hands `manylights view ...` here so that the
// CLI library (and the tests linking it) need no GLFW or ImGui.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>

#include "apps/cli/CommandSupport.h"
#include "apps/view/Keymaps.h"
#include "apps/view/Viewer.h"
#include "core/Error.h"
#include "core/Numbers.h"
#include "render/Views.h"
#include "render/techniques/Technique.h"

namespace manylights {

int runViewCommand(int argc, const char* const* argv)
{
    CLI::App app{"manylights view: the scene in a window (docs/viewer.md)", "manylights view"};
    ViewOptions options;
    // The source tree's shaders, when the binary runs where it was built: editing them reloads.
    options.shaderDirectory = MANYLIGHTS_SOURCE_DIR "/shaders";
    app.add_option("scene", options.scenePath, "Scene file (JSON); the built-in default scene if absent");
    addSizeOption(app, options.size, "Window size WxH");
    addTechniqueOption(app, options.technique);
    app.add_option("--view", options.view, "What to show")
        ->check(CLI::IsMember(viewModeNames()))
        ->capture_default_str();
    app.add_option("--time", options.time, "Animation start time in seconds")->check(numberIn(0.0, kMaxSceneSeconds));
    addLightCountOption(app, options.lights);
    app.add_option("--script", options.scriptPath, "Run the commands in this file (docs/viewer.md)");
    // `--keymap list` prints every map's keys, from the tables the viewer reads, and opens no window.
    bool listKeymaps = false;
    std::vector<std::string> keymapChoices = keymapNames();
    keymapChoices.push_back("list");
    app.add_option_function<std::string>(
           "--keymap",
           [&options, &listKeymaps](const std::string& name) {
               listKeymaps = name == "list";
               options.keymap = parseKeymap(name).value_or(Keymap::Default);
           },
           "Which keys do what: default, deferred-course or stencil-volumes; 'list' prints each map's keys "
           "(docs/viewer.md)")
        ->check(CLI::IsMember(keymapChoices));
    app.add_flag("--strict", options.strict, "Treat what model files get forgiven (warnings) as errors");
    addCameraOptions(app, options.camera);
    addDisplayOptions(app, options.display);
    addDriverOptions(app, options.driver);
    addShadowOptions(app, options.shadows);
    app.add_option("--shader-dir", options.shaderDirectory,
                   "Compile shaders from this directory and reload them when they change ('' for the embedded ones)")
        ->capture_default_str();
    if (const std::optional<int> status = parseCommandLine(app, argc, argv))
        return *status;
    if (listKeymaps) {
        std::fputs(keymapListing().c_str(), stdout);
        return 0;
    }
    return reportingErrors(
        [&] {
            options.culling = cullingTuningFromEnvironment();
            runView(options);
        },
        "in the viewer");
}

}  // namespace manylights
