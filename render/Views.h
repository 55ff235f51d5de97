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
};

// Whether the view shows the lit picture (the final image, with or without an overlay).
inline bool showsFinalImage(ViewMode mode)
{
    return mode == ViewMode::Final || mode == ViewMode::Volumes || mode == ViewMode::VolumeCorners;
}

// Whether the view shows a G-buffer quantity (rendered by the geometry pass alone).
inline bool isGBufferView(ViewMode mode) { return !showsFinalImage(mode) && mode != ViewMode::LightCount; }

// The heat-map colour of a light-evaluation count (docs/techniques.md has the legend): black
// for 0, then blue, cyan, green, yellow, red and white at 1, 4, 16, 64, 256 and 1024 or more.
void heatMapColour(float count, float rgb[3]);

std::optional<ViewMode> parseViewMode(std::string_view name);
std::string_view viewModeName(ViewMode mode);
const std::vector<std::string>& viewModeNames();

// Turns the raw view values into what a PNG can show (docs/cli.md states each rule):
// final, diffuse, specular, emissive unchanged (the PNG writer clamps); normal as 0.5·N + 0.5;
// position per axis from the image's own minimum to maximum; depth from 1 at the nearest
// surface to 0.1 at the farthest; light-count as a heat map (heatMapColour). Background
// pixels (no surface) stay black.
// `covered` marks pixels that hold a surface.
Image displayableView(const Image& raw, ViewMode mode, const std::vector<bool>& covered);

}  // namespace manylights
