// The viewer's Dear ImGui panel (docs/viewer.md): what it shows and the settings it edits.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "apps/view/ViewerWindow.h"
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
}  // namespace

void Viewer::drawPanel()
{
    ImGui::SetNextWindowPos({10, 10}, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize({330, 0}, ImGuiCond_FirstUseEver);
    ImGui::Begin("manylights (F1 hides)");
    // Sliders, combos and the plot leave room on their right for the widest of their labels,
    // so that none is cut at the panel's edge.
    float widestLabel = 0.0f;
    for (const char* label : kLabelledWidgets)
        widestLabel = std::max(widestLabel, ImGui::CalcTextSize(label).x);
    ImGui::PushItemWidth(-(widestLabel + ImGui::GetStyle().ItemInnerSpacing.x));
    ImGui::Text("%s", scene_.source.c_str());
    ImGui::Text("%dx%d, %zu lights, %zu objects", renderer_->width(), renderer_->height(), lights_.size(),
                scene_.objects.size());

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
    ImGui::SliderInt(kShadowedLightsLabel, &shadowLights_, 0, kMaxShadowLights);
    AmbientOcclusion& occlusion = ambientOcclusion_;
    ImGui::Checkbox("SSAO", &occlusion.enabled);
    ImGui::SliderFloat(kSsaoRadiusLabel, &occlusion.radius, 0.05f, 4.0f, "%.2f");
    ImGui::SliderFloat(kSsaoStrengthLabel, &occlusion.strength, 0.0f, 2.0f, "%.2f");
    drawEnvironmentPanel();

    if (ImGui::Button("print camera (C)"))
        printCamera();

    ImGui::Separator();
    ImGui::Checkbox("auto exposure", &autoExposure_);
    if (autoExposure_) {
        ImGui::SameLine();
        ImGui::Text("%+.2f EV", adaptedExposure_);
    } else {
        ImGui::SliderFloat(kExposureLabel, &display_.exposure, -8.0f, 8.0f, "%+.2f");
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
    ImGui::Checkbox("pause (P)", &paused_);
    ImGui::SameLine();
    ImGui::Text("t = %.2f s", time_);
    ImGui::SliderFloat(kSpeedLabel, &speed_, 0.0f, 4.0f, "%.2fx");

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
    ImGui::End();
}

}  // namespace manylights
