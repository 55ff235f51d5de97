// How the linear colour of docs/lighting.md becomes a displayable picture (docs/display.md):
// exposure, a tone curve, sRGB encoding and anti-aliasing, applied after lighting by one
// display pass (render/effects/DisplayPass.h) that every technique shares. The scene file's
// `display` block sets them; the command line overrides it. The defaults below are the one
// place the default look is set: a tone curve, then sRGB (SPEC.md §3, since 2026-11-25), so that
// a PNG and the window look right on a screen; the curve is PBR Neutral since issue 48; `--tonemap none --no-srgb`
// (`--classic`) gives the classic round(255 · clamp(colour, 0, 1)).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace manylights {

enum class ToneCurve {
    None,        // the colour as it is (clamped when quantised)
    Reinhard,    // x / (1 + x) per channel (Reinhard et al., SIGGRAPH 2002)
    Aces,        // Narkowicz's fit of the ACES filmic curve (2015)
    Agx,         // Sobotka's AgX, as Wrensch's minimal fit (2023)
    PbrNeutral,  // Khronos PBR Neutral (2024): base colours as authored, highlights compressed
};

enum class Antialiasing {
    None,
    Fxaa,  // luma-edge post-process after Lottes's FXAA 3.11 (render/effects/DisplayPass.h)
};

// Exposures beyond this many stops either way leave no picture (2^±32 of any lit value).
inline constexpr float kMaxExposureStops = 32.0f;
// --supersample N renders N x N as many pixels; 8 keeps a 1920x1080 frame within 16k.
inline constexpr int kMaxSupersample = 8;

struct DisplaySettings {
    float exposure = 0.0f;  // EV: the linear colour is multiplied by 2^exposure
    // Base colours as authored, hot spots unclipped, measured (docs/display.md: why PBR Neutral)
    ToneCurve toneCurve = ToneCurve::PbrNeutral;
    bool srgb = true;  // encode 8-bit outputs with the sRGB curve (IEC 61966-2-1)
    Antialiasing antialiasing = Antialiasing::None;

    // Whether the display pass leaves every value as it is (the classic look: no pass runs).
    bool isIdentity() const
    {
        return exposure == 0.0f && toneCurve == ToneCurve::None && !srgb && antialiasing == Antialiasing::None;
    }
    bool operator==(const DisplaySettings&) const = default;
};

std::optional<ToneCurve> parseToneCurve(std::string_view name);
std::string_view toneCurveName(ToneCurve curve);
const std::vector<std::string>& toneCurveNames();

std::optional<Antialiasing> parseAntialiasing(std::string_view name);
std::string_view antialiasingName(Antialiasing method);
const std::vector<std::string>& antialiasingNames();

}  // namespace manylights
