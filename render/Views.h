// What `--view` shows (docs/cli.md): the lit image or one G-buffer quantity.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/output/Image.h"

namespace manylights {

// The values are the shader's viewMode (shaders/gbuffer_view.frag).
enum class ViewMode {
    Final = 0,
    Position = 1,
    Normal = 2,
    Diffuse = 3,
    Specular = 4,
    Emissive = 5,
    Depth = 6,
    LightCount = 7,  // light evaluations per pixel (a heat map in PNG)
    Volumes = 8,     // the final image with every light's volume as a wireframe
    Shadow = 9,      // the directional light's shadow factor (1 lit, 0 umbra; 1 without shadows)
    Ssao = 10,       // the blurred ambient-occlusion factor (1 open, 0 occluded)
    // The final image with every light volume's corners (its proxy mesh's vertices) as points:
    // where the volume techniques' geometry lies, without its edges hiding the picture.
    VolumeCorners = 11,
    // The shadow texels per screen pixel of the pages the shadowed local lights' lookups read
    // (render/shadows/ShadowResolutionView.h; a heat map in PNG, black where none reaches).
    ShadowResolution = 12,
};

// Whether the view shows the lit picture (the final image, with or without an overlay).
inline bool showsFinalImage(ViewMode mode)
{
    return mode == ViewMode::Final || mode == ViewMode::Volumes || mode == ViewMode::VolumeCorners;
}

// Whether the view shows a quantity of the G-buffer's surfaces, the same for every technique
// (rendered without the technique: the geometry pass and, for the shadow-resolution view, the
// shadow pool's walk of its light lists).
inline bool isGBufferView(ViewMode mode) { return !showsFinalImage(mode) && mode != ViewMode::LightCount; }

// Whether the view's PNG and the viewer carry a legend (render/HeatMapLegend.h).
inline bool hasLegend(ViewMode mode) { return mode == ViewMode::LightCount || mode == ViewMode::ShadowResolution; }

// The heat-map colour of a light-evaluation count (docs/techniques.md has the legend): black
// for 0, then blue, cyan, green, yellow, red and white at 1, 4, 16, 64, 256 and 1024 or more.
void heatMapColour(float count, float rgb[3]);

// The shadow-resolution view's colour of a figure of texels per pixel (docs/shadows.md has the
// legend): black for 0 (no shadowed light reaches), then a stop per level on a log scale:
// violet 1/8 or less, blue 1/4, cyan 1/2, green 1 (the target), yellow 2, red 4, white 8 or more.
void shadowResolutionColour(float texelsPerPixel, float rgb[3]);

std::optional<ViewMode> parseViewMode(std::string_view name);
std::string_view viewModeName(ViewMode mode);
const std::vector<std::string>& viewModeNames();

// Turns the raw view values into what a PNG can show (docs/cli.md states each rule):
// final, diffuse, specular, emissive unchanged (the PNG writer clamps); normal as 0.5·N + 0.5;
// position per axis from the image's own minimum to maximum; depth from 1 at the nearest
// surface to 0.1 at the farthest; light-count as a heat map (heatMapColour);
// shadow-resolution likewise (shadowResolutionColour). Background
// pixels (no surface) stay black.
// `covered` marks pixels that hold a surface.
Image displayableView(const Image& raw, ViewMode mode, const std::vector<bool>& covered);

}  // namespace manylights
