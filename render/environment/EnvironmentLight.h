// The environment on the GPU (issue 42; docs/lighting.md, "The environment"): the map's
// irradiance as spherical harmonics and its radiance prefiltered for the GGX lobe, in the
// uniform block and texture that shaders/lib/environment.glsl reads. Made once at load, where a
// compute pass (shaders/environment_prefilter.comp) fills the prefiltered levels; the look
// (intensity, rotation, background) changes without prefiltering again.
//
// The prefiltered radiance is an equirectangular chain of kRadianceLevels levels, the first
// kRadianceWidth x kRadianceWidth / 2, each level half the one before (down to 16x8). Level l
// holds the map convolved with the GGX lobe of roughness l / (kRadianceLevels − 1) (level 0 the
// map itself), and a surface of roughness r reads level r · (kRadianceLevels − 1), between two
// levels linearly. The chain repeats across u = 0 and 1 (GL_REPEAT: bilinear filtering wraps
// round the seam at −Z's back, +Z) and clamps at the poles (v = 0 and 1), where each row's
// texels all lie within half a texel of the pole; the lookups give their level explicitly, so no
// derivative jumps at the seam either.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/MipmappedTexture.h"
#include "gl/Program.h"
#include "scene/Environment.h"

namespace manylights {

// std140 layout of shaders/lib/environment.glsl: EnvironmentLight.
struct EnvironmentUniforms {
    std::array<glm::vec4, 9> irradianceSh;  // rgb: irradianceSh(map) times the intensity
    glm::vec4 lookup;                       // cos and sin of the rotation, the intensity, the last level
};

class EnvironmentLight {
public:
    static constexpr int kRadianceWidth = 512;
    static constexpr int kRadianceLevels = 6;
    // The storage of the prefiltered levels: 32-bit floats. Half floats (2^-11 relative) would
    // do for the image, but llvmpipe samples float texels faster (no conversion): with them and
    // environmentAtan2 (shaders/lib/environment.glsl) the environment's cost in the lighting pass
    // of scenes/pbr-models.json fell from 55 to about 20 ms (docs/performance.md). A GPU
    // would save bandwidth with half floats, but the image would then depend on the driver.
    static constexpr GLenum kRadianceFormat = GL_RGBA32F;
    // Samples per texel of the prefiltering (shaders/environment_prefilter.comp): 64 for level 1,
    // 128 for level 2, 256 for the rest. Filtered importance sampling reads a mipmap as wide as
    // each sample's share of the lobe, so the fewer the samples the blurrier the estimate: with
    // these every level is within 2% of the integral (tests/gl/EnvironmentLightTest.cpp; 64 for
    // every level left the roughest 8% off, 128 4%). Level 1 (256x128 texels, a narrow lobe)
    // needs few, and 256 there would take three times as long at load (docs/performance.md).
    // The same on every driver: a GPU could take more for nearly nothing, but the image would
    // then depend on the driver, and every technique under either driver profile is compared
    // with one reference.
    static constexpr int kMaxPrefilterSamples = 256;
    static constexpr int prefilterSamples(int level) { return level <= 1 ? 64 : level == 2 ? 128 : 256; }

    // No environment: a zero irradiance and a black 1x1 radiance, so that a program built with
    // the environment's code (a LightingFeatures without NO_ENVIRONMENT) adds exactly 0.
    EnvironmentLight();
    // `environment`'s map loaded (render/environment/EnvironmentFiles.h) and prefiltered, waiting
    // for the GPU to finish (loadMs() times it all). Throws manylights::Error naming the map for a
    // bad one.
    explicit EnvironmentLight(const Environment& environment);

    // Binds the uniform block and the prefiltered radiance at shaders/lib/bindings.glsl's
    // ENVIRONMENT_BLOCK_BINDING and ENVIRONMENT_RADIANCE_UNIT.
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
    // The prefiltered radiance (tests read its levels).
    const gl::MipmappedTexture2D& radiance() const { return radiance_; }

    // The prefiltering compute program for a chain stored as `format`, and the pass the
    // constructor runs with it: prefilters `map` into `radiance` (its levels as above). Public
    // for tests to run on maps of their own.
    static gl::Program prefilterProgram(GLenum format);
    static void prefilter(const EnvironmentImage& map, const gl::MipmappedTexture2D& radiance,
                          const gl::Program& program);

private:
    void upload();

    bool present_ = false;
    EnvironmentLook look_;
    IrradianceSh sh_{};
    gl::MipmappedTexture2D radiance_;
    gl::Program prefilterProgram_;  // kept with the scene's programs (tests/gl/BindingsTest.cpp sees it)
    gl::Buffer uniforms_;
    double loadMs_ = 0.0;
};

// The roughness level l of the chain is prefiltered for: l / (kRadianceLevels − 1).
constexpr float environmentLevelRoughness(int level)
{
    return static_cast<float>(level) / static_cast<float>(EnvironmentLight::kRadianceLevels - 1);
}

}  // namespace manylights
