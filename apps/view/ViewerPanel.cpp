// The viewer's Dear ImGui panel (docs/viewer.md "The panel"): what it shows, the settings it
// edits, and how it fits the window (issues 43 and 48): collapsed to its title bar, which carries
// the frame time, in small windows, never larger than the window, never over the light-count
// legend, no text cut at its edge, its values beside their sliders where the handle cannot hide
// them, and the controls that cannot apply disabled, saying why.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <imgui.h>

#include "apps/view/ViewerWindow.h"
#include "core/AtomicFile.h"
#include "render/HeatMapLegend.h"
#include "render/Techniques.h"
#include "render/Views.h"
#include "render/techniques/Technique.h"
#include "scene/ShadowSelection.h"

namespace manylights {

namespace {
// The labels of the widgets drawn with the panel's item width, beside them on the right.
constexpr const char* kTechniqueLabel = "technique";
constexpr const char* kViewLabel = "view";
constexpr const char* kShadowedLightsLabel = "shadowed lights";
constexpr const char* kSsaoRadiusLabel = "SSAO radius";
constexpr const char* kSsaoStrengthLabel = "SSAO strength";
constexpr const char* kEnvironmentIntensityLabel = "env. intensity";
constexpr const char* kEnvironmentRotationLabel = "env. rotation";
constexpr const char* kExposureLabel = "exposure (EV)";
constexpr const char* kToneCurveLabel = "tone curve";
constexpr const char* kSpeedLabel = "speed";
constexpr const char* kFrameMsLabel = "frame ms";
constexpr const char* kLabelledWidgets[] = {kTechniqueLabel,
                                            kViewLabel,
                                            kShadowedLightsLabel,
                                            kSsaoRadiusLabel,
                                            kSsaoStrengthLabel,
                                            kEnvironmentIntensityLabel,
                                            kEnvironmentRotationLabel,
                                            kExposureLabel,
                                            kToneCurveLabel,
                                            kSpeedLabel,
                                            kFrameMsLabel};
// The widest value a slider shows beside it ("+8.00", "4.00x", "+180°"), but for the shadowed
// lights' count, which is as wide as the lights' (Viewer::widestShadowLightCount).
constexpr const char* kWidestSliderValue = "+0.00x";
// Beside the shadowed lights' slider: every light that does not opt out casts shadows.
constexpr const char* kAllLightsLabel = "all lights cast shadows";
// The narrowest slider beside its value: this many frame heights (room for the handle to move).
constexpr float kMinimumSliderFrames = 2.0f;
// The widest time a pass table cell shows ("%.3f" below 1000 ms, "%.0f" above).
constexpr const char* kWidestPassMs = "999.999";

// Below this window size the panel starts collapsed to its title bar (docs/viewer.md): the
// expanded panel, about 330 x 600 pixels, would cover a third of a 960 x 540 window or more.
constexpr float kExpandedPanelMinWidth = 960.0f;
constexpr float kExpandedPanelMinHeight = 540.0f;
constexpr float kPanelWidth = 330.0f;  // expanded, where the window is wide enough
constexpr float kPanelMargin = 10.0f;  // from the window's edges, where it first appears
// The title with the widest frame time it shows, for a collapsed width that stays put; in a
// window too narrow for it, the time alone.
constexpr const char* kWidestTitle = "manylights 9999.9 ms";
constexpr float kLongestTitleMs = 9999.9f;
// Tooltips wrap at this many font heights.
constexpr float kTooltipWidthInFonts = 24.0f;

// The part of a label ImGui shows: up to "##" (what follows is the widget's identity).
std::string visiblePart(const std::string& label) { return label.substr(0, label.find("##")); }

float textWidth(const std::string& text) { return ImGui::CalcTextSize(text.c_str(), nullptr, true).x; }

// The right edge of the space the current widget is laid out in: the panel's content region
// (less its scrollbar), or a table cell's.
float contentRight() { return ImGui::GetWindowPos().x + ImGui::GetContentRegionMax().x; }

// Notes `text` with the rectangle of the last widget, which it ends at.
void noteLastItem(PanelRecord& record, const std::string& text)
{
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    record.texts.push_back({visiblePart(text), {min.x, min.y, max.x - min.x, max.y - min.y}, contentRight()});
}

// Text that wraps at the panel's (or cell's) edge instead of running past it.
void wrappedText(PanelRecord& record, const std::string& text)
{
    ImGui::TextWrapped("%s", text.c_str());
    noteLastItem(record, text);
}

void plainText(PanelRecord& record, const std::string& text)
{
    ImGui::TextUnformatted(text.c_str());
    noteLastItem(record, text);
}

bool checkbox(PanelRecord& record, const std::string& label, bool* value)
{
    const bool changed = ImGui::Checkbox(label.c_str(), value);
    noteLastItem(record, label);
    return changed;
}

// A combo whose preview text ends before its arrow (ImGui's BeginCombo clips it there) and
// whose label follows in the labels' column.
bool beginCombo(PanelRecord& record, const char* label, const std::string& preview)
{
    const float itemWidth = ImGui::CalcItemWidth();
    const bool open = ImGui::BeginCombo(label, preview.c_str());
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float frameRight = min.x + itemWidth;
    record.texts.push_back({preview,
                            {min.x + style.FramePadding.x, min.y, textWidth(preview), max.y - min.y},
                            frameRight - ImGui::GetFrameHeight()});
    record.texts.push_back({label, {min.x, min.y, max.x - min.x, max.y - min.y}, contentRight()});
    return open;
}

// A slider with its value beside it, not on it: ImGui centres a slider's value over its frame,
// where the handle hides a digit or the decimal point ("1|00"). The slider and its value share
// the item width; the label follows in the labels' column, as for the other widgets.
// `widestValue`: the widest text the value may show, which the slider leaves room for.
template <typename T>
bool sliderWithValue(PanelRecord& record, const char* label, T& value, T min, T max, const char* format,
                     const std::string& widestValue = kWidestSliderValue)
{
    const ImGuiStyle& style = ImGui::GetStyle();
    const float itemWidth = ImGui::CalcItemWidth();
    const float valueWidth = textWidth(widestValue);
    ImGui::SetNextItemWidth(std::max(1.0f, itemWidth - valueWidth - style.ItemInnerSpacing.x));
    constexpr ImGuiDataType kType = std::is_same_v<T, int> ? ImGuiDataType_S32 : ImGuiDataType_Float;
    const bool changed = ImGui::SliderScalar((std::string("##") + label).c_str(), kType, &value, &min, &max, "");
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    // Placed after the slider, not at offsets from the line's start, which ImGui takes from a
    // group's start inside a group (unlessUnavailable's).
    ImGui::SameLine(0.0f, style.ItemInnerSpacing.x);
    plainText(record, text);
    ImGui::SameLine(0.0f, valueWidth - textWidth(text) + style.ItemInnerSpacing.x);
    plainText(record, label);
    return changed;
}

// The next widget on the same line as the last where it fits in the panel, else on the next.
void sameLineIfRoom(float nextWidth)
{
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + nextWidth;
    if (right <= contentRight())
        ImGui::SameLine();
}

float checkboxWidth(const std::string& label)
{
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + textWidth(label);
}

// Checkboxes side by side while they fit.
void checkboxRow(PanelRecord& record, const std::vector<std::pair<std::string, bool*>>& boxes)
{
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (i > 0)
            sameLineIfRoom(checkboxWidth(boxes[i].first));
        checkbox(record, boxes[i].first, boxes[i].second);
    }
}

// Draws `draw`'s widgets as one group, disabled where `reason` is set (the control cannot apply:
// issue 48), with the reason as the group's tooltip.
template <typename Draw>
void unlessUnavailable(PanelRecord& record, const std::string& control, const std::string& reason, Draw draw)
{
    const bool unavailable = !reason.empty();
    ImGui::BeginGroup();
    if (unavailable)
        ImGui::BeginDisabled();
    draw(unavailable);
    if (unavailable)
        ImGui::EndDisabled();
    ImGui::EndGroup();
    if (!unavailable)
        return;
    record.unavailable.push_back({visiblePart(control), reason});
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * kTooltipWidthInFonts);
        ImGui::TextUnformatted(reason.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

std::string passMs(double ms)
{
    char text[32];
    std::snprintf(text, sizeof text, ms < 1000.0 ? "%.3f" : "%.0f", ms);
    return text;
}

}  // namespace

std::string Viewer::keyedLabel(const char* label, KeyAction action) const
{
    const std::string keys = keysOf(options_.keymap, action);
    // After ###, the widget's identity, which stays when the key map changes the label.
    return std::string(label) + (keys.empty() ? "" : " (" + keys + ")") + "###" + label;
}

std::string Viewer::widestShadowLightCount() const
{
    const std::string count = std::to_string(shadowLightLimit_);
    return textWidth(count) > textWidth("all") ? count : "all";
}

std::optional<WindowRect> Viewer::shownLegend() const
{
    if (!hasLegend(view_))
        return std::nullopt;
    const LegendArea area = heatMapLegendArea(renderer_->width(), renderer_->height());
    if (area.isEmpty())
        return std::nullopt;
    // The legend is drawn in framebuffer pixels; the panel is placed in window pixels.
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const float sx = scale.x > 0.0f ? scale.x : 1.0f;
    const float sy = scale.y > 0.0f ? scale.y : 1.0f;
    return WindowRect{static_cast<float>(area.x) / sx, static_cast<float>(area.y) / sy,
                      static_cast<float>(area.width) / sx, static_cast<float>(area.height) / sy};
}

// The widest of what the panel lays out without wrapping: a labelled widget at its narrowest
// (the widest label beside a combo showing its widest name, or a slider of two handles' width
// with its value), the widest checkbox, the button, the tables' columns of numbers and keys;
// plus the window's padding and a scrollbar. Text wraps, so it needs no more.
float Viewer::minimumExpandedPanelWidth() const
{
    const ImGuiStyle& style = ImGui::GetStyle();
    const float frame = ImGui::GetFrameHeight();
    float widestLabel = 0.0f;
    for (const char* label : kLabelledWidgets)
        widestLabel = std::max(widestLabel, textWidth(label));
    float widestName = 0.0f;
    for (const std::vector<std::string>* names : {&techniqueNames(), &viewModeNames(), &toneCurveNames()})
        for (const std::string& name : *names)
            widestName = std::max(widestName, textWidth(name));
    const float combo = widestName + 2.0f * style.FramePadding.x + frame;
    const float slider = kMinimumSliderFrames * frame + style.ItemInnerSpacing.x +
                         std::max(textWidth(kWidestSliderValue), textWidth(widestShadowLightCount()));
    float content = widestLabel + style.ItemInnerSpacing.x + std::max(combo, slider);

    const std::string checkboxes[] = {keyedLabel("ambient", KeyAction::ToggleAmbient),
                                      keyedLabel("diffuse", KeyAction::ToggleDiffuse),
                                      keyedLabel("specular", KeyAction::ToggleSpecular),
                                      keyedLabel("axes", KeyAction::ToggleAxes),
                                      keyedLabel("wireframe", KeyAction::ToggleWireframe),
                                      keyedLabel("pause", KeyAction::TogglePause),
                                      "directional shadows",
                                      kAllLightsLabel,
                                      "environment as background",
                                      "auto exposure"};
    for (const std::string& label : checkboxes)
        content = std::max(content, checkboxWidth(label));
    content =
        std::max(content, textWidth(keyedLabel("print camera", KeyAction::PrintCamera)) + 2.0f * style.FramePadding.x);
    // The keys' table: the widest keys, and a description column of a few words at least.
    float widestKeys = 0.0f;
    for (const KeyBinding& binding : keyBindings(options_.keymap))
        widestKeys = std::max(widestKeys, textWidth(keysOf(options_.keymap, binding.action)));
    content = std::max(content, widestKeys + textWidth("forward / deferred") + 4.0f * style.CellPadding.x);
    // The passes' table: two columns of times and a name column of a word at least.
    content = std::max(content, 2.0f * textWidth(kWidestPassMs) + textWidth("shadows") + 6.0f * style.CellPadding.x);
    return content + 2.0f * style.WindowPadding.x + style.ScrollbarSize;
}

void Viewer::drawPanel()
{
    const ImGuiStyle& style = ImGui::GetStyle();
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    panelRecord_ = {};
    panelDrawn_ = false;
    const std::optional<WindowRect> legend = shownLegend();

    // Collapsed by default in a small window: on the first frame, and whenever a resize
    // crosses the size; in between, the panel stays as the user left it. A window too narrow
    // for its contents keeps it collapsed, and its title says why.
    const float widthLimit = window.x - 2.0f * kPanelMargin;
    const float minimumWidth = minimumExpandedPanelWidth();
    const bool expandable = widthLimit >= minimumWidth;
    const bool small = window.x < kExpandedPanelMinWidth || window.y < kExpandedPanelMinHeight;
    const bool wasCollapsed = panelRect_ ? panelRect_->collapsed : small;
    bool collapsed = wasCollapsed;
    if (smallWindow_ != small) {
        smallWindow_ = small;
        collapsed = small;
    }
    if (std::exchange(togglePanelCollapsed_, false))
        collapsed = !collapsed;
    if (!expandable)
        collapsed = true;

    // The title: the frame time after the name, or alone where the name does not fit; a window
    // that cannot hold even that shows no panel (nothing cut).
    const float latestMs = std::min(frameMs_.empty() ? 0.0f : frameMs_.back(), kLongestTitleMs);
    char fullTitle[64];
    std::snprintf(fullTitle, sizeof fullTitle, "manylights %.1f ms", latestMs);
    char shortTitle[32];
    std::snprintf(shortTitle, sizeof shortTitle, "%.1f ms", latestMs);
    // Where ImGui starts the title (RenderWindowTitleBarContents): after the collapse arrow; it
    // ends a padding short of the right edge.
    const float titleStart = style.FramePadding.x + ImGui::GetFontSize() + style.ItemInnerSpacing.x;
    const float collapsedWidth = titleStart + textWidth(kWidestTitle) + 2.0f * style.FramePadding.x;
    const float width =
        std::min(collapsed ? collapsedWidth : std::max(kPanelWidth, minimumWidth), std::max(1.0f, widthLimit));
    const float titleRoom = width - titleStart - style.FramePadding.x;
    const char* titleText = textWidth(fullTitle) <= titleRoom ? fullTitle : shortTitle;
    if (!panel_ || textWidth(titleText) > titleRoom || window.y < ImGui::GetFrameHeight())
        return;
    // Every frame where it cannot open: a click on the arrow opens it for the frame after,
    // with no contents (below), until this closes it again.
    if (collapsed != wasCollapsed || !panelRect_ || !expandable)
        ImGui::SetNextWindowCollapsed(collapsed, ImGuiCond_Always);

    // Kept inside the window, and above the light-count legend wherever the two share columns
    // (issue 48): ImGui leaves a window that fits its contents every frame where it was, and a
    // smaller window would leave it out of sight or over the legend. The height fits the
    // contents every frame (the light-count view's pass table is longer), up to what is there,
    // scrolling beyond.
    const float x = panelRect_ ? std::clamp(panelRect_->x, 0.0f, std::max(0.0f, window.x - width)) : kPanelMargin;
    float bottom = window.y;
    if (legend && x < legend->x + legend->width && x + width > legend->x)
        bottom = legend->y;
    const float tallest = std::max(1.0f, bottom - 2.0f * kPanelMargin);
    const float height =
        collapsed ? ImGui::GetFrameHeight() : std::min(panelRect_ ? panelRect_->height : 0.0f, tallest);
    const float y = panelRect_ ? std::clamp(panelRect_->y, 0.0f, std::max(0.0f, bottom - height)) : kPanelMargin;
    if (!panelRect_ || x != panelRect_->x || y != panelRect_->y)
        ImGui::SetNextWindowPos({x, y}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({width, 0.0f}, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints({0.0f, 0.0f}, {width, std::max(1.0f, std::min(tallest, bottom - y))});

    const std::string title = std::string(titleText) + "###manylights";
    const bool open = ImGui::Begin(title.c_str());
    const ImVec2 position = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    panelRect_ = PanelRect{position.x, position.y, size.x, size.y, ImGui::IsWindowCollapsed()};
    panelDrawn_ = true;
    if (!expandable && ImGui::IsItemHovered()) {  // the title bar
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * kTooltipWidthInFonts);
        ImGui::Text("The panel opens in a window at least %.0f pixels wide.", minimumWidth + 2.0f * kPanelMargin);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    panelRecord_.texts.push_back({titleText,
                                  {position.x + titleStart, position.y, textWidth(titleText), ImGui::GetFrameHeight()},
                                  position.x + size.x - style.FramePadding.x});
    // A click on the arrow opens the panel in the frame after, which was laid out for it
    // collapsed, too narrow: its contents wait for the next frame, laid out for it open.
    if (open && !collapsed)
        drawPanelContents();
    ImGui::End();
}

void Viewer::drawPanelContents()
{
    PanelRecord& record = panelRecord_;
    const ImGuiStyle& style = ImGui::GetStyle();
    // Sliders, combos and the plot leave room on their right for the widest of their labels,
    // so that none is cut at the panel's edge.
    float widestLabel = 0.0f;
    for (const char* label : kLabelledWidgets)
        widestLabel = std::max(widestLabel, textWidth(label));
    ImGui::PushItemWidth(-(widestLabel + style.ItemInnerSpacing.x));
    wrappedText(record, scene_.source);
    wrappedText(record, std::to_string(renderer_->width()) + "x" + std::to_string(renderer_->height()) + ", " +
                            std::to_string(lights_.size()) + " lights, " + std::to_string(scene_.objects.size()) +
                            " objects");

    // The active key map and its keys, from the table the key handler reads: the keys in a
    // column as wide as the widest, their actions wrapped in the rest.
    const std::string keysHeader = "keys: " + std::string(keymapName(options_.keymap)) + "###keys";
    if (std::exchange(togglePanelKeys_, false))
        ImGui::SetNextItemOpen(!ImGui::GetStateStorage()->GetBool(ImGui::GetID(keysHeader.c_str())), ImGuiCond_Always);
    const bool keysOpen = ImGui::CollapsingHeader(keysHeader.c_str());
    {
        // ImGui's framed header puts its text after the arrow, three paddings and a font in.
        const ImVec2 min = ImGui::GetItemRectMin();
        const ImVec2 max = ImGui::GetItemRectMax();
        const std::string text = visiblePart(keysHeader);
        record.texts.push_back(
            {text,
             {min.x + ImGui::GetFontSize() + 3.0f * style.FramePadding.x, min.y, textWidth(text), max.y - min.y},
             max.x});
    }
    if (keysOpen && ImGui::BeginTable("keys", 2)) {
        float widestKeys = 0.0f;
        for (const KeyBinding& binding : keyBindings(options_.keymap))
            widestKeys = std::max(widestKeys, textWidth(keysOf(options_.keymap, binding.action)));
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, widestKeys);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        for (const KeyBinding& binding : keyBindings(options_.keymap)) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            plainText(record, keysOf(options_.keymap, binding.action));
            ImGui::TableNextColumn();
            wrappedText(record, std::string(actionDescription(binding.action)));
        }
        ImGui::EndTable();
    }

    // Why a control cannot apply in this view or scene (issue 48), or "" where it can.
    const std::string viewName(viewModeName(view_));
    const bool lit = showsFinalImage(view_);
    const std::string unlit = lit ? "" : "The " + viewName + " view does not show the lighting.";

    const std::vector<std::string>& names = techniqueNames();
    const std::string sameForEvery = isGBufferView(view_) ? "The " + viewName + " view is the same for every technique."
                                     : showsWireframe() ? "The wireframe is drawn with forward, whatever the technique."
                                                        : "";
    unlessUnavailable(record, kTechniqueLabel, sameForEvery, [&](bool) {
        if (beginCombo(record, kTechniqueLabel, techniqueName_)) {
            for (const std::string& name : names)
                if (ImGui::Selectable(name.c_str(), name == techniqueName_))
                    techniqueName_ = name;
            ImGui::EndCombo();
        }
    });
    if (beginCombo(record, kViewLabel, viewName)) {
        for (const std::string& name : viewModeNames())
            if (ImGui::Selectable(name.c_str(), name == viewName))
                view_ = *parseViewMode(name);
        ImGui::EndCombo();
    }
    unlessUnavailable(record, "ambient / diffuse / specular", unlit, [&](bool) {
        checkboxRow(record, {{keyedLabel("ambient", KeyAction::ToggleAmbient), &ambient_},
                             {keyedLabel("diffuse", KeyAction::ToggleDiffuse), &diffuse_},
                             {keyedLabel("specular", KeyAction::ToggleSpecular), &specular_}});
    });
    checkbox(record, keyedLabel("axes", KeyAction::ToggleAxes), &axes_);
    const std::string wireframeLabel = keyedLabel("wireframe", KeyAction::ToggleWireframe);
    sameLineIfRoom(checkboxWidth(wireframeLabel));
    unlessUnavailable(record, wireframeLabel,
                      view_ == ViewMode::Final ? "" : "The wireframe shows in the final view only.",
                      [&](bool) { checkbox(record, wireframeLabel, &wireframe_); });

    ImGui::Separator();
    const std::optional<DirectionalLight>& sun = scene_.directional;
    const std::string noDirectionalShadows =
        !sun            ? "The scene has no directional light."
        : !sun->shadows ? "The scene's directional light does not ask for shadows (\"shadows\": true)."
        : !lit && view_ != ViewMode::Shadow ? unlit
                                            : "";
    unlessUnavailable(record, "directional shadows", noDirectionalShadows, [&](bool unavailable) {
        // Unticked where it cannot apply: no shadow falls.
        bool shown = directionalShadows_ && !unavailable;
        checkbox(record, "directional shadows", unavailable ? &shown : &directionalShadows_);
    });
    unlessUnavailable(record, kShadowedLightsLabel, lights_.empty() ? "The scene has no point or spot lights." : unlit,
                      [&](bool) { drawShadowedLights(); });
    AmbientOcclusion& occlusion = ambientOcclusion_;
    const bool ssaoView = view_ == ViewMode::Ssao;
    unlessUnavailable(record, "SSAO", ssaoView ? "The ssao view shows the occlusion whether SSAO is on or off." : unlit,
                      [&](bool) { checkbox(record, "SSAO", &occlusion.enabled); });
    const std::string noOcclusion = ssaoView ? "" : !lit ? unlit : !occlusion.enabled ? "SSAO is off." : "";
    unlessUnavailable(record, "SSAO radius / strength", noOcclusion, [&](bool) {
        sliderWithValue(record, kSsaoRadiusLabel, occlusion.radius, 0.05f, 4.0f, "%.2f");
        sliderWithValue(record, kSsaoStrengthLabel, occlusion.strength, 0.0f, 2.0f, "%.2f");
    });
    drawEnvironmentPanel();

    const std::string cameraButton = keyedLabel("print camera", KeyAction::PrintCamera);
    if (ImGui::Button(cameraButton.c_str()))
        printCamera();
    noteLastItem(record, cameraButton);

    ImGui::Separator();
    const std::string undisplayed =
        lit ? "" : "The " + viewName + " view is shown as `render --view` writes it, without the display settings.";
    unlessUnavailable(record, "auto exposure / exposure / tone curve / sRGB / FXAA", undisplayed, [&](bool) {
        checkbox(record, "auto exposure", &autoExposure_);
        if (autoExposure_) {
            char exposure[32];
            std::snprintf(exposure, sizeof exposure, "%+.2f EV", adaptedExposure_);
            sameLineIfRoom(textWidth(exposure));
            plainText(record, exposure);
        } else {
            sliderWithValue(record, kExposureLabel, display_.exposure, -8.0f, 8.0f, "%+.2f");
        }
        const std::string curveName(toneCurveName(display_.toneCurve));
        if (beginCombo(record, kToneCurveLabel, curveName)) {
            for (const std::string& name : toneCurveNames())
                if (ImGui::Selectable(name.c_str(), name == curveName))
                    display_.toneCurve = *parseToneCurve(name);
            ImGui::EndCombo();
        }
        bool fxaa = display_.antialiasing == Antialiasing::Fxaa;
        checkboxRow(record, {{"sRGB", &display_.srgb}, {"FXAA", &fxaa}});
        display_.antialiasing = fxaa ? Antialiasing::Fxaa : Antialiasing::None;
    });

    ImGui::Separator();
    checkbox(record, keyedLabel("pause", KeyAction::TogglePause), &paused_);
    char timeText[32];
    std::snprintf(timeText, sizeof timeText, "t = %.2f s", time_);
    sameLineIfRoom(textWidth(timeText));
    plainText(record, timeText);
    sliderWithValue(record, kSpeedLabel, speed_, 0.0f, 4.0f, "%.2fx");

    ImGui::Separator();
    std::vector<float> history(frameMs_.begin(), frameMs_.end());
    const float latest = history.empty() ? 0.0f : history.back();
    char frameText[128];
    std::snprintf(frameText, sizeof frameText, "last frame %.2f ms (%.0f fps); input read at most %.0f ms apart",
                  latest, latest > 0.0f ? 1000.0f / latest : 0.0f, 1000.0 * lastFrameInput_.longestGapSeconds);
    wrappedText(record, frameText);
    ImGui::PlotLines(kFrameMsLabel, history.data(), static_cast<int>(history.size()), 0, nullptr, 0.0f, FLT_MAX,
                     {0, 60});
    noteLastItem(record, kFrameMsLabel);
    // The passes' names wrap in the first column; their times fit the other two.
    if (ImGui::BeginTable("passes", 3)) {
        const float timeWidth = textWidth(kWidestPassMs);
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed, timeWidth);
        ImGui::TableSetupColumn("wall ms", ImGuiTableColumnFlags_WidthFixed, timeWidth);
        ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
        for (int column = 0; column < 3; ++column) {
            ImGui::TableSetColumnIndex(column);
            plainText(record, ImGui::TableGetColumnName(column));
        }
        for (const PassSample& pass : lastSample_.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            wrappedText(record, pass.name);
            ImGui::TableNextColumn();
            plainText(record, pass.gpuMs ? passMs(*pass.gpuMs) : "-");
            ImGui::TableNextColumn();
            plainText(record, pass.wallMs ? passMs(*pass.wallMs) : "-");
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    wrappedText(record, "shaders: " + shaderStatus_);
    if (!shaderError_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.4f, 0.4f, 1.0f});
        wrappedText(record, shaderError_);
        ImGui::PopStyleColor();
    }
    if (!lastMessage_.empty())
        wrappedText(record, lastMessage_);
    ImGui::PopItemWidth();
}

