// The viewer's state and its parts, shared by the files that implement them: Viewer.cpp (the
// window, its frames and screenshots), ViewerKeys.cpp (keys, keymaps and scripts) and
// ViewerPanel.cpp (the Dear ImGui panel).
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

#include "apps/view/ViewScript.h"
#include "apps/view/Viewer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "platform/window/WindowContext.h"
#include "render/Renderer.h"

namespace manylights {

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
    // Camera speeds, per second of wall time with a key held.
    static constexpr float kOrbitDegreesPerSecond = 60.0f;
    static constexpr float kDollyPerSecond = 1.5f;        // distance factor per second
    static constexpr float kFlyFractionPerSecond = 0.4f;  // of the distance to the look-at point
    static constexpr float kMouseDegreesPerPixel = 0.2f;
    // A scripted `key` press acts as the key held for this long.
    static constexpr double kScriptKeySeconds = 1.0 / 30.0;
    static constexpr std::size_t kFrameHistory = 240;
    static constexpr double kShaderCheckSeconds = 0.5;

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
    // The panel's environment section (apps/view/EnvironmentPanel.cpp): nothing without one.
    void drawEnvironmentPanel();
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
    std::map<std::string, std::filesystem::file_time_type> shaderTimes_;
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

}  // namespace manylights
