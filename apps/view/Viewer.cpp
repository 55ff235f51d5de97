// The viewer (docs/viewer.md): a GLFW window drawing the Renderer's image each frame, the
// Dear ImGui panels that change its RendererDesc, camera controls, scripted runs for the tests,
// and shader reloading from --shader-dir.
#include "apps/view/Viewer.h"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "apps/cli/CommandSupport.h"
#include "apps/view/CameraControls.h"
#include "apps/view/ViewScript.h"
#include "core/Error.h"
#include "gl/ShaderSource.h"
#include "gl/VertexArray.h"
#include "platform/HeadlessContext.h"
#include "platform/window/WindowContext.h"
#include "render/Renderer.h"
#include "scene/LightSets.h"

namespace manylights {

namespace {

namespace fs = std::filesystem;

// Camera speeds, per second of wall time with a key held.
constexpr float kOrbitDegreesPerSecond = 60.0f;
constexpr float kDollyPerSecond = 1.5f;        // distance factor per second
constexpr float kFlyFractionPerSecond = 0.4f;  // of the distance to the look-at point
constexpr float kMouseDegreesPerPixel = 0.2f;
// A scripted `key` press acts as the key held for this long.
constexpr double kScriptKeySeconds = 1.0 / 30.0;
constexpr std::size_t kFrameHistory = 240;
constexpr double kShaderCheckSeconds = 0.5;

std::string readTextFile(const std::string& path, const char* what)
{
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw Error(path + ": cannot open " + what);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// Every shader file under `directory` with its modification time.
std::map<std::string, fs::file_time_type> shaderTimes(const std::string& directory)
{
    std::map<std::string, fs::file_time_type> times;
    std::error_code error;
    for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
        std::error_code statError;
        if (it->is_regular_file(statError))
            times[it->path().string()] = it->last_write_time(statError);
    }
    return times;
}

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

namespace {

class Viewer {
public:
    explicit Viewer(const ViewOptions& options);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    void run();
    // "GL_RENDERER (GL_VERSION) via GLFW".
    const std::string& contextDescription() const { return window_.description(); }

private:
    static Viewer& of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

    Technique& technique();
    // The renderer's settings as the viewer's state has them (the one route they take).
    RendererDesc rendererDesc() const;
    void onKeyPressed(int key);
    // The seeds' keymaps (docs/viewer.md): true when `key` is one of theirs.
    bool onDeferredCourseKey(int key);
    bool onStencilVolumesKey(int key);
    // Prints the command-line options of the camera on screen (stdout), so that a view found
    // here can be rendered with `manylights render ... --eye ... --look-at ...`.
    void printCamera() const;
    void applyHeldKeys(const std::vector<int>& keys, double seconds);
    std::vector<int> heldKeys() const;
    void runScript();
    void checkShaders();
    void reloadShaders();
    void resizeIfNeeded();
    void renderScene();
    void showImage();
    void drawAxes();
    void writeScreenshot(const std::string& path);
    void drawPanel();
    std::string effectiveTechnique() const { return wireframe_ ? "forward" : techniqueName_; }

    ViewOptions options_;
    const Scene scene_;
    std::vector<Light> lights_;
    WindowContext window_;
    std::unique_ptr<Renderer> renderer_;
    int width_ = 1;  // the window's framebuffer, which frames are rendered at
    int height_ = 1;
    std::string techniqueName_;
    // The last technique drawn with, and whether it counted its work (a technique whose
    // shaders fail to compile falls back on it).
    std::string lastGoodTechnique_;
    bool lastGoodCounted_ = false;
    ViewMode view_ = ViewMode::Final;
    Camera camera_;                      // the scene's, then moved by keys and the mouse
    AmbientOcclusion ambientOcclusion_;  // the scene's, then edited in the panel

    double time_ = 0.0;
    bool paused_ = false;
    float speed_ = 1.0f;
    bool ambient_ = true;
    bool diffuse_ = true;
    bool specular_ = true;
    bool axes_ = false;
    bool wireframe_ = false;
    bool panel_ = true;
    bool rotating_ = false;           // stencil-volumes 'r': the camera orbits the look-at point
    bool directionalShadows_ = true;  // where the scene's directional light asks for them
    int shadowLights_ = 0;            // local lights with shadow maps (--shadow-lights)
    bool quit_ = false;
    // The display settings (the scene's, then the command line's; the panel edits them).
    // With auto-exposure the exposure follows the lit image's log-average luminance, adapting
    // over about a second as an eye does, instead of the slider's.
    DisplaySettings display_;
    bool autoExposure_ = false;
    float adaptedExposure_ = 0.0f;
    double frameSeconds_ = 0.0;  // wall time since the previous frame
    void adaptExposure();

