// Shadows and ambient occlusion (docs/shadows.md), through the CLI's own path.
//
// Shadow tests are analytic: a box above a plane under a directional light. Each visible
// plane point is in the box's shadow exactly when the ray from it towards the light hits the
// box, computed here in double precision. Points in the umbra get no contribution from the
// light (docs/lighting.md: A·S treated as 0), so their colour is exactly the ambient term; points
// outside are fully lit. Points within kPenumbraMargin of the shadow's edge are skipped: the
// 3x3 percentage-closer filter blurs the edge over about two shadow-map texels (a few
// hundredths of a unit here), and the margin is several times that.
//
// Tolerance for checked pixels: the analytic tests' (2e-5 absolute + 1e-4 relative, see
// AnalyticTest.cpp); the umbra's centre pixel must equal the ambient-only value exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"
#include "tests/support/ImageComparison.h"
#include "tests/support/RayBox.h"

namespace manylights {
// Every render here uses the exact seed G-buffer layout: the expected values are docs/lighting.md
// evaluated by hand, and the compact layout's 8-bit kd (0.5 stored as 128/255) would move
// them by more than the analytic tolerance (its own bound is TechniqueAgreementTest's).
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

constexpr double kAbsoluteTolerance = test::kAnalyticTolerance.absolute;  // 2e-5, tests/support/ImageComparison.h
constexpr double kRelativeTolerance = test::kAnalyticTolerance.relative;  // 1e-4
constexpr double kPenumbraMargin = 0.05;

using test::Box;

// Whether the ray origin + t·direction (t > 0) hits the box.
bool rayHitsBox(const glm::dvec3& origin, const glm::dvec3& direction, const Box& box)
{
    return test::rayEntersBox(origin, direction, box).has_value();
}

// In shadow (true), lit (false), or too close to the shadow's edge to say (nullopt): the
// point and its neighbours kPenumbraMargin away on the plane must agree.
std::optional<bool> shadowedOnPlane(const glm::dvec3& p, const glm::dvec3& toLight, const Box& box,
                                    double margin = kPenumbraMargin)
{
    const bool centre = rayHitsBox(p, toLight, box);
    for (const glm::dvec3 offset :
         {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)})
        if (rayHitsBox(p + margin * offset, toLight, box) != centre)
            return std::nullopt;
    return centre;
}

struct Rendered {
    Image colour;
    Image position;
    Image normal;
    bool covered(int x, int y) const { return test::holdsSurface(normal, x, y); }
};

Rendered renderWithPositions(const std::string& sceneJson, const std::string& size,
                             const std::vector<std::string>& extraArgs)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", sceneJson);
    const std::string scene = (dir / "scene.json").string();
    std::vector<std::string> args = {"--gbuffer", "seed", "--size", size};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    Rendered r;
    r.colour = renderPfm(scene, dir / "final.pfm", args);
    r.position = renderPfm(scene, dir / "position.pfm", {"--gbuffer", "seed", "--size", size, "--view", "position"});
    r.normal = renderPfm(scene, dir / "normal.pfm", {"--gbuffer", "seed", "--size", size, "--view", "normal"});
    return r;
}

bool near(const float* got, const glm::dvec3& want)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(got[c] - want[c]) > kAbsoluteTolerance + kRelativeTolerance * std::abs(want[c]))
            return false;
    return true;
}

class Shadows : public ::testing::TestWithParam<std::string> {};

// Checks the plane pixels a shadow test has classified against their expected values, counts
// the shadowed and lit ones, and keeps the shadowed pixel nearest the umbra's centre, whose
// colour must then be exactly ke + ambient ⊙ kd as the shader computes it in 32-bit floats.
class ShadowChecks {
public:
    ShadowChecks(const Rendered& rendered, const glm::dvec3& umbraCentre)
        : rendered_(rendered), umbraCentre_(umbraCentre)
    {
    }

    // `counted`: whether the pixel counts towards the shadowed and lit totals.
    void check(int x, int y, const glm::dvec3& position, bool inShadow, double want, bool counted = true)
    {
        if (counted)
            ++(inShadow ? shadowed_ : lit_);
        const float* got = rendered_.colour.pixel(x, y);
        if (!near(got, glm::dvec3(want)) && ++failures_ <= 5)
            ADD_FAILURE() << "pixel (" << x << ", " << y << ") at (" << position.x << ", " << position.y << ", "
                          << position.z << "): got " << got[0] << ", expected " << want
                          << (inShadow ? " (in shadow)" : " (lit)");
        if (inShadow && glm::length(position - umbraCentre_) < nearestToCentre_) {
            nearestToCentre_ = glm::length(position - umbraCentre_);
            centreX_ = x;
            centreY_ = y;
        }
    }

