// The viewer's keys (docs/viewer.md): what the key map's actions do (apps/view/Keymaps.h has
// the tables), the keys held down each frame, and the scripts that press them
// (apps/view/ViewScript.h).
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "apps/view/CameraControls.h"
#include "apps/view/ViewerWindow.h"
#include "core/Error.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"

namespace manylights {

void Viewer::printCamera() const
{
    std::printf("%s\n", cameraCommandLine(camera_).c_str());
    std::fflush(stdout);
}

// The actions that act once per press; the held ones move the camera in applyHeldKeys.
void Viewer::perform(KeyAction action)
{
    switch (action) {
    case KeyAction::Quit: quit_ = true; break;
    case KeyAction::ToggleAxes: axes_ = !axes_; break;
    case KeyAction::ToggleWireframe: wireframe_ = !wireframe_; break;
    case KeyAction::ForwardOrDeferred: techniqueName_ = techniqueName_ == "forward" ? "deferred" : "forward"; break;
    case KeyAction::NextTechnique: {
        const std::vector<std::string>& names = techniqueNames();
        auto it = std::find(names.begin(), names.end(), techniqueName_);
        techniqueName_ = (it == names.end() || it + 1 == names.end()) ? names.front() : *(it + 1);
        break;
    }
    case KeyAction::NextView: {
        const std::vector<std::string>& views = viewModeNames();
        auto it = std::find(views.begin(), views.end(), std::string(viewModeName(view_)));
        view_ = *parseViewMode((it == views.end() || it + 1 == views.end()) ? views.front() : *(it + 1));
        break;
    }
    case KeyAction::TogglePause: paused_ = !paused_; break;
    case KeyAction::Screenshot: {
        // Numbered so that repeated presses never overwrite an earlier picture.
        for (int n = 0;; ++n) {
            char name[64];
            std::snprintf(name, sizeof name, "manylights-%03d.png", n);
            if (!std::filesystem::exists(name)) {
                pendingScreenshot_ = name;
                break;
            }
        }
        break;
    }
    case KeyAction::TogglePanel: panel_ = !panel_; break;
    case KeyAction::PrintCamera: printCamera(); break;
    case KeyAction::UseDeferred:
    case KeyAction::UseTexturedForward:
        techniqueName_ = action == KeyAction::UseDeferred ? "deferred" : "forward";
        wireframe_ = false;
        break;
    case KeyAction::ToggleRotation: rotating_ = !rotating_; break;
    case KeyAction::ToggleVolumes: view_ = view_ == ViewMode::Volumes ? ViewMode::Final : ViewMode::Volumes; break;
    case KeyAction::ToggleUnlitVolumes: {
        const bool unlit = view_ == ViewMode::Volumes && !ambient_ && !diffuse_ && !specular_;
        view_ = unlit ? ViewMode::Final : ViewMode::Volumes;
        ambient_ = diffuse_ = specular_ = unlit;
        break;
    }
    case KeyAction::ToggleAmbient: ambient_ = !ambient_; break;
    case KeyAction::ToggleDiffuse: diffuse_ = !diffuse_; break;
    case KeyAction::ToggleSpecular: specular_ = !specular_; break;
    case KeyAction::ToggleVolumeCorners:
        view_ = view_ == ViewMode::VolumeCorners ? ViewMode::Final : ViewMode::VolumeCorners;
        break;
    default: break;  // held: applyHeldKeys
    }
}

void Viewer::onKeyPressed(int key)
{
    if (const std::optional<KeyAction> action = actionOfKey(options_.keymap, key))
        perform(*action);
}

void Viewer::applyHeldKeys(const std::vector<HeldKey>& keys)
{
    for (const HeldKey& held : keys)
        if (const std::optional<KeyAction> action = actionOfKey(options_.keymap, held.key))
            applyHeldAction(camera_, *action, held.seconds);
}

// Runs script commands until one needs frames drawn (frames, screenshot) or the script ends.
void Viewer::runScript()
{
    scriptKeys_.clear();
    if (scriptFramesLeft_ > 0) {
        --scriptFramesLeft_;
        return;
    }
    while (scriptNext_ < script_.size() && !quit_) {
        const ScriptCommand& command = script_[scriptNext_++];
        switch (command.kind) {
        case ScriptCommand::Kind::WaitFor:
            if (!std::filesystem::exists(command.words[0])) {
                --scriptNext_;  // again next frame
                return;
            }
            break;
        case ScriptCommand::Kind::Frames:
            // This frame is the first of them.
            scriptFramesLeft_ = static_cast<long>(command.number) - 1;
            return;
        case ScriptCommand::Kind::Resize: glfwSetWindowSize(window_.window(), command.width, command.height); break;
        case ScriptCommand::Kind::Technique: techniqueName_ = command.words[0]; break;
        case ScriptCommand::Kind::View: view_ = *parseViewMode(command.words[0]); break;
        case ScriptCommand::Kind::Time:
            time_ = command.number;
            paused_ = true;
            break;
        case ScriptCommand::Kind::Pause: paused_ = true; break;
        case ScriptCommand::Kind::Play: paused_ = false; break;
        case ScriptCommand::Kind::Speed: speed_ = static_cast<float>(command.number); break;
        case ScriptCommand::Kind::Toggle: {
            const std::string& what = command.words[0];
            // As a click on the panel's arrow, and on its list of keys, would do.
            if (what == "panel-collapsed" || what == "panel-keys") {
                (what == "panel-collapsed" ? togglePanelCollapsed_ : togglePanelKeys_) = true;
                break;
            }
            bool& flag = what == "ambient"         ? ambient_
                         : what == "diffuse"       ? diffuse_
                         : what == "specular"      ? specular_
                         : what == "axes"          ? axes_
                         : what == "wireframe"     ? wireframe_
                         : what == "shadows"       ? directionalShadows_
                         : what == "ssao"          ? ambientOcclusion_.enabled
                         : what == "auto-exposure" ? autoExposure_
                                                   : panel_;
            flag = !flag;
            break;
        }
        case ScriptCommand::Kind::Key: {
            const int key = scriptKey(command.words[0]);
            ML_ASSERT(key != GLFW_KEY_UNKNOWN);  // the script parser accepts only these names
            scriptKeys_.push_back({key, kScriptKeySeconds});
            onKeyPressed(key);
            return;  // one key per frame, as a person would press them
        }
        case ScriptCommand::Kind::Screenshot: pendingScreenshot_ = command.words[0]; return;
        case ScriptCommand::Kind::ReportPanel: pendingPanelReport_ = command.words[0]; return;
        case ScriptCommand::Kind::Quit: quit_ = true; return;
        }
    }
    // A script that ends without `quit` leaves the window open for a person.
}

}  // namespace manylights
