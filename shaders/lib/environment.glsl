// The environment's light (docs/lighting.md, "The environment"; issue 42): the mapping of
// directions onto the equirectangular map (docs/scene-format.md, "environment"; the same as
// scene/Environment.cpp's), the irradiance as spherical harmonics and the prefiltered radiance
// that render/environment/EnvironmentLight.h uploads. lib/lighting.glsl includes it unless the
// program is built with NO_ENVIRONMENT (a scene without one).
#include "lib/bindings.glsl"

// std140 layout of render/environment/EnvironmentLight.cpp: EnvironmentUniforms.
layout(std140, binding = ENVIRONMENT_BLOCK_BINDING) uniform EnvironmentLight {
    // rgb: E(n)/π as spherical harmonics of order 2 (scene/Environment.h irradianceSh), times the
    // intensity: c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz + c6 (3z² − 1) + c7 xz + c8 (x² − y²).
    vec4 irradianceSh[9];
    // x, y: cos and sin of the rotation; z: the intensity; w: the prefiltered chain's levels, n.
    vec4 lookup;
} environment;

// Level 0: the map itself, at its own resolution up to EnvironmentLight::kMaxMapWidth (issue 48).
layout(binding = ENVIRONMENT_MAP_UNIT) uniform sampler2D environmentMap;
// The prefiltered radiance, apart from the map: its layer k holds the map convolved with the GGX
// lobe of roughness (k + 1) / n, at mipmap level (k + 1) / 2 (EnvironmentLight::radianceMip).
layout(binding = ENVIRONMENT_RADIANCE_UNIT) uniform sampler2DArray environmentRadiance;

const float kEnvironmentPi = 3.14159265358979;

// atan(y, x) in [−π, π] within 1.2e-5 radians (a minimax polynomial of atan on [0, 1], with the
// octants unfolded by selects): a thousandth of a texel of the 512-wide chain, and cheaper on
// llvmpipe than GLSL's atan and acos, which environmentUv would take per pixel.
float environmentAtan2(float y, float x)
{
    float ax = abs(x);
    float ay = abs(y);
    float a = min(ax, ay) / max(max(ax, ay), 1e-30);
    float s = a * a;
    float r = a * (0.999866 + s * (-0.3302995 + s * (0.180141 + s * (-0.085133 + s * 0.0208351))));
    r = ay > ax ? 0.5 * kEnvironmentPi - r : r;
    r = x < 0.0 ? kEnvironmentPi - r : r;
    return y < 0.0 ? -r : r;
}

// u = 0.5 + atan2(x, −z) / (2π), v = acos(y) / π (= atan2(√(x² + z²), y) / π); v = 0 is the
// map's top row (+Y), stored as the texture's first row, so (u, v) are the texture coordinates
// as they are.
vec2 environmentUv(vec3 d)
{
    return vec2(0.5 + environmentAtan2(d.x, -d.z) / (2.0 * kEnvironmentPi),
                environmentAtan2(sqrt(d.x * d.x + d.z * d.z), d.y) / kEnvironmentPi);
}

vec3 environmentDirection(vec2 uv)
{
    float phi = (uv.x - 0.5) * 2.0 * kEnvironmentPi;
    float theta = uv.y * kEnvironmentPi;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}

// The direction the map is sampled at for world direction d: d turned by −rotation about +Y,
// so that the map's content turns by +rotation.
vec3 environmentLookup(vec3 d)
{
    float c = environment.lookup.x;
    float s = environment.lookup.y;
    return vec3(d.x * c - d.z * s, d.y, d.x * s + d.z * c);
}

// E(n) / π, the irradiance at unit normal n over π, times the intensity.
vec3 environmentIrradianceOverPi(vec3 n)
{
    vec3 d = environmentLookup(n);
    return environment.irradianceSh[0].rgb + environment.irradianceSh[1].rgb * d.y +
           environment.irradianceSh[2].rgb * d.z + environment.irradianceSh[3].rgb * d.x +
           environment.irradianceSh[4].rgb * (d.x * d.y) + environment.irradianceSh[5].rgb * (d.y * d.z) +
           environment.irradianceSh[6].rgb * (3.0 * d.z * d.z - 1.0) + environment.irradianceSh[7].rgb * (d.x * d.z) +
           environment.irradianceSh[8].rgb * (d.x * d.x - d.y * d.y);
}

// The map's radiance in direction d, times the intensity: what the background shows.
vec3 environmentShown(vec3 d)
{
    return textureLod(environmentMap, environmentUv(environmentLookup(d)), 0.0).rgb * environment.lookup.z;
}

// Level `level` (1 to n, whole) at (u, v): the prefiltered radiance's layer level − 1, at its mipmap level.
vec3 environmentLevelRadiance(vec2 uv, float level)
{
    float layer = level - 1.0;
    float mip = min(floor((layer + 1.0) * 0.5), float(textureQueryLevels(environmentRadiance) - 1));
    return textureLod(environmentRadiance, vec3(uv, layer), mip).rgb;
}

// The radiance prefiltered for `roughness` in direction d, times the intensity: level
// roughness · n counting the map as level 0, between the two nearest levels linearly.
vec3 environmentPrefiltered(vec3 d, float roughness)
{
    float level = clamp(roughness, 0.0, 1.0) * environment.lookup.w;
    vec2 uv = environmentUv(environmentLookup(d));
    float lower = floor(level);
    vec3 below = lower < 1.0 ? textureLod(environmentMap, uv, 0.0).rgb : environmentLevelRadiance(uv, lower);
    vec3 above = environmentLevelRadiance(uv, clamp(lower + 1.0, 1.0, environment.lookup.w));
    return mix(below, above, level - lower) * environment.lookup.z;
}