    // At least this many shadowed and lit pixels were checked, none failed, and the umbra's
    // centre is exactly ambient-only: `ambient` · `kd` in floats (ke = 0).
    void expectAllPassed(int minShadowed, int minLit, float ambient, float kd) const
    {
        EXPECT_EQ(failures_, 0);
        EXPECT_GT(shadowed_, minShadowed);
        EXPECT_GT(lit_, minLit);
        ASSERT_GE(centreX_, 0);
        const float exactAmbient = ambient * kd;
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(rendered_.colour.pixel(centreX_, centreY_)[c], exactAmbient) << "umbra centre channel " << c;
    }

private:
    const Rendered& rendered_;
    glm::dvec3 umbraCentre_;
    int shadowed_ = 0;
    int lit_ = 0;
    int failures_ = 0;
    double nearestToCentre_ = 1e30;
    int centreX_ = -1;
    int centreY_ = -1;
};

// The camera straight above the origin looking down; the light falls along (1, −2, 0), so the
// shadow of the box lies on its +x side, where the camera sees it.
const char* kBoxAbovePlane = R"({
    "camera": {"eye": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 60, "near": 0.1, "far": 100},
    "ambient": [0.1, 0.1, 0.1],
    "directional": {"direction": [1, -2, 0], "intensity": [0.8, 0.8, 0.8], "shadows": SHADOWS},
    "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
    "objects": [
        {"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
        {"mesh": {"primitive": "box", "size": [2, 0.5, 2]}, "material": "grey", "transform": {"translate": [-1, 2, 0]}}]})";

std::string boxAbovePlane(bool shadows)
{
    std::string scene = kBoxAbovePlane;
    scene.replace(scene.find("SHADOWS"), 7, shadows ? "true" : "false");
    return scene;
}

TEST_P(Shadows, BoxAbovePlaneUnderDirectionalLight)
{
    // kd = 0.5, ambient 0.1, intensity 0.8, L = (−1, 2, 0)/√5: on the plane and the box's top
    // N·L = 2/√5. Lit: 0.5 · (0.1 + 0.8 · 2/√5) = 0.4077709; shadowed: 0.5 · 0.1 = 0.05.
    const glm::dvec3 toLight = glm::normalize(glm::dvec3(-1, 2, 0));
    const Box box{{-2, 1.75, -1}, {0, 2.25, 1}};
    const double lit = 0.5 * (0.1 + 0.8 * 2.0 / std::sqrt(5.0));
    const double ambientOnly = 0.5 * 0.1;
    const Rendered r = renderWithPositions(boxAbovePlane(true), "65x65", {"--technique", GetParam()});
    // The umbra's centre: the middle of the visible part of the shadow (x from 0, where the
    // box hides the rest, to 1.125), on the light's plane of incidence z = 0.
    ShadowChecks checks(r, glm::dvec3(0.5625, 0, 0));
    for (int y = 0; y < r.colour.height; ++y)
        for (int x = 0; x < r.colour.width; ++x) {
            if (!r.covered(x, y))
                continue;
            const float* p = r.position.pixel(x, y);
            const glm::dvec3 position(p[0], p[1], p[2]);
            std::optional<bool> inShadow = false;  // the box's top: nothing above it
            if (position.y < 1.0)
                inShadow = shadowedOnPlane(position, toLight, box);
            if (inShadow)
                checks.check(x, y, position, *inShadow, *inShadow ? ambientOnly : lit);
        }
    checks.expectAllPassed(40, 2000, 0.1f, 0.5f);
}

TEST_P(Shadows, ShadowsOffLeaveThePlaneLit)
{
    // The same scene with "shadows": false: docs/lighting.md without shadows, every plane point lit.
    const double lit = 0.5 * (0.1 + 0.8 * 2.0 / std::sqrt(5.0));
    const Rendered r = renderWithPositions(boxAbovePlane(false), "65x65", {"--technique", GetParam()});
    int checked = 0;
    for (int y = 0; y < r.colour.height; ++y)
        for (int x = 0; x < r.colour.width; ++x)
            if (r.covered(x, y)) {
                EXPECT_TRUE(near(r.colour.pixel(x, y), glm::dvec3(lit))) << "pixel (" << x << ", " << y << ")";
                ++checked;
            }
    EXPECT_GT(checked, 3000);
}

