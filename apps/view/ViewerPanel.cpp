// The viewer's Dear ImGui panel (docs/viewer.md "The panel"): what it shows, the settings it
// edits, and how it fits the window (issue 43): collapsed to its title bar, which carries the
// frame time, in small windows, never larger than the window, and its values beside their
// sliders where the handle cannot hide them.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include <imgui.h>

#include "apps/view/ViewerWindow.h"
#include "core/AtomicFile.h"
#include "render/Techniques.h"
#include "render/effects/ShadowMaps.h"
#include "render/techniques/Technique.h"

namespace manylights {

namespace {
// The labels of the widgets drawn with the panel's item width, beside them on the right.
constexpr const char* kTechniqueLabel = "technique";
constexpr const char* kViewLabel = "view";
constexpr const char* kShadowedLightsLabel = "shadowed lights";
constexpr const char* kSsaoRadiusLabel = "SSAO radius";
constexpr const char* kSsaoStrengthLabel = "SSAO strength";
constexpr const char* kExposureLabel = "exposure (EV)";
constexpr const char* kToneCurveLabel = "tone curve";
constexpr const char* kSpeedLabel = "speed";
constexpr const char* kFrameMsLabel = "frame ms";
constexpr const char* kLabelledWidgets[] = {kTechniqueLabel,  kViewLabel,         kShadowedLightsLabel,
                                            kSsaoRadiusLabel, kSsaoStrengthLabel, kExposureLabel,
                                            kToneCurveLabel,  kSpeedLabel,        kFrameMsLabel};
// The widest value a slider shows beside it ("+8.00", "4.00x", "256").
constexpr const char* kWidestSliderValue = "+0.00x";

// Below this window size the panel starts collapsed to its title bar (docs/viewer.md): the
// expanded panel, about 330 x 600 pixels, would cover a third of a 960 x 540 window or more.
constexpr float kExpandedPanelMinWidth = 960.0f;
constexpr float kExpandedPanelMinHeight = 540.0f;
constexpr float kPanelWidth = 330.0f;  // expanded, where the window is wide enough
constexpr float kPanelMargin = 10.0f;  // from the window's edges, where it first appears
// The title with the widest frame time it shows, for a collapsed width that stays put.
constexpr const char* kWidestTitle = "manylights 9999.9 ms";

// A slider with its value beside it, not on it: ImGui centres a slider's value over its frame,
// where the handle hides a digit or the decimal point ("1|00"). The slider and its value share
// the item width; the label follows in the labels' column, as for the other widgets.
template <typename T>
bool sliderWithValue(const char* label, T& value, T min, T max, const char* format)
{
    const ImGuiStyle& style = ImGui::GetStyle();
    const float itemWidth = ImGui::CalcItemWidth();
    const float valueWidth = ImGui::CalcTextSize(kWidestSliderValue).x;
    const float startX = ImGui::GetCursorPosX();
    ImGui::SetNextItemWidth(std::max(1.0f, itemWidth - valueWidth - style.ItemInnerSpacing.x));
    constexpr ImGuiDataType kType = std::is_same_v<T, int> ? ImGuiDataType_S32 : ImGuiDataType_Float;
    const bool changed = ImGui::SliderScalar((std::string("##") + label).c_str(), kType, &value, &min, &max, "");
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    ImGui::SameLine(startX + itemWidth - valueWidth);
    ImGui::TextUnformatted(text);
    ImGui::SameLine(startX + itemWidth + style.ItemInnerSpacing.x);
    ImGui::TextUnformatted(label);
    return changed;
}

// The next widget on the same line as the last where it fits in the panel, else on the next.
void sameLineIfRoom(float nextWidth)
{
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + nextWidth;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
        ImGui::SameLine();
}

float checkboxWidth(const std::string& label)
{
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
           ImGui::CalcTextSize(label.c_str(), nullptr, true).x;
}

// Checkboxes side by side while they fit.
void checkboxRow(const std::vector<std::pair<std::string, bool*>>& boxes)
{
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (i > 0)
            sameLineIfRoom(checkboxWidth(boxes[i].first));
        ImGui::Checkbox(boxes[i].first.c_str(), boxes[i].second);
    }
}

}  // namespace

std::string Viewer::keyedLabel(const char* label, KeyAction action) const
{
    const std::string keys = keysOf(options_.keymap, action);
    // After ###, the widget's identity, which stays when the key map changes the label.
    return std::string(label) + (keys.empty() ? "" : " (" + keys + ")") + "###" + label;
}