// The first line, "X Y WIDTH HEIGHT WINDOW_WIDTH WINDOW_HEIGHT STATE", in window pixels
// (docs/viewer.md "Scripts"): STATE is expanded, collapsed, or hidden (F1, or a window too small
// for the title; then the rectangle is 0 0 0 0). Then the last whole frame's length and the
// longest time it went without reading input, in ms; the legend's rectangle where the
// light-count view shows it, each text the panel drew with its rectangle, the edge it must end
// before and whether it does, and each control drawn disabled with its reason.
void Viewer::writePanelReport(const std::string& path) const
{
    int windowWidth = 0;
    int windowHeight = 0;
    glfwGetWindowSize(window_.window(), &windowWidth, &windowHeight);
    const bool shown = panel_ && panelDrawn_ && panelRect_;
    const PanelRect rect = shown ? *panelRect_ : PanelRect{};
    const char* state = !shown ? "hidden" : rect.collapsed ? "collapsed" : "expanded";
    char line[256];
    std::snprintf(line, sizeof line, "%.0f %.0f %.0f %.0f %d %d %s\n", rect.x, rect.y, rect.width, rect.height,
                  windowWidth, windowHeight, state);
    std::string report = line;
    // The last whole frame's length and the longest it went without reading input (issue 48).
    std::snprintf(line, sizeof line, "input %.1f %.1f\n", 1000.0 * lastFrameInput_.frameSeconds,
                  1000.0 * lastFrameInput_.longestGapSeconds);
    report += line;
    if (const std::optional<WindowRect> legend = shownLegend()) {
        std::snprintf(line, sizeof line, "legend %.0f %.0f %.0f %.0f\n", legend->x, legend->y, legend->width,
                      legend->height);
        report += line;
    }
    if (shown) {
        for (const PanelRecord::Text& text : panelRecord_.texts) {
            std::snprintf(line, sizeof line, "label %.1f %.1f %.1f %.1f %.1f %s\t", text.rect.x, text.rect.y,
                          text.rect.width, text.rect.height, text.limit, text.fits() ? "fits" : "cut");
            report += line + text.text + "\n";
        }
        for (const PanelRecord::Unavailable& control : panelRecord_.unavailable)
            report += "disabled\t" + control.control + "\t" + control.reason + "\n";
    }
    writeFileAtomically(path, "panel report", report);
}

