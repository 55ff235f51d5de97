// The viewer's state and its parts, shared by the files that implement them: Viewer.cpp (the
// window, its frames and screenshots), ViewerKeys.cpp (what keys and scripts do; the key maps'
// tables are in Keymaps.h) and ViewerPanel.cpp (the Dear ImGui panel).
#pragma once

#include <cstddef>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>  // before GLFW's header, which would include the system's GL/gl.h
#include <GLFW/glfw3.h>

#include "apps/view/HeldKeys.h"
#include "apps/view/Keymaps.h"
#include "apps/view/ViewScript.h"
#include "apps/view/Viewer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "platform/window/KeyEventTimes.h"
#include "platform/window/WindowContext.h"
#include "render/Renderer.h"

namespace manylights {

// A rectangle in the window's pixels (ImGui's), rows top to bottom.
struct WindowRect {
    float x = 0.0f;
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
};

// What the panel drew in a frame, for the script's report-panel (docs/viewer.md "Scripts";
// issue 48): every piece of text with the rectangle it takes and the right edge it must end
// before (the panel's, a table cell's, a combo's arrow), and the controls drawn disabled with
// the reason their tooltips give.
struct PanelRecord {
    struct Text {
        std::string text;
        WindowRect rect;
        float limit = 0.0f;
        bool fits() const { return rect.x + rect.width <= limit; }
    };
    struct Unavailable {
        std::string control;
        std::string reason;
    };
    std::vector<Text> texts;
    std::vector<Unavailable> unavailable;
};

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
    // The held keys' speeds are in apps/view/CameraControls.h.
    static constexpr float kMouseDegreesPerPixel = 0.2f;
    // A scripted `key` press acts as the key held for this long: a tap's (HeldKeys.h).
    static constexpr double kScriptKeySeconds = kTapSeconds;
    static constexpr std::size_t kFrameHistory = 240;
    static constexpr double kShaderCheckSeconds = 0.5;

    static Viewer& of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

    Technique& technique();
    // The renderer's settings as the viewer's state has them (the one route they take).
    RendererDesc rendererDesc();
    // Reads the window's events (GLFW reads them on the main thread only): at the start of a
    // frame, and while it renders, from the renderer's wait hook (issue 48).
    void readInput();
    // A key pressed: its action in the key map (apps/view/Keymaps.h), if any.
    void onKeyPressed(int key);
    void perform(KeyAction action);
    // Prints the command-line options of the camera on screen (stdout), so that a view found
    // here can be rendered with `manylights render ... --eye ... --look-at ...`.
    void printCamera() const;
    // Moves the camera for the keys held in this frame, each for the time it was held.
    void applyHeldKeys(const std::vector<HeldKey>& keys);
    void runScript();
    void checkShaders();
    void reloadShaders();
    void resizeIfNeeded();
    void renderScene();
    void showImage();
    void drawAxes();
    void writeScreenshot(const std::string& path);
    void drawPanel();
    void drawPanelContents();
    // A widget's label with the keys that do the same in the key map: "pause (Space)".
    std::string keyedLabel(const char* label, KeyAction action) const;
    // For the script's report-panel: the panel as this frame drew it (docs/viewer.md "Scripts").
    void writePanelReport(const std::string& path) const;
    // The panel's environment section (ViewerPanel.cpp): nothing without one.
    void drawEnvironmentPanel();
    // The panel's shadowed lights: their count's slider and the "all lights" box (ViewerPanel.cpp).
    void drawShadowedLights();
    // The panel's narrowest width at which none of its text is cut (ViewerPanel.cpp).
    float minimumExpandedPanelWidth() const;
    // The widest value the shadowed lights' slider shows: its largest count, or "all".
    std::string widestShadowLightCount() const;
    // Where the light-count legend is in the window this frame; none in other views or where
    // the window is too small for it.
    std::optional<WindowRect> shownLegend() const;
    // The wireframe is drawn with forward, in the final view only (Renderer::renderFrame).
    bool showsWireframe() const { return wireframe_ && view_ == ViewMode::Final; }
    std::string effectiveTechnique() const { return showsWireframe() ? "forward" : techniqueName_; }

    ViewOptions options_;
    const Scene scene_;
    std::vector<Light> lights_;
    WindowContext window_;
    KeyEventTimes keyTimes_{window_.window()};  // when the server sent each key event (X11)
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
    // The scene's environment's intensity, rotation and background, then edited in the panel;
    // none without an environment.
    std::optional<EnvironmentLook> environmentLook_;

    double time_ = 0.0;
    bool paused_ = false;
    float speed_ = 1.0f;
    bool ambient_ = true;
    bool diffuse_ = true;
    bool specular_ = true;
    bool axes_ = false;
    bool wireframe_ = false;
    bool panel_ = true;
    // The panel as last drawn, in window pixels (ImGui's), and whether the window was below
    // the size at which it starts collapsed (ViewerPanel.cpp); unset before the first frame.
    struct PanelRect {
        float x = 0.0f;
        float y = 0.0f;
        float width = 0.0f;
        float height = 0.0f;
        bool collapsed = false;
    };
    std::optional<PanelRect> panelRect_;
    std::optional<bool> smallWindow_;
    bool panelDrawn_ = false;  // false where F1 hid it or the window cannot hold even its title
    PanelRecord panelRecord_;
    bool togglePanelCollapsed_ = false;  // the script's `toggle panel-collapsed`
    bool togglePanelKeys_ = false;       // the script's `toggle panel-keys`
    bool rotating_ = false;              // stencil-volumes 'r': the camera orbits the look-at point
    bool directionalShadows_ = true;     // where the scene's directional light asks for them
    // The shadowed lights (--shadow-lights, else the scene's "shadow_lights"; the panel edits them):
    // every light that does not opt out where `allLightsShadowed_`, else the `shadowLightCount_`
    // ranked highest. The slider goes up to `shadowLightLimit_`, the lights there are (or the
    // count asked for, where larger).
    bool allLightsShadowed_ = false;
    int shadowLightCount_ = 0;
    int shadowLightLimit_ = 1;
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

    HeldKeys heldKeys_;  // the window's key presses and releases, by when they came
    // The longest time between two reads of input in the frame so far, when the last was, and
    // for the last whole frame, its length and that longest time (the panel and its report
    // show them).
    double inputGapSeconds_ = 0.0;
    double lastInputRead_ = 0.0;
    struct FrameInput {
        double frameSeconds = 0.0;
        double longestGapSeconds = 0.0;
    };
    FrameInput lastFrameInput_;
    std::vector<int> pressedKeys_;  // pressed since the frame began: their actions run at the next
    bool dragging_ = false;
    double dragX_ = 0.0;
    double dragY_ = 0.0;

    std::string shaderDirectory_;
    std::map<std::string, std::filesystem::file_time_type> shaderTimes_;
    double lastShaderCheck_ = 0.0;
    std::string shaderStatus_;
    std::string shaderError_;

    std::vector<ScriptCommand> script_;
    std::size_t scriptNext_ = 0;
    long scriptFramesLeft_ = 0;
    std::string pendingScreenshot_;
    std::string pendingPanelReport_;
    std::vector<HeldKey> scriptKeys_;  // keys a script holds for this frame
    std::string lastMessage_;
};

}  // namespace manylights
