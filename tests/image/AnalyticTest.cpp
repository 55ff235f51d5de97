// Analytic scenes: the expected colour of each pixel follows from docs/lighting.md by hand. The
// tests render the final image and the position view as PFM (unclamped floats) and compare
// every covered pixel with the formula evaluated at that pixel's world position, written
// here independently of the renderer's shaders, in double precision.
//
// Every test runs for every technique, with the seed G-buffer layout: these tests check the
// lighting formula to float precision, which the compact layout's 8-bit kd (e.g. 0.5 stored as
// 128/255) would blur; the compact layout is held to forward by TechniqueAgreementTest and to
// the hand-derived normal-mapping result below.
//
// Tolerance: 2e-5 absolute + 1e-4 relative. The renderer works in 32-bit floats: positions
// of about 10 units carry ~1e-6 absolute error, and pow(), normalize() and the sum of a few
// terms add a few ulps (~1e-6 relative each); GPUs may use faster, less exact pow and
// inversesqrt. A wrong formula (a missing factor, a wrong exponent, the radius cut in the
// wrong place) is off by orders of magnitude more.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <tuple>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "AnalyticSupport.h"
#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::checkEveryPixel;
using test::Expected;
using test::kTopCamera;
using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

constexpr double kAbsoluteTolerance = test::kAnalyticTolerance.absolute;  // 2e-5, tests/support/ImageComparison.h
constexpr double kRelativeTolerance = test::kAnalyticTolerance.relative;  // 1e-4

class Analytic : public ::testing::TestWithParam<std::string> {};

TEST_P(Analytic, PointLightAboveDiffusePlane)
{
    // kd = 0.5, light 2 above the origin, A(d) = 1 / (1 + 0.25 d²).
    // Under the light: d = 2, N·L = 1, A = 1/2, so the colour is 0.5 · 1 · 0.5 = 0.25.
    // Elsewhere at distance r from the origin: d = sqrt(r² + 4), N·L = 2 / d.
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "lights": [{"type": "point", "pos": [0, 2, 0], "intensity": [1, 1, 1],
                    "attenuation": {"constant": 1, "linear": 0, "quadratic": 0.25}}],
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [{"mesh": {"primitive": "plane", "size": [40, 40]}, "material": "grey"}]})";
    const auto expected = [](const glm::dvec3& p) {
        const double d = std::sqrt(p.x * p.x + p.z * p.z + 4.0);
        return glm::dvec3(0.5 * (2.0 / d) / (1.0 + 0.25 * d * d));
    };
    EXPECT_EQ(checkEveryPixel(scene, expected), 65 * 65);

    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", scene);
    const Image image = renderPfm((dir / "scene.json").string(), dir / "final.pfm",
                                  {"--size", "65x65", "--technique", GetParam(), "--gbuffer", "seed"});
    const float* centre = image.pixel(32, 32);
    EXPECT_NEAR(centre[0], 0.25, 1e-6);
    EXPECT_NEAR(centre[1], 0.25, 1e-6);
    EXPECT_NEAR(centre[2], 0.25, 1e-6);
}

TEST_P(Analytic, DirectionalLightOnTiltedPlane)
{
    // The plane turned 30° about X has the normal (0, cos 30°, sin 30°); light falling
    // straight down gives N·L = cos 30° = 0.8660254 everywhere. With ambient 0.1:
    // colour = kd · (0.1 + 0.8660254) = (0.7728203, 0.5796152, 0.3864102).
    const std::string scene = R"({
        "camera": {"eye": [0, 6, 8], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
        "ambient": [0.1, 0.1, 0.1],
        "directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1]},
        "materials": {"m": {"diffuse": [0.8, 0.6, 0.4]}},
        "objects": [{"mesh": {"primitive": "plane", "size": [4, 4]}, "material": "m",
                     "transform": {"rotate": [30, 0, 0]}}]})";
    const auto expected = [](const glm::dvec3&) { return glm::dvec3(0.7728203, 0.5796152, 0.3864102); };
    EXPECT_GT(checkEveryPixel(scene, expected), 500);
}

