// The environment on the GPU (issue 42; docs/lighting.md, "The environment"): the map's
// irradiance as spherical harmonics, the map itself and its radiance prefiltered for the GGX
// lobe, in the uniform block and textures that shaders/lib/environment.glsl reads. Made once at
// load, where a compute pass (shaders/environment_prefilter.comp) fills the prefiltered levels;
// the look (intensity, rotation, background) changes without prefiltering again.
//
// Level 0 is the map itself, at its own resolution up to kMaxMapWidth (issue 48: a larger map is
// box-filtered to that width, with a warning), one texture that the background and mirror-like
// surfaces read. The prefiltered radiance is a separate equirectangular 2D array of
// kRadianceLevels layers whatever the map's size: layer k holds the map convolved with the GGX
// lobe of roughness (k + 1) / kRadianceLevels, at mipmap level radianceMip(k) of a
// kRadianceWidth x kRadianceWidth / 2 array, so at the texels its lobe needs (256x128 for
// roughness 0.2, 128x64 for 0.4 and 0.6, 64x32 for 0.8 and 1; the other levels of each layer are
// unused).
// A surface of roughness r reads level r · kRadianceLevels counting the map as level 0, between
// two levels linearly. Both repeat across u = 0 and 1 (GL_REPEAT: bilinear filtering wraps round
// the seam at −Z's back, +Z) and clamp at the poles (v = 0 and 1), where each row's texels all lie
// within half a texel of the pole; the lookups give their level explicitly, so no derivative
// jumps at the seam either.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/LayeredTexture.h"
#include "gl/MipmappedTexture.h"
#include "gl/Program.h"
#include "scene/Environment.h"

namespace manylights {

// std140 layout of shaders/lib/environment.glsl: EnvironmentLight.
struct EnvironmentUniforms {
    std::array<glm::vec4, 9> irradianceSh;  // rgb: irradianceSh(map) times the intensity
    glm::vec4 lookup;                       // cos and sin of the rotation, the intensity, kRadianceLevels
};

class EnvironmentLight {
public:
    // The widest level 0 kept: a 8192x4096 map shows at its own resolution (its horizon sharp at
    // 1280x720 with a 60° field of view, about a texel a pixel); a 16384x8192 one (the widest
    // accepted, render/environment/EnvironmentFiles.h) is box-filtered to this. At 32-bit floats
    // level 0 of 8192x4096 takes 512 MiB.
    static constexpr int kMaxMapWidth = 8192;
    static constexpr int kRadianceWidth = 256;
    static constexpr int kRadianceLevels = 5;
    // The mipmap level layer k is stored at, (k + 1) / 2: its texels a small part of its lobe.
    // Bilinear filtering flattens what varies within a texel: the peak of a sun's lobe by about
    // (texel / lobe width)² / 2, and the kink where the sun crosses the surface's horizon
    // (max(N·l, 0)) by a quarter of a texel's change. At 22.5° (the 16x8 a halving chain gave
    // roughness 1) the sun came out 6% off at that kink, and at 5.6° (64x32) the peak of
    // roughness 0.6 2.8%: 256x128 for roughness 0.2, 128x64 for 0.4 and 0.6, 64x32 for 0.8 and 1
    // keep each within about 1% (docs/lighting.md).
    static constexpr int kRadianceMips = 3;
    static constexpr int radianceMip(int level) { return (level + 1) / 2; }
    // The storage of the map and the prefiltered levels: 32-bit floats. Half floats (2^-11
    // relative) would do for the image, but llvmpipe samples float texels faster (no
    // conversion): with them and environmentAtan2 (shaders/lib/environment.glsl) the
    // environment's cost in the lighting pass of scenes/pbr-models.json fell from 55 to about
    // 20 ms (docs/performance.md). A GPU would save bandwidth with half floats, but the image
    // would then depend on the driver.
    static constexpr GLenum kRadianceFormat = GL_RGBA32F;
    // No environment: a zero irradiance and a black 1x1 map and radiance, so that a program
    // built with the environment's code (a LightingFeatures without NO_ENVIRONMENT) adds exactly 0.
    EnvironmentLight();
    // `environment`'s map loaded (render/environment/EnvironmentFiles.h), uploaded as level 0
    // and prefiltered, waiting for the GPU to finish (loadMs() times it all); the map's CPU copy
    // is freed once uploaded and prefiltered. A map wider than `maxMapWidth` (tests make it
    // small) is box-filtered to it, with a warning. Throws manylights::Error naming the map for a
    // bad one.
    explicit EnvironmentLight(const Environment& environment, int maxMapWidth = kMaxMapWidth);

    // Binds the uniform block, the map and the prefiltered radiance at shaders/lib/bindings.glsl's
    // ENVIRONMENT_BLOCK_BINDING, ENVIRONMENT_MAP_UNIT and ENVIRONMENT_RADIANCE_UNIT.
    void bind() const;
    // Whether there is an environment (the constructor with one).
    bool present() const { return present_; }
    // Changes the intensity, rotation and background (the viewer's panel): no prefiltering.
    void setLook(const EnvironmentLook& look);
    const EnvironmentLook& look() const { return look_; }
    // Whether frames draw the environment where no surface is.
    bool showsBackground() const { return present_ && look_.background; }
    // Wall-clock milliseconds of making the environment: reading or making the map, its
    // harmonics, uploading it and prefiltering, until the GPU finished; 0 without one.
    double loadMs() const { return loadMs_; }
    const IrradianceSh& irradiance() const { return sh_; }
    // Level 0, the map (tests read it), and the prefiltered radiance (tests read its levels).
    const gl::MipmappedTexture2D& map() const { return map_; }
    const gl::LayeredTexture& radiance() const { return radiance_; }
    // What the loading forgave, one line each naming the map (the apps print them): a map wider
    // than kMaxMapWidth shown box-filtered.
    const std::vector<std::string>& warnings() const { return warnings_; }

    // The prefiltering compute program for a chain stored as `format`, and the pass the
    // constructor runs with it: prefilters `map` into `radiance` (its levels as above). Public
    // for tests to run on maps of their own.
    static gl::Program prefilterProgram(GLenum format);
    static void prefilter(const EnvironmentImage& map, const gl::LayeredTexture& radiance, const gl::Program& program);

private:
    void upload();

    bool present_ = false;
    EnvironmentLook look_;
    IrradianceSh sh_{};
    gl::MipmappedTexture2D map_;
    gl::LayeredTexture radiance_;
    std::vector<std::string> warnings_;
    gl::Program prefilterProgram_;  // kept with the scene's programs (tests/gl/BindingsTest.cpp sees it)
    gl::Buffer uniforms_;
    double loadMs_ = 0.0;
};

// The roughness layer k of the prefiltered radiance is made for: (k + 1) / kRadianceLevels.
constexpr float environmentLevelRoughness(int level)
{
    return static_cast<float>(level + 1) / static_cast<float>(EnvironmentLight::kRadianceLevels);
}

}  // namespace manylights
