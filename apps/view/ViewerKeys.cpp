// The viewer's keys (docs/viewer.md): the default keymap, the seeds' keymaps, the keys held
// down each frame, and the scripts that press them (apps/view/ViewScript.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

#include "apps/view/CameraControls.h"
#include "apps/view/ViewerWindow.h"
#include "core/Error.h"
#include "render/techniques/Technique.h"

namespace manylights {

namespace {

// The keys the viewer acts on, by the names scripts use.
struct KeyBinding {
    const char* name;
    int key;
};
constexpr KeyBinding kKeys[] = {
    {"left", GLFW_KEY_LEFT},  {"right", GLFW_KEY_RIGHT}, {"up", GLFW_KEY_UP},         {"down", GLFW_KEY_DOWN},
    {"plus", GLFW_KEY_EQUAL}, {"minus", GLFW_KEY_MINUS}, {"w", GLFW_KEY_W},           {"a", GLFW_KEY_A},
    {"s", GLFW_KEY_S},        {"d", GLFW_KEY_D},         {"x", GLFW_KEY_X},           {"l", GLFW_KEY_L},
    {"m", GLFW_KEY_M},        {"t", GLFW_KEY_T},         {"v", GLFW_KEY_V},           {"p", GLFW_KEY_P},
    {"f12", GLFW_KEY_F12},    {"c", GLFW_KEY_C},         {"escape", GLFW_KEY_ESCAPE}, {"q", GLFW_KEY_Q},
    {"r", GLFW_KEY_R},        {"u", GLFW_KEY_U},         {"o", GLFW_KEY_O},           {"i", GLFW_KEY_I},
};

int keyByName(const std::string& name)
{
    for (const KeyBinding& binding : kKeys)
        if (name == binding.name)
            return binding.key;
    ML_ASSERT(false);  // the script parser accepts only these names
    return GLFW_KEY_UNKNOWN;
}

}  // namespace

const std::vector<std::string>& keymapNames()
{
    static const std::vector<std::string> names{"default", "deferred-course", "stencil-volumes"};
    return names;
}

void Viewer::printCamera() const
{
    std::printf("%s\n", cameraCommandLine(camera_).c_str());
    std::fflush(stdout);
}

// The deferred-rendering course project's keys: 'a' axes, 'd' deferred, 't' textured
// forward, 'w' wireframe, '+'/'-' toward and away from the look-at point and the arrows
// rotating the view (both held keys, applyHeldKeys), 'q' quit.
bool Viewer::onDeferredCourseKey(int key)
{
    switch (key) {
    case GLFW_KEY_A: axes_ = !axes_; return true;
    case GLFW_KEY_D:
        techniqueName_ = "deferred";
        wireframe_ = false;
        return true;
    case GLFW_KEY_T:
        techniqueName_ = "forward";
        wireframe_ = false;
        return true;
    case GLFW_KEY_W: wireframe_ = !wireframe_; return true;
    case GLFW_KEY_Q: quit_ = true; return true;
    default: return false;
    }
}

// The stencil light-volume write-up's keys: 'w'/'s' forward and back, 'a'/'d' up and down, the
// arrows look around (held keys, applyHeldKeys), 'r' turns the camera about the look-at point
// until pressed again, 'v' the light volumes, 'u' the volumes in their colours without
// lighting, 'c' the volumes' corners only (the volume-corners view: each volume's vertices as
// points over the lit image, where the write-up shows which corners its volumes have),
// 'p'/'o'/'i' ambient, diffuse, specular, 'q' quit.
bool Viewer::onStencilVolumesKey(int key)
{
    switch (key) {
    case GLFW_KEY_R: rotating_ = !rotating_; return true;
    case GLFW_KEY_V: view_ = view_ == ViewMode::Volumes ? ViewMode::Final : ViewMode::Volumes; return true;
    case GLFW_KEY_U: {
        const bool unlit = view_ == ViewMode::Volumes && !ambient_ && !diffuse_ && !specular_;
        view_ = unlit ? ViewMode::Final : ViewMode::Volumes;
        ambient_ = diffuse_ = specular_ = unlit;
        return true;
    }
    case GLFW_KEY_P: ambient_ = !ambient_; return true;
    case GLFW_KEY_O: diffuse_ = !diffuse_; return true;
    case GLFW_KEY_I: specular_ = !specular_; return true;
    case GLFW_KEY_Q: quit_ = true; return true;
    case GLFW_KEY_W:
    case GLFW_KEY_S:
    case GLFW_KEY_A:
    case GLFW_KEY_D: return true;  // held keys
    case GLFW_KEY_C: view_ = view_ == ViewMode::VolumeCorners ? ViewMode::Final : ViewMode::VolumeCorners; return true;
    default: return false;
    }
}

void Viewer::onKeyPressed(int key)
{
    if (options_.keymap == Keymap::DeferredCourse && onDeferredCourseKey(key))
        return;
    if (options_.keymap == Keymap::StencilVolumes && onStencilVolumesKey(key))
        return;
    const std::vector<std::string>& names = techniqueNames();
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: quit_ = true; break;
    case GLFW_KEY_X: axes_ = !axes_; break;
    case GLFW_KEY_L: wireframe_ = !wireframe_; break;
    case GLFW_KEY_M: techniqueName_ = techniqueName_ == "forward" ? "deferred" : "forward"; break;
    case GLFW_KEY_T: {
        auto it = std::find(names.begin(), names.end(), techniqueName_);
        techniqueName_ = (it == names.end() || it + 1 == names.end()) ? names.front() : *(it + 1);
        break;
    }
    case GLFW_KEY_V: {
        const std::vector<std::string>& views = viewModeNames();
        auto it = std::find(views.begin(), views.end(), std::string(viewModeName(view_)));
        view_ = *parseViewMode((it == views.end() || it + 1 == views.end()) ? views.front() : *(it + 1));
        break;
    }
    case GLFW_KEY_P:
    case GLFW_KEY_SPACE: paused_ = !paused_; break;
    case GLFW_KEY_F12:
    case GLFW_KEY_PRINT_SCREEN: {
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
    case GLFW_KEY_F1: panel_ = !panel_; break;
    case GLFW_KEY_C: printCamera(); break;
    default: break;
    }
}

std::vector<int> Viewer::heldKeys() const
{
    std::vector<int> keys;
    if (ImGui::GetIO().WantCaptureKeyboard)
        return keys;
    for (int key : {GLFW_KEY_LEFT, GLFW_KEY_RIGHT, GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD,
                    GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT, GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D})
        if (glfwGetKey(window_.window(), key) == GLFW_PRESS)
            keys.push_back(key);
    return keys;
}

void Viewer::applyHeldKeys(const std::vector<int>& keys, double seconds)
{
    Camera& camera = camera_;
    const auto dt = static_cast<float>(seconds);
    const float orbit = kOrbitDegreesPerSecond * dt;
    const float fly = kFlyFractionPerSecond * dt * glm::distance(camera.eye, camera.lookAt);
    for (int key : keys) {
        if (options_.keymap == Keymap::DeferredCourse &&
            (key == GLFW_KEY_W || key == GLFW_KEY_A || key == GLFW_KEY_S || key == GLFW_KEY_D))
            continue;  // toggles there (onDeferredCourseKey), not moves
        if (options_.keymap == Keymap::StencilVolumes) {
            switch (key) {
            case GLFW_KEY_W: flyCamera(camera, {0.0f, 0.0f, fly}); break;
            case GLFW_KEY_S: flyCamera(camera, {0.0f, 0.0f, -fly}); break;
            case GLFW_KEY_A: flyCamera(camera, {0.0f, fly, 0.0f}); break;
            case GLFW_KEY_D: flyCamera(camera, {0.0f, -fly, 0.0f}); break;
            case GLFW_KEY_LEFT: lookCamera(camera, -orbit, 0.0f); break;
            case GLFW_KEY_RIGHT: lookCamera(camera, orbit, 0.0f); break;
            case GLFW_KEY_UP: lookCamera(camera, 0.0f, orbit); break;
            case GLFW_KEY_DOWN: lookCamera(camera, 0.0f, -orbit); break;
            default: break;
            }
            continue;
        }
        switch (key) {
        case GLFW_KEY_LEFT: orbitCamera(camera, -orbit, 0.0f); break;
        case GLFW_KEY_RIGHT: orbitCamera(camera, orbit, 0.0f); break;
        case GLFW_KEY_UP: orbitCamera(camera, 0.0f, orbit); break;
        case GLFW_KEY_DOWN: orbitCamera(camera, 0.0f, -orbit); break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD: dollyCamera(camera, std::pow(1.0f / kDollyPerSecond, dt)); break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: dollyCamera(camera, std::pow(kDollyPerSecond, dt)); break;
        case GLFW_KEY_W: flyCamera(camera, {0.0f, 0.0f, fly}); break;
        case GLFW_KEY_S: flyCamera(camera, {0.0f, 0.0f, -fly}); break;
        case GLFW_KEY_A: flyCamera(camera, {-fly, 0.0f, 0.0f}); break;
        case GLFW_KEY_D: flyCamera(camera, {fly, 0.0f, 0.0f}); break;
        default: break;
        }
    }
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
            const int key = keyByName(command.words[0]);
            scriptKeys_.push_back(key);
            onKeyPressed(key);
            return;  // one key per frame, as a person would press them
        }
        case ScriptCommand::Kind::Screenshot: pendingScreenshot_ = command.words[0]; return;
        case ScriptCommand::Kind::Quit: quit_ = true; return;
        }
    }
    // A script that ends without `quit` leaves the window open for a person.
}

}  // namespace manylights