// A local light 6 above the origin, A = 1 (a = b = 0), exponent 0: a lit plane point at
// distance d gets kd · (ambient + I · 6/d) (N·L = 6/d, S = 1 inside the cone), a shadowed one
// kd · ambient exactly. The box (1 × 0.5 × 1 at height 3) throws a magnified shadow on
// x ≈ 0.9 to 3.3, of which the camera sees x > 2.2 (the box hides the rest).
// --shadow-lights 1 gives the light a map: a spot map for `cutoffDegrees` ≤ 75, a cube map
// for a point light (cutoffDegrees 180) or a wider spot.
void checkLocalLightShadow(const std::string& technique, const std::string& lightJson, double cutoffDegrees)
{
    const std::string scene = R"({
        "camera": {"eye": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov_y": 60, "near": 0.1, "far": 100},
        "ambient": [0.1, 0.1, 0.1],
        "lights": [)" + lightJson +
                              R"(],
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [
            {"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
            {"mesh": {"primitive": "box", "size": [1, 0.5, 1]}, "material": "grey", "transform": {"translate": [1, 3, 0]}}]})";
    const glm::dvec3 light(0, 6, 0);
    const Box box{{0.5, 2.75, -0.5}, {1.5, 3.25, 0.5}};
    const double cosCutoff = std::cos(glm::radians(cutoffDegrees));
    const double ambientOnly = 0.5 * 0.1;
    // The maps' texels are about 0.012 (spot: 2 · 6 · tan 46° / 1024) to 0.025 (cube face:
    // 2 · 6 / 512) apart on the plane; the filter reaches two of them: a margin of 0.15 is
    // several times the blurred edge.
    constexpr double kLocalPenumbraMargin = 0.15;
    const Rendered r = renderWithPositions(scene, "65x65", {"--technique", technique, "--shadow-lights", "1"});
    ShadowChecks checks(r, glm::dvec3(2.75, 0, 0));
    for (int y = 0; y < r.colour.height; ++y)
        for (int x = 0; x < r.colour.width; ++x) {
            if (!r.covered(x, y))
                continue;
            const float* p = r.position.pixel(x, y);
            const glm::dvec3 position(p[0], p[1], p[2]);
            const glm::dvec3 toLight = light - position;
            const double d = glm::length(toLight);
            const double cosTheta = (light.y - position.y) / d;
            if (std::abs(cosTheta - cosCutoff) < 1e-4)
                continue;  // on the cone's edge: either answer is right
            if (position.y > 1.0)
                continue;  // the box: its faces see the light at other angles; the plane is the test
            const std::optional<bool> inShadow = shadowedOnPlane(position, toLight / d, box, kLocalPenumbraMargin);
            if (!inShadow)
                continue;
            const bool inCone = cosTheta >= cosCutoff;
            const double want = *inShadow || !inCone ? ambientOnly : 0.5 * (0.1 + 0.8 * cosTheta);
            checks.check(x, y, position, *inShadow, want, inCone);
        }
    checks.expectAllPassed(30, 1500, 0.1f, 0.5f);
}

TEST_P(Shadows, BoxAbovePlaneUnderSpotLight)
{
    checkLocalLightShadow(GetParam(),
                          R"({"type": "spot", "pos": [0, 6, 0], "direction": [0, -1, 0], "cutoff": 45, "exponent": 0,
                              "intensity": [0.8, 0.8, 0.8], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}})",
                          45.0);
}

TEST_P(Shadows, BoxAbovePlaneUnderPointLight)
{
    checkLocalLightShadow(GetParam(),
                          R"({"type": "point", "pos": [0, 6, 0], "intensity": [0.8, 0.8, 0.8],
                              "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}})",
                          180.0);
}

TEST_P(Shadows, BoxAbovePlaneUnderWideSpotLight)
{
    // 100° is wider than one perspective map covers well: the spot gets a cube map.
    checkLocalLightShadow(GetParam(),
                          R"({"type": "spot", "pos": [0, 6, 0], "direction": [0, -1, 0], "cutoff": 100, "exponent": 0,
                              "intensity": [0.8, 0.8, 0.8], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}})",
                          100.0);
}

TEST(ShadowView, ShowsTheDirectionalShadowFactor)
{
    // --view shadow of the box above the plane: 0 in the umbra, 1 where lit, and only values
    // in between at the shadow's filtered edge; the same classification as the final image.
    const glm::dvec3 toLight = glm::normalize(glm::dvec3(-1, 2, 0));
    const Box box{{-2, 1.75, -1}, {0, 2.25, 1}};
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", boxAbovePlane(true));
    const std::string scene = (dir / "scene.json").string();
    const Image shadow =
        renderPfm(scene, dir / "shadow.pfm", {"--gbuffer", "seed", "--size", "65x65", "--view", "shadow"});
    const Image position =
        renderPfm(scene, dir / "position.pfm", {"--gbuffer", "seed", "--size", "65x65", "--view", "position"});
    int umbra = 0;
    int lit = 0;
    for (int y = 0; y < shadow.height; ++y)
        for (int x = 0; x < shadow.width; ++x) {
            const float* p = position.pixel(x, y);
            if (p[1] > 1.0f || (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f))
                continue;  // the box, or background (a plane pixel exactly at the origin is not used)
            const std::optional<bool> inShadow = shadowedOnPlane(glm::dvec3(p[0], p[1], p[2]), toLight, box);
            if (!inShadow)
                continue;
            EXPECT_EQ(shadow.pixel(x, y)[0], *inShadow ? 0.0f : 1.0f) << "pixel (" << x << ", " << y << ")";
            ++(*inShadow ? umbra : lit);
        }
    EXPECT_GT(umbra, 40);
    EXPECT_GT(lit, 2000);
}

INSTANTIATE_TEST_SUITE_P(Techniques, Shadows, ::testing::ValuesIn(techniqueNames()), test::techniqueTestName);

}  // namespace
}  // namespace manylights
