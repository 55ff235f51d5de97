// The viewer (docs/viewer.md): a GLFW window drawing the Renderer's image each frame, its
// screenshots, and shader reloading from --shader-dir (its keys and scripts: ViewerKeys.cpp;
// its panel: ViewerPanel.cpp).
#include "apps/view/Viewer.h"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <utility>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "apps/cli/CommandSupport.h"
#include "apps/view/CameraControls.h"
#include "apps/view/ViewScript.h"
#include "apps/view/ViewerWindow.h"
#include "core/Error.h"
#include "gl/ShaderSource.h"
#include "gl/VertexArray.h"
#include "platform/EglChoice.h"
#include "platform/HeadlessContext.h"
#include "platform/window/WindowContext.h"
#include "render/HeatMapLegend.h"
#include "render/Renderer.h"
#include "scene/LightSets.h"
#include "scene/ShadowSelection.h"

namespace manylights {

namespace {

namespace fs = std::filesystem;

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

Scene loadScene(const ViewOptions& options)
{
    return loadSceneForCommand(options.scenePath, options.strict, options.camera);
}

}  // namespace

Viewer::Viewer(const ViewOptions& options)
    : options_(options),
      scene_(loadScene(options)),
      window_({options.size.width, options.size.height, "manylights — " + scene_.source, defaultDebugContext()}),
      techniqueName_(options.technique),
      view_(*parseViewMode(options.view)),
      camera_(scene_.camera),
      ambientOcclusion_(scene_.ssao),
      environmentLook_(scene_.environment ? std::optional(scene_.environment->look) : std::nullopt),
      time_(options.time)
{
    lights_ = lightsForCommand(scene_, options.lights);
    const int shadowLights = chooseShadowLights(scene_, options.shadows);
    allLightsShadowed_ = shadowLights == kAllShadowLights;
    const int lightCount = static_cast<int>(std::min<std::size_t>(lights_.size(), kAllShadowLights));
    shadowLightCount_ = allLightsShadowed_ ? lightCount : shadowLights;
    shadowLightLimit_ = std::max({1, lightCount, shadowLightCount_});
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
    printWarnings(renderer_->gpuScene().environment().warnings());
    axesProgram_ = gl::Program("axes", {{GL_VERTEX_SHADER, "axes.vert"}, {GL_FRAGMENT_SHADER, "axes.frag"}});

    GLFWwindow* window = window_.window();
    glfwSetWindowUserPointer(window, this);
    // Installed before ImGui's, which chains to them. The moments of presses and releases time
    // the held keys' moves (HeldKeys.h): when the display server sent them (KeyEventTimes.h),
    // else when they were read. Events are also read while a frame renders (the renderer's wait
    // hook, rendererDesc), so a press's action waits for the next frame's start rather than
    // changing the settings of the frame being drawn.
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int) {
        if (action == GLFW_REPEAT)
            return;
        Viewer& viewer = of(w);
        const double readAt = glfwGetTime();
        const double time = viewer.keyTimes_.take(scancode, action == GLFW_PRESS, readAt).value_or(readAt);
        if (action == GLFW_RELEASE)
            viewer.heldKeys_.release(key, time);
        if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureKeyboard) {
            viewer.heldKeys_.press(key, time);
            viewer.pressedKeys_.push_back(key);
        }
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

RendererDesc Viewer::rendererDesc()
{
    DisplaySettings shown = display_;
    if (autoExposure_)
        shown.exposure = adaptedExposure_;
    return {.width = width_,
            .height = height_,
            .countWork = view_ == ViewMode::LightCount,
            .shadowLights = allLightsShadowed_ ? kAllShadowLights : shadowLightCount_,
            .shadowPoolMiB = options_.shadows.poolMiB,
            .directionalShadows = directionalShadows_,
            .ambientOcclusion = ambientOcclusion_,
            .environmentLook = environmentLook_,
            .lightingTerms = {ambient_ ? 1.0f : 0.0f, diffuse_ ? 1.0f : 0.0f, specular_ ? 1.0f : 0.0f},
            .display = shown,
            .wireframe = wireframe_,
            .driver = options_.driver.overrides,
            .culling = options_.culling,
            // Input read between passes and during the waits for the GPU (issue 48): a key's
            // press and release are then timed to within PassProfiler::kWaitHookInterval and a
            // pass, not to a whole frame, which on llvmpipe lasts up to seconds. GLFW reads
            // events on the main thread only, which is the one that renders.
            .waitHook = [this] { readInput(); }};
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
// writer does), or the view's displayable image as `render --view` writes it to PNG (the
// light-count and shadow-resolution views' with their legends).
void Viewer::showImage()
{
    const int width = renderer_->width();
    const int height = renderer_->height();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    if (showsFinalImage(view_)) {
        glBlitNamedFramebuffer(renderer_->displayedFramebuffer()->id(), 0, 0, 0, width, height, 0, 0, width, height,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return;
    }
    const Image raw = renderer_->readColour();
    Image shown = displayableView(raw, view_, renderer_->readCoverage());
    drawViewLegend(shown, raw, view_, effectiveTechnique());  // the legend `render` draws into its PNG
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

void Viewer::readInput()
{
    glfwPollEvents();
    const double now = glfwGetTime();
    inputGapSeconds_ = std::max(inputGapSeconds_, now - lastInputRead_);
    lastInputRead_ = now;
}

void Viewer::run()
{
    double last = glfwGetTime();
    lastInputRead_ = last;
    while (!quit_ && !glfwWindowShouldClose(window_.window())) {
        readInput();
        const double now = glfwGetTime();
        // The frame that just ended: its length, and the longest it went without reading input.
        lastFrameInput_ = {now - last, std::exchange(inputGapSeconds_, 0.0)};
        // The keys pressed since the last frame began, also those read while it rendered.
        for (const int key : std::exchange(pressedKeys_, {}))
            onKeyPressed(key);
        const double elapsed = now - last;
        last = now;
        frameSeconds_ = elapsed;
        runScript();
        if (quit_)
            break;
        const std::vector<HeldKey> held = heldKeys_.endFrame(now);
        if (!ImGui::GetIO().WantCaptureKeyboard)  // keys typed into the panel are the panel's
            applyHeldKeys(held);
        applyHeldKeys(scriptKeys_);
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
        readInput();  // after the views converted and shown on the CPU (the G-buffer views, light-count)
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
        if (!pendingPanelReport_.empty()) {
            writePanelReport(pendingPanelReport_);
            pendingPanelReport_.clear();
        }
        glfwSwapBuffers(window_.window());
    }
}

namespace {

// --device N|UUID in the viewer: the EGL device's renderer, asked before the window exists
// (listing makes and ends a context on every device). Throws manylights::Error for an index or
// a UUID that no device has.
std::string requestedDeviceRenderer(const DeviceSelector& selector)
{
    const std::vector<EglDeviceInfo> devices = listDevices();
    return devices[selectListedDevice(selector, devices)].renderer;
}

}  // namespace

void runView(const ViewOptions& options)
{
    const std::string deviceRenderer = options.driver.device ? requestedDeviceRenderer(*options.driver.device) : "";
    Viewer viewer(options);
    if (options.driver.device && viewer.contextDescription().rfind(deviceRenderer, 0) != 0)
        throw Error("--device " + formatDeviceSelector(*options.driver.device) + " is " + deviceRenderer +
                    ", but the window's context is " + viewer.contextDescription() +
                    " (the display server chooses the window's GPU)");
    viewer.run();
}

}  // namespace manylights
