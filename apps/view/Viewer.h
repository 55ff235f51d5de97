// `manylights view`: the animated scene in a GLFW window, driven through the same Renderer as
// the CLI, with camera controls, the seeds' keys, a Dear ImGui panel, screenshots, shader hot
// reload and scripted input. docs/viewer.md describes every control.
#pragma once

#include <optional>
#include <string>

#include "apps/cli/CommandSupport.h"
#include "apps/view/Keymaps.h"

namespace manylights {

struct ViewOptions {
    std::string scenePath;               // empty: the built-in default scene
    ImageSize size = kDefaultImageSize;  // the window's
    std::string technique{kDefaultTechnique};
    std::string view = "final";
    std::optional<int> lights;
    double time = 0.0;                // the animation's start time
    std::string scriptPath;           // commands to run (apps/view/ViewScript.h); empty: interactive
    Keymap keymap = Keymap::Default;  // --keymap (apps/view/Keymaps.h)
    bool strict = false;              // --strict: model files' forgiven problems are errors
    CameraOptions camera;             // --camera, --eye, --look-at, --up, --fov-y: the starting view
    DisplayOptions display;           // --exposure, --tonemap, --srgb, --aa: the starting display settings
    ShadowOptions shadows;            // --shadow-lights, --shadow-pool-mib: the starting shadowed lights
    // Shader sources to compile and watch for changes; empty: the embedded shaders, no reload.
    std::string shaderDirectory;
    // --driver-profile, and --device: the window's context is the display server's, so the
    // viewer checks that it runs on that device rather than choosing it (docs/viewer.md).
    DriverOptions driver;
    // The culling's tuning (the environment's: cullingTuningFromEnvironment).
    CullingTuning culling{};
};

// Runs the viewer until the window closes, Escape/Q, or the script's `quit`. Throws
// manylights::Error on a bad scene or script, or when no window can be opened.
void runView(const ViewOptions& options);

// The `view` subcommand's command line (argv[0] is "view"): returns the exit status.
int runViewCommand(int argc, const char* const* argv);

}  // namespace manylights