TEST_P(Analytic, SpotLightConeEdge)
{
    // Spot 4 above the plane pointing down, cutoff 30°, exponent 2, constant attenuation
    // (a = b = 0: unbounded, A = 1). At distance r from the axis: d = sqrt(r² + 16),
    // cos θ = 4 / d = N·L. Inside the cone (cos θ ≥ cos 30°, r ≤ 4 tan 30° = 2.3094) the
    // colour is kd · N·L · cos²θ = (4/d)³; outside it is exactly 0.
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "lights": [{"type": "spot", "pos": [0, 4, 0], "direction": [0, -1, 0], "cutoff": 30, "exponent": 2,
                    "intensity": [1, 1, 1], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}}],
        "objects": [{"mesh": {"primitive": "plane", "size": [12, 12]}, "material": {"diffuse": [1, 1, 1]}}]})";
    int inside = 0;
    int outside = 0;
    const double cosCutoff = std::cos(glm::radians(30.0));
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const double d = std::sqrt(p.x * p.x + p.z * p.z + 16.0);
        const double cosTheta = 4.0 / d;
        if (std::abs(cosTheta - cosCutoff) < 1e-5)
            return std::nullopt;
        if (cosTheta < cosCutoff) {
            ++outside;
            return glm::dvec3(0.0);
        }
        ++inside;
        return glm::dvec3(cosTheta * cosTheta * cosTheta);
    };
    checkEveryPixel(scene, expected);
    EXPECT_GT(inside, 300);
    EXPECT_GT(outside, 300);
}

// Range falloff r = 6: A(d) = 1/max(d, 0.06)² − 1/36 for d < 6, else 0, and a specular term
// ks · max(N·H, 0)^s with H = normalize(L + V), V towards the eye at (0, 10, 0), on a floor
// whose halves x < 0 and x > 0 have shininess `left` and `right`.
void checkRangeFalloffWithSpecularHighlight(const std::string& left, const std::string& right)
{
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "lights": [{"type": "point", "pos": [1, 1.5, 0.5], "intensity": [0.8, 0.6, 0.4], "range": 6}],
        "materials": {"left": {"diffuse": [0.5, 0.5, 0.5], "specular": [0.5, 0.5, 0.5], "shininess": )" +
                              left + R"(},
                      "right": {"diffuse": [0.5, 0.5, 0.5], "specular": [0.5, 0.5, 0.5], "shininess": )" +
                              right + R"(}},
        "objects": [{"mesh": {"primitive": "plane", "size": [10, 20]}, "material": "left",
                     "transform": {"translate": [-5, 0, 0]}},
                    {"mesh": {"primitive": "plane", "size": [10, 20]}, "material": "right",
                     "transform": {"translate": [5, 0, 0]}}]})";
    const double leftExponent = std::stod(left);
    const double rightExponent = std::stod(right);
    const glm::dvec3 light(1, 1.5, 0.5);
    const glm::dvec3 intensity(0.8, 0.6, 0.4);
    const glm::dvec3 eye(0, 10, 0);
    const glm::dvec3 n(0, 1, 0);
    int unlit = 0;
    int highlighted[2] = {0, 0};  // pixels where the specular term is visible, per half
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        if (std::abs(p.x) < 1e-4)
            return std::nullopt;  // the seam, where either half may be drawn
        const double d = glm::length(p - light);
        if (d >= 6.0) {
            ++unlit;
            return glm::dvec3(0.0);
        }
        const double attenuation = 1.0 / (std::max(d, 0.06) * std::max(d, 0.06)) - 1.0 / 36.0;
        const glm::dvec3 l = (light - p) / d;
        const glm::dvec3 v = glm::normalize(eye - p);
        const glm::dvec3 h = glm::normalize(l + v);
        const double specular = 0.5 * std::pow(std::max(glm::dot(n, h), 0.0), p.x < 0.0 ? leftExponent : rightExponent);
        highlighted[p.x < 0.0 ? 0 : 1] += specular > 1e-3 ? 1 : 0;
        return intensity * (0.5 * glm::dot(n, l) + specular) * attenuation;
    };
    checkEveryPixel(scene, expected);
    EXPECT_GT(unlit, 100);  // the corners lie beyond the range and must be exactly black
    EXPECT_GT(highlighted[0], 10);
    EXPECT_GT(highlighted[1], 10);
}

