// The display pass (render/effects/DisplayPass.h) on textures of known values: each tone curve
// and the sRGB encoding against the published formulas (typed here from the papers, not from
// shaders/lib/display.glsl; PBR Neutral on colours worked by hand), the default settings as PBR
// Neutral then sRGB, AgX's fused sRGB step, the box filter of supersampling against the CPU's,
// and FXAA on flat regions (unchanged) and on an analytic edge (closer to the true coverage).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <vector>

#include <glm/glm.hpp>

#include "GlContextTest.h"
#include "render/effects/DisplayPass.h"
#include "render/output/Image.h"
#include "render/scene/GpuScene.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"
#include "tests/support/ImageComparison.h"
#include "tests/support/PbrNeutral.h"

namespace manylights {
namespace {

class DisplayPassTest : public GlContextTest {};

// `image` (rows top to bottom, as Image stores them) into an RGBA32F texture of its size.
void writeLinear(const Image& image, const gl::Texture2D& texture)
{
    std::vector<float> rgba(static_cast<std::size_t>(image.width) * image.height * 4, 1.0f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            std::copy_n(image.pixel(x, y), 3,
                        &rgba[(static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 4]);
    texture.write(GL_RGBA, GL_FLOAT, rgba.data());
}

// An RGBA32F texture holding `image`.
gl::Texture2D uploadLinear(const Image& image)
{
    gl::Texture2D texture("display test input", GL_RGBA32F, image.width, image.height);
    writeLinear(image, texture);
    return texture;
}

// The pass's 8-bit output, rows top to bottom, RGB.
std::vector<unsigned char> runDisplay(const Image& input, const DisplaySettings& settings, int supersample = 1)
{
    // The pass runs as a pass of a frame: a frame of one plane whose lit image is `input`.
    const Scene scene =
        parseScene(R"({"objects": [{"mesh": {"primitive": "plane", "size": [4, 4]}}]})", "<one plane>", ".");
    const GpuScene gpuScene(scene, expandLights(scene), resolveDriverChoices({.profile = DriverProfile::Auto}));
    FrameTargets targets(input.width, input.height);
    writeLinear(input, targets.lit);
    DisplayPass pass;
    PassProfiler profiler;
    profiler.beginFrame();
    {
        FramePasses passes(gpuScene, targets, profiler);
        pass.run(passes, settings, supersample);
    }
    profiler.endFrame();
    const gl::Texture2D& out = pass.output();
    std::vector<unsigned char> rgba(static_cast<std::size_t>(out.width()) * out.height() * 4);
    out.read(GL_RGBA, GL_UNSIGNED_BYTE, rgba.size(), rgba.data());
    std::vector<unsigned char> rgb;
    for (int y = out.height() - 1; y >= 0; --y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < 3; ++c)
                rgb.push_back(rgba[(static_cast<std::size_t>(y) * out.width() + x) * 4 + c]);
    return rgb;
}

// A one-row image with `values` as grey pixels.
Image greyRow(const std::vector<float>& values)
{
    Image image{static_cast<int>(values.size()), 1, {}};
    for (float v : values)
        image.rgb.insert(image.rgb.end(), {v, v, v});
    return image;
}

// The classic look (8-bit values linear and clamped), which the box filter and FXAA tests
// compare with exact coverages; the default look has its own test.
const DisplaySettings kClassic{.toneCurve = ToneCurve::None, .srgb = false};
const DisplaySettings kClassicFxaa{.toneCurve = ToneCurve::None, .srgb = false, .antialiasing = Antialiasing::Fxaa};

const std::vector<float> kInputs{0.0f,  0.001f, 0.0031308f, 0.01f, 0.05f, 0.18f, 0.25f, 0.5f,
                                 0.75f, 1.0f,   1.5f,       2.0f,  4.0f,  16.0f, 100.0f};

double srgbEncode(double c)
{
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// The output must be the formula's value quantised to 8 bits: within half a level, plus
// 0.25 level for the GPU's float arithmetic (pow, log2 and division are not exact).
void expectCurve(const DisplaySettings& settings, const std::function<double(double)>& formula)
{
    const std::vector<unsigned char> out = runDisplay(greyRow(kInputs), settings);
    for (std::size_t i = 0; i < kInputs.size(); ++i) {
        const double expected = 255.0 * std::clamp(formula(kInputs[i]), 0.0, 1.0);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(out[i * 3 + c], expected, 0.75) << "input " << kInputs[i];
    }
}

TEST_F(DisplayPassTest, ExposureScalesByPowersOfTwo)
{
    expectCurve({.exposure = 2.0f, .toneCurve = ToneCurve::None, .srgb = false}, [](double x) { return 4.0 * x; });
    expectCurve({.exposure = -1.5f, .toneCurve = ToneCurve::None, .srgb = false},
                [](double x) { return x * std::pow(2.0, -1.5); });
}

TEST_F(DisplayPassTest, SrgbEncodingAtTheStandardsBreakpoints)
{
    // IEC 61966-2-1: the linear segment up to 0.0031308 (12.92 c), the power segment above.
    expectCurve({.toneCurve = ToneCurve::None, .srgb = true}, srgbEncode);
    // Spot values of the standard's table: 0.0031308 -> 0.040449936, 0.18 -> 0.46135612.
    const std::vector<unsigned char> out =
        runDisplay(greyRow({0.0031308f, 0.18f, 1.0f}), {.toneCurve = ToneCurve::None, .srgb = true});
    EXPECT_EQ(out[0], 10);   // 255 · 0.04045 = 10.31
    EXPECT_EQ(out[3], 118);  // 255 · 0.46136 = 117.65
    EXPECT_EQ(out[6], 255);
}

TEST_F(DisplayPassTest, ReinhardIsXOverOnePlusX)
{
    expectCurve({.toneCurve = ToneCurve::Reinhard, .srgb = false}, [](double x) { return x / (1.0 + x); });
    expectCurve({.toneCurve = ToneCurve::Reinhard, .srgb = true}, [](double x) { return srgbEncode(x / (1.0 + x)); });
}

TEST_F(DisplayPassTest, AcesIsNarkowiczsFit)
{
    const auto aces = [](double x) { return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14); };
    expectCurve({.toneCurve = ToneCurve::Aces, .srgb = false}, aces);
    expectCurve({.exposure = 1.0f, .toneCurve = ToneCurve::Aces, .srgb = true},
                [&](double x) { return srgbEncode(aces(2.0 * x)); });
}

// AgX on a grey, typed from Wrensch's post: the inset matrix's rows sum to 1 - 0.0008 or so,
// so a grey stays grey through it, and the outset matrix's rows sum to 1.091...
double agx(double x)
{
    const double inset = 0.842479062253094 + 0.0784335999999992 + 0.0792237451477643;
    const double minStops = -12.47393;
    const double maxStops = 4.026069;
    double v = std::max(x, 0.0) * inset;
    v = (std::clamp(std::log2(std::max(v, 1e-10)), minStops, maxStops) - minStops) / (maxStops - minStops);
    const double v2 = v * v;
    const double v4 = v2 * v2;
    v = 15.5 * v4 * v2 - 40.14 * v4 * v + 31.96 * v4 - 6.868 * v2 * v + 0.4298 * v2 + 0.1191 * v - 0.00232;
    const double outset = 1.19687900512017 - 0.0980208811401368 - 0.0990297440797205;
    return std::pow(std::clamp(v * outset, 0.0, 1.0), 2.2);
}

TEST_F(DisplayPassTest, AgxIsWrenschsMinimalFit) { expectCurve({.toneCurve = ToneCurve::Agx, .srgb = false}, agx); }

// Khronos PBR Neutral (2024) on colours, each worked by hand from the specification
// (github.com/KhronosGroup/ToneMapping, PBR_Neutral): offset o = t − 6.25 t² for the darkest
// channel t below 0.08, else 0.04; below a peak of 0.76 the colour minus o is the output;
// above, n = 1 − 0.24² / (p − 0.52), every channel times n / p, then mixed towards n by
// g = 1 − 1 / (0.15 (p − n) + 1). In 8-bit linear values (× 255):
struct NeutralCase {
    glm::vec3 input;
    glm::dvec3 output;
};
const NeutralCase kNeutralCases[] = {
    // Black stays black: t = 0, o = 0.
    {{0.0f, 0.0f, 0.0f}, {0.0, 0.0, 0.0}},
    // A dark grey: t = 0.05, o = 0.05 − 0.015625 = 0.034375, out 0.015625 = 6.25 t².
    {{0.05f, 0.05f, 0.05f}, {0.015625, 0.015625, 0.015625}},
    // Below the shoulder only the offset: (0.5, 0.3, 0.2) − 0.04.
    {{0.5f, 0.3f, 0.2f}, {0.46, 0.26, 0.16}},
    // The darkest channel in the toe: t = 0.04, o = 0.03, so (0.77, 0.37, 0.01) with p = 0.77:
    // n = 1 − 0.0576 / 0.25 = 0.7696, scale 0.7696 / 0.77, g = 1 − 1 / 1.00006 = 6.0e-5.
    {{0.8f, 0.4f, 0.04f}, {0.7696, 0.369832, 0.010040}},
    // Just over the shoulder: (0.86, 0.56, 0.26), n = 1 − 0.0576 / 0.34 = 0.830588,
    // scale 0.965800, g = 1 − 1 / 1.004412 = 0.004392.
    {{0.9f, 0.6f, 0.3f}, {0.830588, 0.542121, 0.253653}},
    // Bright: (3.96, 1.96, 0.96), n = 1 − 0.0576 / 3.44 = 0.983256, scale 0.248297,
    // g = 1 − 1 / 1.446512 = 0.308682: (0.983256, 0.486662 + g · 0.496594, 0.238365 + g · 0.744891).
    {{4.0f, 2.0f, 1.0f}, {0.983256, 0.639951, 0.468299}},
    // Far past white, a saturated red whitens: (15.96, 0.96, 0.21), n = 0.996269,
    // g = 1 − 1 / 3.244560 = 0.691792.
    {{16.0f, 1.0f, 0.25f}, {0.996269, 0.707681, 0.693251}},
    // 1.0 is not white: (0.96, ...), n = 1 − 0.0576 / 0.44 = 0.869091.
    {{1.0f, 1.0f, 1.0f}, {0.869091, 0.869091, 0.869091}},
};

TEST_F(DisplayPassTest, PbrNeutralIsKhronossSpecification)
{
    Image row{static_cast<int>(std::size(kNeutralCases)), 1, {}};
    for (const NeutralCase& c : kNeutralCases)
        row.rgb.insert(row.rgb.end(), {c.input.r, c.input.g, c.input.b});
    // Linear 8-bit values, then sRGB-encoded ones (finer in the darks): the formula's value
    // quantised, within half a level plus 0.25 for the GPU's arithmetic, as expectCurve.
    for (const bool srgb : {false, true}) {
        const std::vector<unsigned char> out = runDisplay(row, {.toneCurve = ToneCurve::PbrNeutral, .srgb = srgb});
        for (std::size_t i = 0; i < std::size(kNeutralCases); ++i)
            for (int c = 0; c < 3; ++c) {
                const double value = kNeutralCases[i].output[c];
                EXPECT_NEAR(out[i * 3 + c], 255.0 * (srgb ? srgbEncode(value) : value), 0.75)
                    << "case " << i << " channel " << c << (srgb ? " (sRGB)" : "");
            }
    }
}

TEST_F(DisplayPassTest, PbrNeutralReferenceAgreesWithTheHandWorkedValues)
{
    // tests/support/PbrNeutral.h, which the default-look tests use, pinned to the same values.
    for (const NeutralCase& c : kNeutralCases) {
        const std::array<double, 3> out = test::pbrNeutral({c.input.r, c.input.g, c.input.b});
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(out[i], c.output[i], 1e-6) << c.input.r << " " << c.input.g << " " << c.input.b;
    }
}

double pbrNeutralGrey(double x) { return test::pbrNeutral({x, x, x})[0]; }

TEST_F(DisplayPassTest, DefaultSettingsArePbrNeutralThenSrgb)
{
    // The default look (SPEC.md §3 since 2026-11-25; the curve PBR Neutral since issue 48,
    // docs/display.md): every input of kInputs through PBR Neutral, then the sRGB encoding,
    // within the same 0.75 level as each curve alone.
    expectCurve({}, [](double x) { return srgbEncode(pbrNeutralGrey(x)); });
    expectCurve({.exposure = -1.0f}, [](double x) { return srgbEncode(pbrNeutralGrey(0.5 * x)); });
}

TEST_F(DisplayPassTest, AgxThenSrgbIsTheFusedStep)
{
    // AgX with sRGB takes the pass's one-log2 path (agxSrgbEncoded): the same function as the
    // curve, then the encoding.
    expectCurve({.toneCurve = ToneCurve::Agx}, [](double x) { return srgbEncode(agx(x)); });
    expectCurve({.exposure = -1.0f, .toneCurve = ToneCurve::Agx}, [](double x) { return srgbEncode(agx(0.5 * x)); });
}

TEST_F(DisplayPassTest, CurvesAreMonotonicAndKeepBlackBlack)
{
    for (ToneCurve curve : {ToneCurve::Reinhard, ToneCurve::Aces, ToneCurve::Agx, ToneCurve::PbrNeutral}) {
        const std::vector<unsigned char> out = runDisplay(greyRow(kInputs), {.toneCurve = curve, .srgb = true});
        EXPECT_LE(out[0], 1) << toneCurveName(curve);
        for (std::size_t i = 1; i < kInputs.size(); ++i)
            EXPECT_GE(out[i * 3], out[(i - 1) * 3]) << toneCurveName(curve) << " at " << kInputs[i];
    }
}

TEST_F(DisplayPassTest, SupersamplingIsTheBoxFilterInLinearLight)
{
    Image input{16, 8, {}};
    for (int i = 0; i < 16 * 8 * 3; ++i)
        input.rgb.push_back(static_cast<float>((i * 37) % 101) / 100.0f);
    for (int factor : {2, 4}) {
        const std::vector<unsigned char> out = runDisplay(input, kClassic, factor);
        const Image expected = boxDownsample(input, factor);
        ASSERT_EQ(out.size(), expected.rgb.size());
        for (std::size_t i = 0; i < out.size(); ++i)
            EXPECT_NEAR(out[i], 255.0 * expected.rgb[i], test::kEightBitConversionTolerance)
                << "value " << i << ", factor " << factor;
    }
}

// A black-and-white half-plane across a 64x64 image: its edge runs at a shallow angle (1 in
// 5), where aliasing shows as long stair steps. coverage: the exact area of each pixel on the
// white side (256 sub-samples); aliased: one sample at each pixel's centre.
struct Edge {
    Image aliased;
    Image coverage;
};
Edge shallowEdge()
{
    constexpr int kSize = 64;
    Edge edge{{kSize, kSize, {}}, {kSize, kSize, {}}};
    const auto white = [](double x, double y) { return y < 20.0 + x / 5.0; };
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            int inside = 0;
            for (int sy = 0; sy < 16; ++sy)
                for (int sx = 0; sx < 16; ++sx)
                    inside += white(x + (sx + 0.5) / 16.0, y + (sy + 0.5) / 16.0);
            const float area = static_cast<float>(inside) / 256.0f;
            const float centre = white(x + 0.5, y + 0.5) ? 1.0f : 0.0f;
            edge.coverage.rgb.insert(edge.coverage.rgb.end(), {area, area, area});
            edge.aliased.rgb.insert(edge.aliased.rgb.end(), {centre, centre, centre});
        }
    return edge;
}

double meanError(const std::vector<unsigned char>& bytes, const Image& truth)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < bytes.size(); ++i)
        sum += std::abs(bytes[i] / 255.0 - truth.rgb[i]);
    return sum / static_cast<double>(bytes.size());
}

TEST_F(DisplayPassTest, FxaaLeavesFlatAndSmoothRegionsUnchanged)
{
    // A flat colour, and a gentle gradient (its steps stay under FXAA's edge threshold).
    Image flat{48, 32, {}};
    Image gradient{48, 32, {}};
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            flat.rgb.insert(flat.rgb.end(), {0.6f, 0.2f, 0.4f});
            gradient.rgb.insert(gradient.rgb.end(), {0.3f + 0.004f * static_cast<float>(x + y),
                                                     0.5f - 0.003f * static_cast<float>(x), 0.4f});
        }
    for (const Image& input : {flat, gradient})
        EXPECT_EQ(runDisplay(input, kClassic), runDisplay(input, kClassicFxaa));
}

