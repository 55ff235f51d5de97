// The environment a scene may be lit by (`environment` in the scene file, issue 42): an
// equirectangular map of radiance, with the mapping from directions to its texels that
// docs/scene-format.md ("environment") states and the shaders use (shaders/lib/environment.glsl),
// the built-in studio map, and the irradiance's spherical harmonics that the lighting function
// evaluates (docs/lighting.md, "The environment"). Plain data, no GL: the render layer decodes
// map files (render/environment/EnvironmentFiles.h) and prefilters the radiance.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace manylights {

// How a map lights and shows: what the viewer may change without prefiltering it again.
struct EnvironmentLook {
    float intensity = 1.0f;        // multiplies the map's radiance (≥ 0, finite)
    float rotationDegrees = 0.0f;  // turns the map's content about +Y, counter-clockwise from above
    bool background = false;       // shown where no surface is, instead of the scene's `background`
    bool operator==(const EnvironmentLook&) const = default;
};

// The scene file's `environment` key.
struct Environment {
    // A path (resolved relative to the scene file) of a .hdr or .exr map, or a built-in map's
    // name (isBuiltinEnvironment).
    std::string map;
    EnvironmentLook look;
};

// The built-in maps, by the name a scene's `map` gives them.
inline constexpr std::string_view kStudioEnvironment = "builtin:studio";
inline constexpr std::string_view kBuiltinEnvironmentPrefix = "builtin:";
// Whether `map` names a built-in map (or tries to: the prefix is reserved).
bool isBuiltinEnvironment(std::string_view map);

// An equirectangular map: `width` = 2 · `height` texels, row-major, the top row (+Y) first.
struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> radiance;
    const glm::vec3& at(int i, int j) const { return radiance[static_cast<std::size_t>(j) * width + i]; }
    glm::vec3& at(int i, int j) { return radiance[static_cast<std::size_t>(j) * width + i]; }
};

// The mapping (docs/scene-format.md): a unit direction d = (x, y, z) has
// u = 0.5 + atan2(x, −z) / (2π) and v = acos(y) / π, v = 0 the top row; texel (i, j) is centred
// at ((i + 0.5) / W, (j + 0.5) / H). −Z is the middle of the image, +X is at u = 0.75.
glm::vec2 environmentUv(const glm::dvec3& direction);
// The unit direction at (u, v): the inverse of environmentUv.
glm::dvec3 environmentDirection(const glm::dvec2& uv);
// The direction a map turned by `rotationDegrees` about +Y is sampled at for `direction`: the
// direction turned by −rotation (counter-clockwise seen from above for a positive angle).
glm::dvec3 environmentLookup(const glm::dvec3& direction, double rotationDegrees);
// The solid angle of a texel of row j of a map `height` rows high (and 2 · height wide):
// (2π / W) · (cos θ_top − cos θ_bottom), exact for the rectangle of (u, v) the texel covers.
double environmentTexelSolidAngle(int row, int height);

// The built-in studio (kStudioEnvironment), made at load: a soft sky above the horizon, a darker
// floor below, and three bright soft-edged area lights (a key, a fill and a strip above).
// `height` rows, 2 · height columns.
EnvironmentImage studioEnvironment(int height);

// E(n) / π of a map, as spherical harmonics of order 2 (Ramamoorthi and Hanrahan, "An efficient
// representation for irradiance environment maps", 2001): nine RGB coefficients c such that
// E(n) / π = c0 + c1·y + c2·z + c3·x + c4·xy + c5·yz + c6·(3z² − 1) + c7·xz + c8·(x² − y²)
// for the unit normal n = (x, y, z) in the map's frame, where E(n) is the irradiance
// ∫ L(ω) max(n·ω, 0) dω of the map's texels, each constant over its (u, v) rectangle. The
// clamped cosine's bands above 2 are left out: |E − E_SH| ≤ (3/32) ∫ L dω (docs/lighting.md).
using IrradianceSh = std::array<glm::vec3, 9>;
IrradianceSh irradianceSh(const EnvironmentImage& map);
// E(n) / π from the coefficients, n unit in the map's frame.
glm::dvec3 irradianceOverPi(const IrradianceSh& sh, const glm::dvec3& n);

}  // namespace manylights
