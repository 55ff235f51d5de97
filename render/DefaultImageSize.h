// The size of an image when none is asked for (docs/cli.md): RendererDesc's zero width and
// height, and --size's default. Apart from render/Renderer.h so that the command line's option
// text (apps/cli/OptionText.h, which the fuzz target builds alone) needs none of the renderer.
#pragma once

namespace manylights {

inline constexpr int kDefaultImageWidth = 1280;
inline constexpr int kDefaultImageHeight = 720;

}  // namespace manylights