TEST_F(DisplayPassTest, FxaaBringsAnAliasedEdgeCloserToItsCoverage)
{
    const Edge edge = shallowEdge();
    const std::vector<unsigned char> aliased = runDisplay(edge.aliased, kClassic);
    const std::vector<unsigned char> antialiased = runDisplay(edge.aliased, kClassicFxaa);
    const double before = meanError(aliased, edge.coverage);
    const double after = meanError(antialiased, edge.coverage);
    // The measured figures, for docs/display.md.
    std::printf("FXAA on a shallow edge: mean error %.4f aliased, %.4f anti-aliased (%.2f x)\n", before, after,
                after / before);
    // Measured: mean error 0.0041 aliased, 0.0018 after FXAA (0.43 x). The bound asks for at
    // least a third less: a pass that left the edge as it was fails it.
    EXPECT_LT(after, 0.67 * before) << "mean error before " << before << ", after " << after;
    // Far from the edge nothing changes.
    for (int x = 0; x < 64; ++x) {
        EXPECT_EQ(antialiased[(2 * 64 + x) * 3], 255);
        EXPECT_EQ(antialiased[(60 * 64 + x) * 3], 0);
    }
}

// A depth texture of `image`'s size: 0.5 (a surface) where `covered`, 1 (background) elsewhere.
gl::Texture2D depthOf(const Image& image, const std::function<bool(int, int)>& covered)
{
    gl::Texture2D depth("display test depth", GL_DEPTH_COMPONENT32F, image.width, image.height);
    std::vector<float> values;
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x)
            values.push_back(covered(x, y) ? 0.5f : 1.0f);
    glTextureSubImage2D(depth.id(), 0, 0, 0, image.width, image.height, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
    return depth;
}

