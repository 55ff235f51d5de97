// The viewer panel's environment section (issue 42, docs/viewer.md): the scene's environment's
// intensity and rotation, and whether it shows where no surface is. The renderer takes them
// through RendererDesc::environmentLook, without prefiltering the map again.
#include <imgui.h>

#include "apps/view/ViewerWindow.h"

namespace manylights {

void Viewer::drawEnvironmentPanel()
{
    if (!environmentLook_)
        return;
    ImGui::Separator();
    ImGui::TextUnformatted(("environment: " + scene_.environment->map).c_str());
    // Labels no wider than the panel's widest ("shadowed lights"): the sliders leave room for it.
    ImGui::SliderFloat("env. intensity", &environmentLook_->intensity, 0.0f, 4.0f, "%.2f");
    ImGui::SliderFloat("env. rotation", &environmentLook_->rotationDegrees, -180.0f, 180.0f, "%.0f deg");
    ImGui::Checkbox("environment as background", &environmentLook_->background);
}

}  // namespace manylights