TEST_P(Analytic, RangeFalloffWithSpecularHighlight)
{
    // A few integer shininesses in the scene: the programs raise N·H to them by multiplications
    // (render/programs/LightingPrograms.h, specularExponents), 16 by squarings alone, 13 (binary 1101) and
    // 40 (101000) by squarings and products, picked per surface. A fractional one takes pow().
    for (const auto& [left, right] : {std::pair<std::string, std::string>{"16", "16"}, {"13", "40"}, {"16", "12.5"}}) {
        SCOPED_TRACE("shininess " + left + " and " + right);
        checkRangeFalloffWithSpecularHighlight(left, right);
    }
}

TEST_P(Analytic, ClassicLightIsCutAtItsThresholdRadius)
{
    // c = 1, a = 1, Imax = 1, threshold 0.05: A(R) = 0.05 at R = sqrt(19) = 4.3589 (from
    // 1 + R² = 20). The light is 1 above the plane, so on the plane the cut falls at
    // r = sqrt(R² − 1) = sqrt(18) = 4.2426: inside, kd · N·L · A with N·L = 1/d; outside, 0.
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "attenuation_threshold": 0.05,
        "lights": [{"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1],
                    "attenuation": {"constant": 1, "linear": 0, "quadratic": 1}}],
        "objects": [{"mesh": {"primitive": "plane", "size": [12, 12]}, "material": {"diffuse": [1, 1, 1]}}]})";
    int inside = 0;
    int outside = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const double d = std::sqrt(p.x * p.x + p.z * p.z + 1.0);
        if (std::abs(d - std::sqrt(19.0)) < 1e-4)
            return std::nullopt;
        if (d >= std::sqrt(19.0)) {
            ++outside;
            return glm::dvec3(0.0);
        }
        ++inside;
        return glm::dvec3((1.0 / d) / (1.0 + d * d));
    };
    checkEveryPixel(scene, expected);
    EXPECT_GT(inside, 300);
    EXPECT_GT(outside, 300);
}

TEST_P(Analytic, EmissiveAndAmbientWithoutLights)
{
    // No lights: colour = ke + ambient ⊙ kd = (0.1, 0.2, 0.3) + (0.5, 0.25, 0.2) ⊙ (0.2, 0.4, 1).
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "ambient": [0.5, 0.25, 0.2], "background": [0.3, 0.6, 0.9],
        "objects": [{"mesh": {"primitive": "box", "size": [2, 2, 2]},
                     "material": {"diffuse": [0.2, 0.4, 1], "emissive": [0.1, 0.2, 0.3]}}]})";
    const auto expected = [](const glm::dvec3&) { return glm::dvec3(0.2, 0.3, 0.5); };
    EXPECT_GT(checkEveryPixel(scene, expected), 100);
    // The background is the scene's background colour, exactly.
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", scene);
    const Image image = renderPfm((dir / "scene.json").string(), dir / "final.pfm",
                                  {"--size", "65x65", "--technique", GetParam(), "--gbuffer", "seed"});
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[0], 0.3f);
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[1], 0.6f);
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[2], 0.9f);
}