    std::deque<float> frameMs_;
    FrameSample lastSample_;

    gl::Texture2D displayTexture_;
    gl::Framebuffer displayFramebuffer_;
    gl::Program axesProgram_;
    gl::VertexArray emptyVertexArray_{"axes (no attributes)"};

    bool dragging_ = false;
    double dragX_ = 0.0;
    double dragY_ = 0.0;

    std::string shaderDirectory_;
    std::map<std::string, fs::file_time_type> shaderTimes_;
    double lastShaderCheck_ = 0.0;
    std::string shaderStatus_;
    std::string shaderError_;

    std::vector<ScriptCommand> script_;
    std::size_t scriptNext_ = 0;
    long scriptFramesLeft_ = 0;
    std::string pendingScreenshot_;
    std::vector<int> scriptKeys_;  // keys a script holds for this frame
    std::string lastMessage_;
};

Scene loadScene(const ViewOptions& options)
{
    return loadSceneForCommand(options.scenePath, options.strict, options.camera);
}

Viewer::Viewer(const ViewOptions& options)
    : options_(options),
      scene_(loadScene(options)),
      window_({options.size.width, options.size.height, "manylights — " + scene_.source, defaultDebugContext()}),
      techniqueName_(options.technique),
      view_(*parseViewMode(options.view)),
      camera_(scene_.camera),
      ambientOcclusion_(scene_.ssao),
      time_(options.time)
{
    lights_ = lightsForCommand(scene_, options.lights);
    if (!options.scriptPath.empty())
        script_ = parseViewScript(readTextFile(options.scriptPath, "script"), options.scriptPath);

    if (!options.shaderDirectory.empty() && fs::is_directory(options.shaderDirectory)) {
        shaderDirectory_ = options.shaderDirectory;
        // Files on disk first; a file missing there (a partial copy) comes from the binary.
        gl::ShaderFileReader disk = gl::directoryShaderReader(shaderDirectory_);
        gl::ShaderFileReader embedded = gl::embeddedShaderReader();
        gl::setDefaultShaderReader([disk, embedded](const std::string& name) {
            if (auto text = disk(name))
                return text;
            return embedded(name);
        });
        shaderTimes_ = shaderTimes(shaderDirectory_);
        shaderStatus_ = "watching " + shaderDirectory_;
    } else {
        shaderStatus_ = "embedded shaders (no --shader-dir): no reload";
    }

    glfwGetFramebufferSize(window_.window(), &width_, &height_);
    width_ = std::max(width_, 1);
    height_ = std::max(height_, 1);
    display_ = chooseDisplay(scene_, options.display);
    adaptedExposure_ = display_.exposure;
    renderer_ = std::make_unique<Renderer>(scene_, lights_, rendererDesc());
    axesProgram_ = gl::Program("axes", {{GL_VERTEX_SHADER, "axes.vert"}, {GL_FRAGMENT_SHADER, "axes.frag"}});

    GLFWwindow* window = window_.window();
    glfwSetWindowUserPointer(window, this);
    // Installed before ImGui's, which chains to them.
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureKeyboard)
            of(w).onKeyPressed(key);
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
        Viewer& viewer = of(w);
        if (button != GLFW_MOUSE_BUTTON_LEFT)
            return;
        viewer.dragging_ = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
        glfwGetCursorPos(w, &viewer.dragX_, &viewer.dragY_);
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        Viewer& viewer = of(w);
        if (!viewer.dragging_)
            return;
        lookCamera(viewer.camera_, -kMouseDegreesPerPixel * static_cast<float>(x - viewer.dragX_),
                   -kMouseDegreesPerPixel * static_cast<float>(y - viewer.dragY_));
        viewer.dragX_ = x;
        viewer.dragY_ = y;
    });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

Viewer::~Viewer()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    gl::setDefaultShaderReader(gl::embeddedShaderReader());
}

RendererDesc Viewer::rendererDesc() const
{
    DisplaySettings shown = display_;
    if (autoExposure_)
        shown.exposure = adaptedExposure_;
    return {.width = width_,
            .height = height_,
            .countWork = view_ == ViewMode::LightCount,
            .shadowLights = shadowLights_,
            .directionalShadows = directionalShadows_,
            .ambientOcclusion = ambientOcclusion_,
            .lightingTerms = {ambient_ ? 1.0f : 0.0f, diffuse_ ? 1.0f : 0.0f, specular_ ? 1.0f : 0.0f},
            .display = shown,
            .wireframe = wireframe_,
            .driverProfile = options_.driver.profile};
}

