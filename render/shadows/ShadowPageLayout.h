// The shadow-page pool's layout of shaders/lib/shadow_page_layout.glsl, read as C++
// (shadowpages::SHADOW_PAGE_TEXELS, ...), so a number cannot drift between the shaders that
// mark and read the pages and the code that places and draws them.
#pragma once

namespace manylights::shadowpages {
#include "shaders/lib/shadow_page_layout.glsl"
}  // namespace manylights::shadowpages