TEST_P(Analytic, ConstantNormalMapTiltsTheShadingNormal)
{
    // A plane (normal +Y; uvs: u along +X, v along −Z, so T = +X, B = −Z, w = +1) with the
    // constant normal map tests/scenes/textures/tilt30.png: every texel encodes the unit vector
    // tilted 30° from +Z towards the uv diagonal, t = (sin 30°/√2, sin 30°/√2, cos 30°). In
    // world space N' = normalize(t.x·T + t.y·B + t.z·N) = normalize(t.x, t.z, −t.y). A
    // directional light travelling along (−1, −1, 1), L = (1, 1, −1)/√3, no other light:
    //   colour = kd · (ambient + max(N'·L, 0)),   N'·L = (t.x + t.z + t.y) / (√3 |t|).
    // Ideal t gives N'·L = (0.70711 + 0.86603) / √3 = 0.90825; the map holds t rounded to 8 bits
    // per component (≤ 1/255 each after 2·byte/255 − 1), so the expected value is computed from
    // the stored bytes: the only error left is the renderer's float rounding. A flipped tangent
    // gives (−t.x + t.z + t.y)/√3 = 0.5, a flipped bitangent the same, no normal map 0.57735.
    const std::string texture = MANYLIGHTS_SOURCE_DIR "/tests/scenes/textures/tilt30.png";
    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* texels = stbi_load(texture.c_str(), &width, &height, &channels, 3);
    ASSERT_NE(texels, nullptr);
    const glm::dvec3 t = glm::dvec3(texels[0], texels[1], texels[2]) * (2.0 / 255.0) - 1.0;
    for (int i = 0; i < width * height * 3; ++i)
        ASSERT_EQ(texels[i], texels[i % 3]) << "the map must be constant";
    stbi_image_free(texels);
    const double ideal =
        (std::sin(std::numbers::pi / 6) * std::sqrt(2.0) + std::cos(std::numbers::pi / 6)) / std::sqrt(3.0);
    const double NdotL = (t.x + t.y + t.z) / (std::sqrt(3.0) * glm::length(t));
    EXPECT_NEAR(NdotL, ideal, 2.0 / 255.0);  // the stored map is the one described above

    // kd = (0.8, 0.6, 0.4) are 204/255, 153/255, 102/255: exact in the compact layout's 8 bits.
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "ambient": [0.1, 0.1, 0.1],
        "directional": {"direction": [-1, -1, 1], "intensity": [1, 1, 1]},
        "materials": {"bumped": {"diffuse": [0.8, 0.6, 0.4], "normal_map": ")" +
                              texture + R"("}},
        "objects": [{"mesh": {"primitive": "plane", "size": [40, 40]}, "material": "bumped"}]})";
    const glm::dvec3 expected = glm::dvec3(0.8, 0.6, 0.4) * (0.1 + NdotL);
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", scene);
    // Seed layout: float rounding only (the file's tolerance). Compact layout: the octahedral
    // normal (RG16) moves N'·L by ≤ 5e-5 (docs/gbuffer.md), times kd ≤ 0.8: 4e-5 more.
    for (const auto& [layout, extra] : {std::pair<std::string, double>{"seed", 0.0}, {"compact", 4e-5}}) {
        const Image image = renderPfm((dir / "scene.json").string(), dir / (layout + ".pfm"),
                                      {"--size", "65x65", "--technique", GetParam(), "--gbuffer", layout});
        // The centre pixels (the map is constant, so every pixel agrees; the centre ones are
        // far from any edge).
        for (int y = 30; y <= 34; ++y)
            for (int x = 30; x <= 34; ++x)
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(image.pixel(x, y)[c], expected[c],
                                kAbsoluteTolerance + kRelativeTolerance * expected[c] + extra)
                        << layout << " layout, pixel (" << x << ", " << y << ") channel " << c;
    }
}

// --- transparency (docs/transparency.md) -------------------------------------------------

// "Over" with the front surface's opacity: the colour a transparent layer leaves.
glm::dvec3 over(const glm::dvec3& front, double opacity, const glm::dvec3& behind)
{
    return opacity * front + (1.0 - opacity) * behind;
}

// Whether the eye ray to plane point p (y = 0) crosses y = height inside |x - cx| < hx,
// |z| < hz; nullopt within 1e-3 of the rectangle's edge.
std::optional<bool> rayCrossesRectangle(const glm::dvec3& eye, const glm::dvec3& p, double height, double cx, double hx,
                                        double hz)
{
    const glm::dvec3 q = eye + (p - eye) * ((eye.y - height) / (eye.y - p.y));
    if (std::abs(std::abs(q.x - cx) - hx) < 1e-3 || std::abs(std::abs(q.z) - hz) < 1e-3)
        return std::nullopt;
    return std::abs(q.x - cx) < hx && std::abs(q.z) < hz;
}

// A 2x2 quad at y = 1 (kd (1, 0.5, 0.25), the material keys `glassKeys` make it transparent)
// over a grey plane (kd 0.5), ambient 0.2, a directional light straight down (N·L = 1 on
// both; no specular): each surface is kd · 1.2, and where the quad covers the plane the pixel
// is coverage · quad + (1 − coverage) · plane. The position view holds the opaque surface (the
// plane) under every pixel. Files go to `dir` (the glass keys may name a map there).
void checkQuadOverPlane(const std::string& glassKeys, double coverage, const std::filesystem::path& dir)
{
    const std::string scene = std::string("{") + kTopCamera + R"(,
        "ambient": [0.2, 0.2, 0.2],
        "directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1]},
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]},
                      "glass": {"diffuse": [1, 0.5, 0.25], )" +
                              glassKeys + R"(}},
        "objects": [{"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
                    {"mesh": {"primitive": "plane", "size": [2, 2]}, "material": "glass",
                     "transform": {"translate": [0, 1, 0]}}]})";
    const glm::dvec3 eye(0, 10, 0);
    const glm::dvec3 plane(0.5 * 1.2);
    const glm::dvec3 glass = glm::dvec3(1.0, 0.5, 0.25) * 1.2;
    int covered = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const auto under = rayCrossesRectangle(eye, p, 1.0, 0.0, 1.0, 1.0);
        if (!under)
            return std::nullopt;
        if (!*under)
            return plane;
        ++covered;
        return over(glass, coverage, plane);
    };
    EXPECT_EQ(checkEveryPixel(scene, expected, "65x65", dir), 65 * 65);
    EXPECT_GT(covered, 100);
}

