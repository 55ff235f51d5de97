// Which G-buffer the deferred techniques write and read (--gbuffer; docs/gbuffer.md shows each
// target): in programs/ because every shader that touches the G-buffer is compiled for one
// layout, a dimension of the shader variant's key (render/programs/LightingPrograms.h:
// TechniqueVariant, GBUFFER_COMPACT), and render/frame/GBuffer.h holds its targets.
#pragma once

#include <optional>
#include <string_view>

#include "core/EnumNames.h"

namespace manylights {

enum class GBufferLayout {
    Seed,     // every quantity as a 32-bit float: exact, 84 bytes per pixel
    Compact,  // position from depth, octahedral normal, 8-bit colours: 28 bytes per pixel
};
inline constexpr GBufferLayout kDefaultGBufferLayout = GBufferLayout::Compact;

inline constexpr EnumNames<GBufferLayout, 2> kGBufferLayoutNames = {{
    {GBufferLayout::Seed, "seed"},
    {GBufferLayout::Compact, "compact"},
}};

inline std::string_view gbufferLayoutName(GBufferLayout layout) { return nameOf(kGBufferLayoutNames, layout); }
inline std::optional<GBufferLayout> parseGBufferLayout(std::string_view name)
{
    return parseName(kGBufferLayoutNames, name);
}

}  // namespace manylights