void Viewer::drawPanel()
{
    const ImGuiStyle& style = ImGui::GetStyle();
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    // Collapsed by default in a small window: on the first frame, and whenever a resize
    // crosses the size; in between, the panel stays as the user left it.
    const bool small = window.x < kExpandedPanelMinWidth || window.y < kExpandedPanelMinHeight;
    bool collapsed = panelRect_ ? panelRect_->collapsed : small;
    if (smallWindow_ != small) {
        ImGui::SetNextWindowCollapsed(small, ImGuiCond_Always);
        smallWindow_ = small;
        collapsed = small;
    }
    // Never larger than the window; the height fits the contents every frame (the
    // light-count view's pass table is longer), the window's height at most, scrolling beyond.
    const ImVec2 largest{std::max(1.0f, window.x - 2.0f * kPanelMargin),
                         std::max(1.0f, window.y - 2.0f * kPanelMargin)};
    const float titleWidth = style.FramePadding.x + ImGui::GetFontSize() + style.ItemInnerSpacing.x +
                             ImGui::CalcTextSize(kWidestTitle).x + 2.0f * style.FramePadding.x;
    const float width = std::min(collapsed ? titleWidth : kPanelWidth, largest.x);
    ImGui::SetNextWindowSize({width, 0.0f}, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints({0.0f, 0.0f}, largest);
    // Kept inside the window: ImGui leaves a window that fits its contents every frame where
    // it was, and a smaller window would leave it out of sight.
    if (!panelRect_) {
        ImGui::SetNextWindowPos({kPanelMargin, kPanelMargin}, ImGuiCond_Always);
    } else {
        const float x = std::clamp(panelRect_->x, 0.0f, std::max(0.0f, window.x - width));
        const float height = collapsed ? ImGui::GetFrameHeight() : std::min(panelRect_->height, largest.y);
        const float y = std::clamp(panelRect_->y, 0.0f, std::max(0.0f, window.y - height));
        if (x != panelRect_->x || y != panelRect_->y)
            ImGui::SetNextWindowPos({x, y}, ImGuiCond_Always);
    }

    const float latestMs = frameMs_.empty() ? 0.0f : frameMs_.back();
    char title[64];
    std::snprintf(title, sizeof title, "manylights %.1f ms###manylights", std::min(latestMs, 9999.9f));
    const bool open = ImGui::Begin(title);
    const ImVec2 position = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    panelRect_ = PanelRect{position.x, position.y, size.x, size.y, ImGui::IsWindowCollapsed()};
    if (open)
        drawPanelContents();
    ImGui::End();
}

void Viewer::drawPanelContents()
{
    // Sliders, combos and the plot leave room on their right for the widest of their labels,
    // so that none is cut at the panel's edge.
    float widestLabel = 0.0f;
    for (const char* label : kLabelledWidgets)
        widestLabel = std::max(widestLabel, ImGui::CalcTextSize(label).x);
    ImGui::PushItemWidth(-(widestLabel + ImGui::GetStyle().ItemInnerSpacing.x));
    ImGui::TextWrapped("%s", scene_.source.c_str());
    ImGui::Text("%dx%d, %zu lights, %zu objects", renderer_->width(), renderer_->height(), lights_.size(),
                scene_.objects.size());

    // The active key map and its keys, from the table the key handler reads.
    const std::string keysHeader = "keys: " + std::string(keymapName(options_.keymap)) + "###keys";
    if (ImGui::CollapsingHeader(keysHeader.c_str()) && ImGui::BeginTable("keys", 2)) {
        for (const KeyBinding& binding : keyBindings(options_.keymap)) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(keysOf(options_.keymap, binding.action).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(actionDescription(binding.action).data());
        }
        ImGui::EndTable();
    }

    const std::vector<std::string>& names = techniqueNames();
    if (ImGui::BeginCombo(kTechniqueLabel, techniqueName_.c_str())) {
        for (const std::string& name : names)
            if (ImGui::Selectable(name.c_str(), name == techniqueName_))
                techniqueName_ = name;
        ImGui::EndCombo();
    }
    const std::string viewName(viewModeName(view_));
    if (ImGui::BeginCombo(kViewLabel, viewName.c_str())) {
        for (const std::string& name : viewModeNames())
            if (ImGui::Selectable(name.c_str(), name == viewName))
                view_ = *parseViewMode(name);
        ImGui::EndCombo();
    }
    checkboxRow({{keyedLabel("ambient", KeyAction::ToggleAmbient), &ambient_},
                 {keyedLabel("diffuse", KeyAction::ToggleDiffuse), &diffuse_},
                 {keyedLabel("specular", KeyAction::ToggleSpecular), &specular_}});
    checkboxRow({{keyedLabel("axes", KeyAction::ToggleAxes), &axes_},
                 {keyedLabel("wireframe", KeyAction::ToggleWireframe), &wireframe_}});

    ImGui::Separator();
    ImGui::Checkbox("directional shadows", &directionalShadows_);
    sliderWithValue(kShadowedLightsLabel, shadowLights_, 0, kMaxShadowLights, "%d");
    AmbientOcclusion& occlusion = ambientOcclusion_;
    ImGui::Checkbox("SSAO", &occlusion.enabled);
    sliderWithValue(kSsaoRadiusLabel, occlusion.radius, 0.05f, 4.0f, "%.2f");
    sliderWithValue(kSsaoStrengthLabel, occlusion.strength, 0.0f, 2.0f, "%.2f");
    drawEnvironmentPanel();

    if (ImGui::Button(keyedLabel("print camera", KeyAction::PrintCamera).c_str()))
        printCamera();

    ImGui::Separator();
    ImGui::Checkbox("auto exposure", &autoExposure_);
    if (autoExposure_) {
        ImGui::SameLine();
        ImGui::Text("%+.2f EV", adaptedExposure_);
    } else {
        sliderWithValue(kExposureLabel, display_.exposure, -8.0f, 8.0f, "%+.2f");
    }
    const std::string curveName(toneCurveName(display_.toneCurve));
    if (ImGui::BeginCombo(kToneCurveLabel, curveName.c_str())) {
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
    ImGui::Checkbox(keyedLabel("pause", KeyAction::TogglePause).c_str(), &paused_);
    sameLineIfRoom(ImGui::CalcTextSize("t = 0000.00 s").x);
    ImGui::Text("t = %.2f s", time_);
    sliderWithValue(kSpeedLabel, speed_, 0.0f, 4.0f, "%.2fx");

    ImGui::Separator();
    std::vector<float> history(frameMs_.begin(), frameMs_.end());
    const float latest = history.empty() ? 0.0f : history.back();
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.2f ms (%.0f fps)", latest, latest > 0.0f ? 1000.0f / latest : 0.0f);
    ImGui::PlotLines(kFrameMsLabel, history.data(), static_cast<int>(history.size()), 0, overlay, 0.0f, FLT_MAX,
                     {0, 60});
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
            pass.gpuMs ? ImGui::Text("%.3f", *pass.gpuMs) : ImGui::TextUnformatted("-");
            ImGui::TableNextColumn();
            pass.wallMs ? ImGui::Text("%.3f", *pass.wallMs) : ImGui::TextUnformatted("-");
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
}

// One line, "X Y WIDTH HEIGHT WINDOW_WIDTH WINDOW_HEIGHT STATE", in window pixels (docs/viewer.md
// "Scripts"): STATE is expanded, collapsed, or hidden (F1; then the rectangle is 0 0 0 0).
void Viewer::writePanelReport(const std::string& path) const
{
    int windowWidth = 0;
    int windowHeight = 0;
    glfwGetWindowSize(window_.window(), &windowWidth, &windowHeight);
    const PanelRect shown = panel_ && panelRect_ ? *panelRect_ : PanelRect{};
    const char* state = !panel_ || !panelRect_ ? "hidden" : shown.collapsed ? "collapsed" : "expanded";
    char line[160];
    std::snprintf(line, sizeof line, "%.0f %.0f %.0f %.0f %d %d %s\n", shown.x, shown.y, shown.width, shown.height,
                  windowWidth, windowHeight, state);
    writeFileAtomically(path, "panel report", line);
}

// The environment's section (issue 42, docs/viewer.md): the scene's environment's intensity and
// rotation, and whether it shows where no surface is. The renderer takes them through
// RendererDesc::environmentLook, without prefiltering the map again.
void Viewer::drawEnvironmentPanel()
{
    if (!environmentLook_)
        return;
    ImGui::Separator();
    ImGui::TextUnformatted(("environment: " + scene_.environment->map).c_str());
    sliderWithValue("env. intensity", environmentLook_->intensity, 0.0f, 4.0f, "%.2f");
    sliderWithValue("env. rotation (deg)", environmentLook_->rotationDegrees, -180.0f, 180.0f, "%+.0f");
    ImGui::Checkbox("environment as background", &environmentLook_->background);
}

}  // namespace manylights