TEST_P(Analytic, HalfTransparentQuadIsTheOverOfBothShadedColours)
{
    checkQuadOverPlane(R"("opacity": 0.4)", 0.4, scratchDirectory());
}

TEST_P(Analytic, OverlappingPanesInEitherOrderGiveTheBackToFrontResult)
{
    // Pane A (y = 1, x in [−2, 1], kd (1, 0.2, 0.2), opacity 0.5) under pane B (y = 2, x in
    // [−1, 2], kd (0.2, 0.2, 1), opacity 0.25), both 2 deep, over the grey plane; lit as above.
    // Where both cover the plane: over(B, over(A, plane)), whichever order the scene lists them.
    const std::string paneA = R"({"mesh": {"primitive": "plane", "size": [3, 2]}, "material": "red glass",
                                  "transform": {"translate": [-0.5, 1, 0]}})";
    const std::string paneB = R"({"mesh": {"primitive": "plane", "size": [3, 2]}, "material": "blue glass",
                                  "transform": {"translate": [0.5, 2, 0]}})";
    const auto scene = [&](const std::string& first, const std::string& second) {
        return std::string("{") + kTopCamera + R"(,
            "ambient": [0.2, 0.2, 0.2],
            "directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1]},
            "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]},
                          "red glass": {"diffuse": [1, 0.2, 0.2], "opacity": 0.5},
                          "blue glass": {"diffuse": [0.2, 0.2, 1], "opacity": 0.25}},
            "objects": [)" +
               first + ", " + second + R"(,
                        {"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"}]})";
    };
    const glm::dvec3 eye(0, 10, 0);
    const glm::dvec3 plane(0.5 * 1.2);
    const glm::dvec3 red = glm::dvec3(1.0, 0.2, 0.2) * 1.2;
    const glm::dvec3 blue = glm::dvec3(0.2, 0.2, 1.0) * 1.2;
    int both = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const auto underA = rayCrossesRectangle(eye, p, 1.0, -0.5, 1.5, 1.0);
        const auto underB = rayCrossesRectangle(eye, p, 2.0, 0.5, 1.5, 1.0);
        if (!underA || !underB)
            return std::nullopt;
        glm::dvec3 colour = plane;
        if (*underA)
            colour = over(red, 0.5, colour);
        if (*underB)
            colour = over(blue, 0.25, colour);
        if (*underA && *underB)
            ++both;
        return colour;
    };
    checkEveryPixel(scene(paneA, paneB), expected);
    const int bothInOneOrder = both;
    EXPECT_GT(bothInOneOrder, 100);
    both = 0;
    checkEveryPixel(scene(paneB, paneA), expected);
    EXPECT_EQ(both, bothInOneOrder);
}