// The shadowed lights (issue 47, docs/viewer.md): a count up to the lights there are, or all of
// them. With "all lights cast shadows" ticked the count does not apply: its slider shows "all",
// disabled, and keeps the count for when the box is unticked.
void Viewer::drawShadowedLights()
{
    PanelRecord& record = panelRecord_;
    if (allLightsShadowed_) {
        ImGui::BeginDisabled();
        int shown = shadowLightLimit_;
        sliderWithValue(record, kShadowedLightsLabel, shown, 0, shadowLightLimit_, "all", widestShadowLightCount());
        ImGui::EndDisabled();
    } else {
        sliderWithValue(record, kShadowedLightsLabel, shadowLightCount_, 0, shadowLightLimit_, "%d",
                        widestShadowLightCount());
    }
    checkbox(record, kAllLightsLabel, &allLightsShadowed_);
}

// The environment's section (issue 42, docs/viewer.md): the scene's environment's intensity and
// rotation, and whether it shows where no surface is. The renderer takes them through
// RendererDesc::environmentLook, without prefiltering the map again.
void Viewer::drawEnvironmentPanel()
{
    if (!environmentLook_)
        return;
    PanelRecord& record = panelRecord_;
    ImGui::Separator();
    wrappedText(record, "environment: " + scene_.environment->map);
    const std::string unlit =
        showsFinalImage(view_) ? "" : "The " + std::string(viewModeName(view_)) + " view does not show the lighting.";
    unlessUnavailable(record, "env. intensity / rotation / background", unlit, [&](bool) {
        sliderWithValue(record, kEnvironmentIntensityLabel, environmentLook_->intensity, 0.0f, 4.0f, "%.2f");
        sliderWithValue(record, kEnvironmentRotationLabel, environmentLook_->rotationDegrees, -180.0f, 180.0f,
                        "%+.0f\u00b0");
        checkbox(record, "environment as background", &environmentLook_->background);
    });
}

}  // namespace manylights