// The technique to draw with (the renderer makes each variant once). A technique whose
// shaders fail to compile (edited under --shader-dir) is not switched to: the previous one
// stays, the error shows.
Technique& Viewer::technique()
{
    const std::string name = effectiveTechnique();
    try {
        Technique& technique = renderer_->technique(name);
        lastGoodTechnique_ = name;
        lastGoodCounted_ = renderer_->desc().countWork;
        return technique;
    } catch (const Error& error) {
        if (lastGoodTechnique_.empty())
            throw;  // the first technique: nothing to fall back on
        shaderError_ = error.what();
        std::fprintf(stderr, "manylights view: cannot switch to %s: %s\n", name.c_str(), error.what());
        // Back to the settings that made the last good technique.
        techniqueName_ = lastGoodTechnique_;
        wireframe_ = false;
        if (lastGoodCounted_)
            view_ = ViewMode::LightCount;
        else if (view_ == ViewMode::LightCount)
            view_ = ViewMode::Final;
        renderer_->apply(rendererDesc());
        return renderer_->technique(lastGoodTechnique_);
    }
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
// lighting, 'p'/'o'/'i' ambient, diffuse, specular, 'q' quit. ('c', lighting the volumes'
// corners only, has no counterpart here: docs/viewer.md says so.)
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
    case GLFW_KEY_C: lastMessage_ = "c: lighting the volumes' corners only is not drawn by manylights"; return true;
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
            if (!fs::exists(name)) {
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
            if (!fs::exists(command.words[0])) {
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

void Viewer::checkShaders()
{
    if (shaderDirectory_.empty() || glfwGetTime() - lastShaderCheck_ < kShaderCheckSeconds)
        return;
    lastShaderCheck_ = glfwGetTime();
    auto times = shaderTimes(shaderDirectory_);
    if (times == shaderTimes_)
        return;
    shaderTimes_ = std::move(times);
    reloadShaders();
}

// A new renderer and technique from the edited files, swapped in only once they have drawn a
// frame: a shader that fails to compile or link leaves the old programs running.
void Viewer::reloadShaders()
{
    try {
        auto renderer = std::make_unique<Renderer>(scene_, lights_, rendererDesc());
        renderer->setCamera(camera_);
        renderer->setTime(time_);
        renderer->renderFrame(effectiveTechnique(), view_);
        renderer_ = std::move(renderer);
        lastGoodTechnique_ = effectiveTechnique();
        lastGoodCounted_ = renderer_->desc().countWork;
        shaderError_.clear();
        shaderStatus_ = "reloaded from " + shaderDirectory_;
        std::fprintf(stderr, "manylights view: shaders reloaded\n");
    } catch (const Error& error) {
        shaderError_ = error.what();
        std::fprintf(stderr, "manylights view: shader reload failed, keeping the old programs: %s\n", error.what());
    }
}

void Viewer::resizeIfNeeded()
{
    int width = 0;
    int height = 0;
    glfwGetFramebufferSize(window_.window(), &width, &height);
    if (width <= 0 || height <= 0)  // minimised
        return;
    // The next frame's desc resizes the G-buffer and every size-dependent target.
    width_ = width;
    height_ = height;
}

void Viewer::adaptExposure()
{
    if (!autoExposure_ || lastSample_.passes.empty())  // no frame yet to measure
        return;
    // Reinhard et al. 2002's key: the log-average maps to middle grey, 0.18.
    const float average = renderer_->logAverageLuminance();
    const float target = std::clamp(std::log2(0.18f / std::max(average, 1e-6f)), -kMaxExposureStops, kMaxExposureStops);
    constexpr double kAdaptationSeconds = 0.7;  // time constant of the exponential approach
    const auto step = static_cast<float>(1.0 - std::exp(-frameSeconds_ / kAdaptationSeconds));
    adaptedExposure_ += (target - adaptedExposure_) * step;
}

void Viewer::renderScene()
{
    adaptExposure();
    renderer_->apply(rendererDesc());
    renderer_->setCamera(camera_);
    renderer_->setTime(time_);
    Technique& current = technique();
    lastSample_ = renderer_->renderFrame(current, view_);
    frameMs_.push_back(static_cast<float>(lastSample_.wallMs));
    if (frameMs_.size() > kFrameHistory)
        frameMs_.pop_front();
}

// The frame into the window: the displayed picture (the display pass's, or the lit image as
// it is where the settings are the identity: the 8-bit window clamps it exactly as the PNG
// writer does), or the view's displayable image as `render --view` writes it.
void Viewer::showImage()
{
    const int width = renderer_->width();
    const int height = renderer_->height();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    if (view_ == ViewMode::Final || view_ == ViewMode::Volumes) {
        glBlitNamedFramebuffer(renderer_->displayedFramebuffer()->id(), 0, 0, 0, width, height, 0, 0, width, height,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return;
    }
    const Image shown = displayableView(renderer_->readColour(), view_, renderer_->readCoverage());
    if (displayTexture_.width() != width || displayTexture_.height() != height) {
        displayTexture_ = gl::Texture2D("viewer display", GL_RGBA8, width, height);
        displayFramebuffer_ = gl::Framebuffer("viewer display", {&displayTexture_}, nullptr);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    displayTexture_.write(GL_RGB, GL_FLOAT, shown.rgb.data());
    // Image rows run top to bottom, GL's bottom to top: the blit flips them.
    glBlitNamedFramebuffer(displayFramebuffer_.id(), 0, 0, 0, width, height, 0, height, width, 0, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
}

void Viewer::drawAxes()
{
    if (!axes_)
        return;
    renderer_->gpuScene().bind();
    glDisable(GL_DEPTH_TEST);
    axesProgram_.set(0, 0.25f * glm::distance(camera_.eye, camera_.lookAt));
    axesProgram_.use();
    emptyVertexArray_.bind();
    glDrawArrays(GL_LINES, 0, 6);
    glEnable(GL_DEPTH_TEST);
}

// The window's back buffer as drawn so far (the scene and the axes; the panel comes after).
void Viewer::writeScreenshot(const std::string& path)
{
    const int width = renderer_->width();
    const int height = renderer_->height();
    std::vector<unsigned char> bytes(static_cast<std::size_t>(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(bytes.size());
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y)
        for (std::size_t i = 0; i < row; ++i)
            image.rgb[static_cast<std::size_t>(y) * row + i] =
                static_cast<float>(bytes[static_cast<std::size_t>(height - 1 - y) * row + i]) / 255.0f;
    writePng(image, path);
    lastMessage_ = "wrote " + path;
    std::fprintf(stderr, "manylights view: wrote %s\n", path.c_str());
}

void Viewer::drawPanel()
{
    ImGui::SetNextWindowPos({10, 10}, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize({330, 0}, ImGuiCond_FirstUseEver);
    ImGui::Begin("manylights (F1 hides)");
    // Sliders and combos leave room on their right for the longest of their labels, so that
    // none is cut at the panel's edge.
    ImGui::PushItemWidth(-(ImGui::CalcTextSize("shadowed lights").x + ImGui::GetStyle().ItemInnerSpacing.x));
    ImGui::Text("%s", scene_.source.c_str());
    ImGui::Text("%dx%d, %zu lights, %zu objects", renderer_->width(), renderer_->height(), lights_.size(),
                scene_.objects.size());

    const std::vector<std::string>& names = techniqueNames();
    if (ImGui::BeginCombo("technique", techniqueName_.c_str())) {
        for (const std::string& name : names)
            if (ImGui::Selectable(name.c_str(), name == techniqueName_))
                techniqueName_ = name;
        ImGui::EndCombo();
    }
    const std::string viewName(viewModeName(view_));
    if (ImGui::BeginCombo("view", viewName.c_str())) {
        for (const std::string& name : viewModeNames())
            if (ImGui::Selectable(name.c_str(), name == viewName))
                view_ = *parseViewMode(name);
        ImGui::EndCombo();
    }
    ImGui::Checkbox("ambient", &ambient_);
    ImGui::SameLine();
    ImGui::Checkbox("diffuse", &diffuse_);
    ImGui::SameLine();
    ImGui::Checkbox("specular", &specular_);
    ImGui::Checkbox("axes (X)", &axes_);
    ImGui::SameLine();
    ImGui::Checkbox("wireframe (L)", &wireframe_);

    ImGui::Separator();
    ImGui::Checkbox("directional shadows", &directionalShadows_);
    ImGui::SliderInt("shadowed lights", &shadowLights_, 0, kMaxShadowLights);
    AmbientOcclusion& occlusion = ambientOcclusion_;
    ImGui::Checkbox("SSAO", &occlusion.enabled);
    ImGui::SliderFloat("SSAO radius", &occlusion.radius, 0.05f, 4.0f, "%.2f");
    ImGui::SliderFloat("SSAO strength", &occlusion.strength, 0.0f, 2.0f, "%.2f");

    if (ImGui::Button("print camera (C)"))
        printCamera();

    ImGui::Separator();
    ImGui::Checkbox("auto exposure", &autoExposure_);
    if (autoExposure_) {
        ImGui::SameLine();
        ImGui::Text("%+.2f EV", adaptedExposure_);
    } else {
        ImGui::SliderFloat("exposure (EV)", &display_.exposure, -8.0f, 8.0f, "%+.2f");
    }
    const std::string curveName(toneCurveName(display_.toneCurve));
    if (ImGui::BeginCombo("tone curve", curveName.c_str())) {
        for (const std::string& name : toneCurveNames())
            if (ImGui::Selectable(name.c_str(), name == curveName))
                display_.toneCurve = *parseToneCurve(name);
        ImGui::EndCombo();
    }
    ImGui::Checkbox("sRGB", &display_.srgb);
    ImGui::SameLine();
    bool fxaa = display_.antialiasing == Antialiasing::Fxaa;
    if (ImGui::Checkbox("FXAA", &fxaa))
        display_.antialiasing = fxaa ? Antialiasing::Fxaa : Antialiasing::None;

    ImGui::Separator();
    ImGui::Checkbox("pause (P)", &paused_);
    ImGui::SameLine();
    ImGui::Text("t = %.2f s", time_);
    ImGui::SliderFloat("speed", &speed_, 0.0f, 4.0f, "%.2fx");

    ImGui::Separator();
    std::vector<float> history(frameMs_.begin(), frameMs_.end());
    const float latest = history.empty() ? 0.0f : history.back();
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.2f ms (%.0f fps)", latest, latest > 0.0f ? 1000.0f / latest : 0.0f);
    ImGui::PlotLines("frame ms", history.data(), static_cast<int>(history.size()), 0, overlay, 0.0f, FLT_MAX, {0, 60});
    if (ImGui::BeginTable("passes", 3)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableSetupColumn("wall ms");
        ImGui::TableHeadersRow();
        for (const PassSample& pass : lastSample_.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(pass.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", pass.gpuMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", pass.wallMs);
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::TextWrapped("shaders: %s", shaderStatus_.c_str());
    if (!shaderError_.empty())
        ImGui::TextColored({1.0f, 0.4f, 0.4f, 1.0f}, "%s", shaderError_.c_str());
    if (!lastMessage_.empty())
        ImGui::TextUnformatted(lastMessage_.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
}

void Viewer::run()
{
    double last = glfwGetTime();
    while (!quit_ && !glfwWindowShouldClose(window_.window())) {
        glfwPollEvents();
        const double now = glfwGetTime();
        const double elapsed = now - last;
        last = now;
        frameSeconds_ = elapsed;
        runScript();
        if (quit_)
            break;
        applyHeldKeys(heldKeys(), elapsed);
        applyHeldKeys(scriptKeys_, kScriptKeySeconds);
        if (rotating_)  // by the script's frame time under a script, so that tests are repeatable
            orbitCamera(camera_,
                        kOrbitDegreesPerSecond * static_cast<float>(script_.empty() ? elapsed : kScriptKeySeconds),
                        0.0f);
        checkShaders();
        resizeIfNeeded();
        if (!paused_)
            time_ += elapsed * speed_;

        renderScene();
        showImage();
        drawAxes();
        if (!pendingScreenshot_.empty()) {
            writeScreenshot(pendingScreenshot_);
            pendingScreenshot_.clear();
        }
        if (panel_) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            drawPanel();
            ImGui::Render();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
        glfwSwapBuffers(window_.window());
    }
}

}  // namespace

namespace {

// --device N in the viewer: the EGL device's renderer, asked before the window exists (listing
// makes and ends a context on every device). Throws manylights::Error for an index that has no
// device.
std::string requestedDeviceRenderer(int index)
{
    const std::vector<EglDeviceInfo> devices = listDevices();
    checkDeviceIndex(index, devices.size());
    return devices[static_cast<std::size_t>(index)].renderer;
}

}  // namespace

void runView(const ViewOptions& options)
{
    const std::string deviceRenderer = options.driver.device ? requestedDeviceRenderer(*options.driver.device) : "";
    Viewer viewer(options);
    if (options.driver.device && viewer.contextDescription().rfind(deviceRenderer, 0) != 0)
        throw Error("--device " + std::to_string(*options.driver.device) + " is " + deviceRenderer +
                    ", but the window's context is " + viewer.contextDescription() +
                    " (the display server chooses the window's GPU)");
    viewer.run();
}

}  // namespace manylights