TEST_P(Analytic, TransparentSurfacesNearerAndFartherThanEveryOpaqueOneGetTheirLights)
{
    // The opaque surfaces: one box at the origin. Quad N (kd (1, 0.5, 0.25), opacity 0.5)
    // hangs at (−2, 2, 6), nearer than any opaque surface; quad F (kd (0.25, 0.5, 1),
    // opacity 0.5) at (2, 2, −20), beyond them all, with only the black background behind it.
    // Each faces the camera (+Z) and has a small light 0.5 in front of its centre (range 1.5,
    // intensity 1: A = 1/0.25 − 1/2.25 at the centre, N·L = 1) that reaches nothing else;
    // ambient 0.1. At the pixel nearest each quad's centre the colour is 0.5 · kd · (0.1 +
    // A(d) · N·L) at the point it sees, over black: a grid fitted to the opaque surfaces'
    // depths would have no cluster there and leave it at 0.5 · kd · 0.1.
    const std::string scene = R"({
        "camera": {"eye": [0, 2, 10], "look_at": [0, 2, 0], "up": [0, 1, 0], "fov_y": 60, "near": 0.1, "far": 100},
        "ambient": [0.1, 0.1, 0.1],
        "lights": [{"type": "point", "pos": [-2, 2, 6.5], "intensity": [1, 1, 1], "range": 1.5},
                   {"type": "point", "pos": [2, 2, -19.5], "intensity": [1, 1, 1], "range": 1.5}],
        "materials": {"near glass": {"diffuse": [1, 0.5, 0.25], "opacity": 0.5},
                      "far glass": {"diffuse": [0.25, 0.5, 1], "opacity": 0.5}},
        "objects": [{"mesh": {"primitive": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 2, 0]}},
                    {"mesh": {"primitive": "plane", "size": [1, 1]}, "material": "near glass",
                     "transform": {"translate": [-2, 2, 6], "rotate": [90, 0, 0]}},
                    {"mesh": {"primitive": "plane", "size": [6, 6]}, "material": "far glass",
                     "transform": {"translate": [2, 2, -20], "rotate": [90, 0, 0]}}]})";
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", scene);
    const int width = 129;
    const int height = 65;
    const Image image = renderPfm((dir / "scene.json").string(), dir / "final.pfm",
                                  {"--size", "129x65", "--technique", GetParam(), "--gbuffer", "seed"});
    // The quads' centres on screen: x = ±2 at depth 4 and 30 from the eye; fov 60, aspect 129/65.
    const double tanHalf = std::tan(std::numbers::pi / 6);
    const double aspect = static_cast<double>(width) / height;
    const auto column = [&](double x, double depth) {
        return static_cast<int>(std::floor((0.5 + 0.5 * x / (depth * tanHalf * aspect)) * width));
    };
    for (const auto& [x, depth, kd] :
         {std::tuple{-2.0, 4.0, glm::dvec3(1, 0.5, 0.25)}, std::tuple{2.0, 30.0, glm::dvec3(0.25, 0.5, 1)}}) {
        // The point the pixel's centre sees on the quad (the centre row looks straight ahead),
        // lit by the light 0.5 in front of the quad's centre. Every technique shades the
        // point at the interpolated depth on the ray through the pixel's centre
        // (docs/lighting.md, "The shaded point"), and the quad faces the camera, so that
        // depth is its own on every driver. (When forward shaded the interpolated position
        // instead, an H100 saw a point 1/900 of a pixel beside the ray: its rasteriser snaps
        // the corners to its sub-pixel grid first. Here, where a pixel is 0.53 units wide and
        // the colour changes 5% per 0.01 units, that was 0.094% off.)
        const int px = column(x, depth);
        const double ndcX = (px + 0.5) / width * 2.0 - 1.0;
        const glm::dvec3 seen(ndcX * depth * tanHalf * aspect, 2.0, 10.0 - depth);
        const glm::dvec3 light(x, 2.0, 10.0 - depth + 0.5);
        const double d = glm::length(light - seen);
        const double attenuation = 1.0 / (d * d) - 1.0 / 2.25;
        const double NdotL = (light.z - seen.z) / d;
        const glm::dvec3 want = 0.5 * kd * (0.1 + attenuation * NdotL);
        const float* got = image.pixel(px, height / 2);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], want[c], kAbsoluteTolerance + kRelativeTolerance * want[c])
                << "quad at depth " << depth << ", channel " << c;
    }
}

TEST_P(Analytic, OpacityMapScalesTheCoverage)
{
    // The quad with opacity 0.8 and a constant grey opacity map of 128: coverage = 0.8 ·
    // 128/255 (the map's red channel, linear).
    const auto dir = scratchDirectory();
    std::vector<unsigned char> grey(8 * 8 * 3, 128);
    ASSERT_NE(stbi_write_png((dir / "grey.png").string().c_str(), 8, 8, 3, grey.data(), 8 * 3), 0);
    checkQuadOverPlane(R"("opacity": 0.8, "opacity_map": "grey.png")", 0.8 * 128.0 / 255.0, dir);
}

INSTANTIATE_TEST_SUITE_P(Techniques, Analytic, ::testing::ValuesIn(techniqueNames()), test::techniqueTestName);

}  // namespace
}  // namespace manylights