TEST_F(DisplayPassTest, LogAverageLuminanceIsTheGeometricMeanOfTheSurfaces)
{
    const auto everywhere = [](int, int) { return true; };
    // Grey 0.5 everywhere: the average is 0.5 (plus the 1e-4 that keeps log(0) away).
    Image grey{64, 36, std::vector<float>(64 * 36 * 3, 0.5f)};
    DisplayPass pass;
    EXPECT_NEAR(pass.logAverageLuminance(uploadLinear(grey), depthOf(grey, everywhere)), 0.5f, 2e-4f);
    // The top half at 0.1, the bottom at 1.0: the geometric mean sqrt(0.1 · 1.0), not the
    // arithmetic 0.55 (a few bright pixels must not dim the whole picture).
    Image halves{64, 36, {}};
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x)
            halves.rgb.insert(halves.rgb.end(), 3, y < 18 ? 0.1f : 1.0f);
    EXPECT_NEAR(pass.logAverageLuminance(uploadLinear(halves), depthOf(halves, everywhere)), std::sqrt(0.1f), 1e-3f);
    // With the top half background, only the bottom's surfaces count.
    EXPECT_NEAR(pass.logAverageLuminance(uploadLinear(halves), depthOf(halves, [](int, int y) { return y >= 18; })),
                1.0f, 1e-3f);
    // No surface at all: middle grey, so that auto-exposure stays at 0.
    EXPECT_FLOAT_EQ(pass.logAverageLuminance(uploadLinear(halves), depthOf(halves, [](int, int) { return false; })),
                    0.18f);
}

}  // namespace
}  // namespace manylights
