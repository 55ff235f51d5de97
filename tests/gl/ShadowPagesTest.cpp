// The shadows the shadow-page pool gives (issue 47, "What must show it"; docs/shadows.md), on a
// headless context through the Renderer: analytic umbrae of spheres under point and spot lights
// (one cell and 1,024 and 65,536 cells, most of them off screen), a box's shadow in contact with
// the floor, a closed room that no light outside it lights, a small pool that lowers levels and
// still shadows every light, and the faces a moving object redraws.
//
// What a lookup may read. The lighting reads one bilinear comparison tap (shaders/lib/
// shadow_pages.glsl): the 2x2 texels around the receiver's place on its face, each texel the
// depth of the nearest caster along its centre's direction from the light. How a tap weighs its
// texels' comparisons is the implementation's (GL 4.6 §8.23.1: in proportion to those that
// pass), so the checks rely only on taps whose four texels agree. The centres lie within √2
// texels of the receiver's place, in the face's plane at unit depth, where a texel is
// 2 tanHalf / R across (R: the resolution of the level read, the face's part or, outside a part,
// its coarse page). The gnomonic projection onto that plane stretches every angle (its scale
// factors 1/cos φ and 1/cos² φ are at least 1), so each centre's direction is within
// √2 · 2 tanHalf / R radians of the receiver's. So:
// - a receiver whose directions within two texels (4 tanHalf / R radians) all pass through an
//   occluder well in front of it (more than the largest bias, SHADOW_MAX_BIAS_WORLD = 0.1) reads
//   four occluded texels: the light gives exactly nothing, and the pixel is exactly kd ⊙ ambient,
//   compared with == (the float product the shader forms, as tests/image/ShadowTest.cpp's umbra
//   centres);
// - a receiver whose directions within two texels all miss every occluder (and meet no other
//   surface: see nearCrease) reads its own surface in the four texels, which its bias clears
//   (see biasIsClamped for where it need not): it is fully lit, within the analytic tolerance
//   (2e-5 absolute + 1e-4 relative, tests/support/ImageComparison.h: the lighting function in
//   floats against the equations in doubles);
// - receivers in between, the edge the filter blurs, are not checked.
// Rasterisation snaps the casters' vertices by at most 1/32 of a texel (GL's sub-pixel precision
// is at least 4 bits), well inside the margin's 2 − √2 texels to spare.
//
// The spheres are lat-long meshes whose vertices lie on the sphere: the mesh holds the sphere
// of its nearest face plane's distance (computed from the mesh) and lies within the sphere, so
// an umbra is taken from the inner sphere and a lit receiver must clear the outer one.
//
// Every render uses the seed G-buffer (exact kd) and `clustered`, the default technique (every
// technique reads the same pages and equals forward: tests/image/TechniqueAgreementTest.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/shadows/ShadowFaces.h"
#include "render/shadows/ShadowPageLayout.h"
#include "scene/LightSets.h"
#include "scene/Meshes.h"
#include "scene/SceneLoader.h"
#include "scene/ShadowSelection.h"
#include "tests/support/ImageComparison.h"
#include "tests/support/RayBox.h"
#include "tests/support/ShadowRoomScene.h"

namespace manylights {
namespace {

constexpr float kAmbient = 0.1f;
constexpr float kDiffuse = 0.5f;
constexpr double kAbsoluteTolerance = test::kAnalyticTolerance.absolute;
constexpr double kRelativeTolerance = test::kAnalyticTolerance.relative;
// The margin around a shadow's edge in texels of the level read (see the top of this file).
constexpr double kMarginTexels = 2.0;

class ShadowPagesTest : public GlContextTest {};

// One frame's images: the lit colour and the G-buffer's position and normal views.
struct Frame {
    Image colour;
    Image position;
    Image normal;
    glm::dvec3 positionAt(int x, int y) const
    {
        const float* p = position.pixel(x, y);
        return {p[0], p[1], p[2]};
    }
    glm::dvec3 normalAt(int x, int y) const
    {
        const float* n = normal.pixel(x, y);
        return {n[0], n[1], n[2]};
    }
    bool covered(int x, int y) const { return glm::length(normalAt(x, y)) > 0.5; }
};

Frame renderViews(Renderer& renderer)
{
    Frame frame;
    renderer.renderFrame("clustered", ViewMode::Final);
    frame.colour = renderer.readColour();
    renderer.renderFrame("clustered", ViewMode::Position);
    frame.position = renderer.readColour();
    renderer.renderFrame("clustered", ViewMode::Normal);
    frame.normal = renderer.readColour();
    return frame;
}

RendererDesc shadowedDesc(int width, int height, int poolMiB = 0)
{
    return {.width = width,
            .height = height,
            .gbufferLayout = GBufferLayout::Seed,
            .shadowLights = kAllShadowLights,
            .shadowPoolMiB = poolMiB};
}

// The pool's faces after a frame, and what a lookup of a light at a receiver reads.
class FaceTexels {
public:
    explicit FaceTexels(const Renderer& renderer) : lights_(renderer.gpuScene().packedLights())
    {
        for (const ShadowPool::ResidentFace& face : renderer.shadowPool().residentFaces())
            faces_[face.light * shadowpages::SHADOW_CUBE_FACES + static_cast<std::size_t>(face.face)] = face.region;
    }

    // What light `light`'s lookup of the receiver at offset v from it reads: the angle one
    // texel spans (2 tanHalf / R of the level read) and, as the shader computes it, the texel's
    // width at the receiver's depth along the face's axis; none where the light has no page there.
    struct Lookup {
        double texelAngle = 0.0;
        double texelWorld = 0.0;
    };
    std::optional<Lookup> lookup(std::size_t light, const glm::dvec3& v) const
    {
        const GpuLight& record = lights_[light];
        int face = 0;
        if (shadowFaceCount(record) != 1) {
            const glm::dvec3 a = glm::abs(v);
            const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
            face = axis * 2 + (v[axis] < 0.0 ? 1 : 0);
        }
        const auto found = faces_.find(light * shadowpages::SHADOW_CUBE_FACES + static_cast<std::size_t>(face));
        if (found == faces_.end())
            return std::nullopt;
        const ShadowFaceRegion& region = found->second;
        const ShadowFaceFrame frame = shadowFaceFrame(record, face);
        const double depth = glm::dot(glm::dvec3(frame.axis), v);
        const glm::dvec2 uv = glm::dvec2(glm::dot(glm::dvec3(frame.across), v), glm::dot(glm::dvec3(frame.up), v)) /
                                  (depth * frame.tanHalf) * 0.5 +
                              0.5;
        const double fine = shadowFaceResolution(region.level);
        const glm::dvec2 texel = uv * fine;
        const double low = region.x0 + shadowpages::SHADOW_GUARD_TEXELS;
        const double lowY = region.y0 + shadowpages::SHADOW_GUARD_TEXELS;
        const double span = region.pages * shadowpages::SHADOW_PAGE_TEXELS - 2 * shadowpages::SHADOW_GUARD_TEXELS;
        const bool inPart = texel.x >= low && texel.x <= low + span && texel.y >= lowY && texel.y <= lowY + span;
        const double resolution = region.whole || inPart ? fine : shadowFaceResolution(0);
        const double angle = 2.0 * frame.tanHalf / resolution;
        return Lookup{.texelAngle = angle, .texelWorld = angle * depth};
    }

    // The highest level of any face, and the faces.
    int highestLevel() const
    {
        int level = -1;
        for (const auto& [key, region] : faces_)
            level = std::max(level, region.level);
        return level;
    }
    std::size_t faceCount() const { return faces_.size(); }

private:
    const std::vector<GpuLight>& lights_;
    std::map<std::size_t, ShadowFaceRegion> faces_;
};

// Whether the receiver offset and bias the lookup uses (shaders/lib/shadow_pages.glsl:
// shadowPageLookup) may fall short of what the tap needs on a lit receiver tilted by θ to the
// light. The tap's texel centres lie up to √2 texels (t) from the receiver's place, where its own
// surface is nearer the light by up to √2 · t · tan θ. The receiver moves
// δ = min(t · (1 + sin θ), SHADOW_MAX_NORMAL_OFFSET_WORLD) along its normal, which puts it
// δ / cos θ before its surface along the light, and its depth is pulled by
// b = min(t, SHADOW_MAX_BIAS_WORLD): unclamped, δ / cos θ + b ≥ √2 · t · tan θ at every θ
// (1 + cos θ ≥ (√2 − 1) sin θ), so only where a clamp cuts them (coarse texels on a tilted
// receiver) may the tap read the receiver's own surface as a shadow; such a receiver is checked
// to get no more than the light gives and no less than the ambient term, not to be fully lit.
bool biasIsClamped(const FaceTexels::Lookup& lookup, const glm::dvec3& normal, const glm::dvec3& v)
{
    const double cosine = glm::dot(normal, -v) / glm::length(v);
    if (cosine < 1e-3)
        return true;
    const double sine = std::sqrt(1.0 - std::min(cosine * cosine, 1.0));
    const double texel = lookup.texelWorld;
    const double offset = std::min(texel * (shadowpages::SHADOW_NORMAL_OFFSET_TEXELS + sine),
                                   static_cast<double>(shadowpages::SHADOW_MAX_NORMAL_OFFSET_WORLD));
    const double bias =
        std::min(texel * shadowpages::SHADOW_BIAS_TEXELS, static_cast<double>(shadowpages::SHADOW_MAX_BIAS_WORLD));
    return offset / cosine + bias < std::numbers::sqrt2 * texel * sine / cosine;
}

// docs/lighting.md for a Blinn-Phong surface of diffuse kd and no specular colour, lit by
// `light` alone at full shadow factor: kd · I · max(N·L, 0) · A(d) · S (no ambient term).
glm::dvec3 localTerm(const Light& light, const glm::dvec3& position, const glm::dvec3& normal)
{
    const glm::dvec3 v = position - glm::dvec3(light.position);
    const double d = glm::length(v);
    const double range = light.range;
    if (d >= range || d == 0.0)
        return glm::dvec3(0.0);
    const double clamped = std::max(d, range / 100.0);
    const double falloff = 1.0 / (clamped * clamped) - 1.0 / (range * range);
    double spot = 1.0;
    if (light.type == LightType::Spot) {
        const double cosAxis = glm::dot(v / d, glm::normalize(glm::dvec3(light.direction)));
        spot = cosAxis >= std::cos(glm::radians(static_cast<double>(light.cutoffDegrees))) ? 1.0 : 0.0;
    }
    const double cosine = std::max(glm::dot(normal, -v / d), 0.0);
    return static_cast<double>(kDiffuse) * glm::dvec3(light.intensity) * cosine * falloff * spot;
}

bool nearValue(const float* got, const glm::dvec3& want)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(got[c] - want[c]) > kAbsoluteTolerance + kRelativeTolerance * std::abs(want[c]))
            return false;
    return true;
}

// The colour of a receiver no light reaches: kd ⊙ ambient, as the shader forms it in floats.
bool isAmbientOnly(const float* got)
{
    const float ambientOnly = kAmbient * kDiffuse;
    return got[0] == ambientOnly && got[1] == ambientOnly && got[2] == ambientOnly;
}

// Counts the receivers checked in shadow and lit, and reports the first few failures.
class Checks {
public:
    void shadowed(const Frame& frame, int x, int y, const std::string& what)
    {
        ++shadowed_;
        const float* got = frame.colour.pixel(x, y);
        if (!isAmbientOnly(got))
            fail(x, y, got, glm::dvec3(kAmbient * kDiffuse), "in the umbra " + what);
    }
    void lit(const Frame& frame, int x, int y, const glm::dvec3& want, const std::string& what)
    {
        ++lit_;
        const float* got = frame.colour.pixel(x, y);
        if (!nearValue(got, want))
            fail(x, y, got, want, "lit " + what);
    }
    int shadowedCount() const { return shadowed_; }
    // A lit receiver whose bias is clamped (biasIsClamped): between kd ⊙ ambient and the lit value.
    void litUnderClampedBias(const Frame& frame, int x, int y, const glm::dvec3& want, const std::string& what)
    {
        ++clamped_;
        const float* got = frame.colour.pixel(x, y);
        const float ambientOnly = kAmbient * kDiffuse;
        for (int c = 0; c < 3; ++c)
            if (got[c] < ambientOnly ||
                got[c] > want[c] + kAbsoluteTolerance + kRelativeTolerance * std::abs(want[c])) {
                fail(x, y, got, want, "lit under a clamped bias (at most this) " + what);
                return;
            }
    }
    int litCount() const { return lit_; }
    int clampedCount() const { return clamped_; }
    int failures() const { return failures_; }

private:
    void fail(int x, int y, const float* got, const glm::dvec3& want, const std::string& what)
    {
        if (++failures_ <= 5)
            ADD_FAILURE() << "pixel (" << x << ", " << y << ") " << what << ": got (" << got[0] << ", " << got[1]
                          << ", " << got[2] << "), expected (" << want.x << ", " << want.y << ", " << want.z << ")";
    }
    int shadowed_ = 0;
    int lit_ = 0;
    int clamped_ = 0;
    int failures_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Analytic umbrae: cells of a light above a sphere above the floor.

// One cell: a light `lightHeight` above the floor, a sphere of `sphereRadius` centred
// `sphereHeight` above it, straight below the light. A point light's umbra on the floor is the
// disc the cone from the light tangent to the sphere cuts: half-angle asin(r / D), D the
// light's distance from the centre. A spot light points straight down.
struct CellSetup {
    LightType type = LightType::Point;
    double lightHeight = 4.0;
    double sphereHeight = 2.0;
    double sphereRadius = 0.5;
    double range = 5.0;
    double intensity = 2.0;
    double cutoffDegrees = 30.0;  // spot only
    int slices = 48;              // the sphere mesh's (the scene file's sphere: 48 x 24)
    int stacks = 24;
};

// The radius of the largest sphere about its centre that `mesh` (convex, its vertices on the
// sphere) holds: the distance to its nearest face plane.
double innerRadius(const Mesh& mesh)
{
    double nearest = 1e30;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::dvec3 a(mesh.vertices[mesh.indices[i]].position);
        const glm::dvec3 b(mesh.vertices[mesh.indices[i + 1]].position);
        const glm::dvec3 c(mesh.vertices[mesh.indices[i + 2]].position);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-12)
            continue;  // the poles' degenerate triangles
        nearest = std::min(nearest, std::abs(glm::dot(glm::normalize(n), a)));
    }
    return nearest;
}

// `side` x `side` cells `spacing` apart on one floor, centred on the origin.
struct CellGrid {
    int side = 1;
    double spacing = 10.0;
    glm::dvec2 centre(int i, int j) const
    {
        const double half = (side - 1) / 2.0;
        return {(i - half) * spacing, (j - half) * spacing};
    }
    std::size_t cellCount() const { return static_cast<std::size_t>(side) * static_cast<std::size_t>(side); }
};

Scene cellScene(const CellSetup& setup, const CellGrid& grid, const Camera& camera)
{
    Scene scene;
    scene.source = "<umbra cells>";
    scene.camera = camera;
    scene.ambient = glm::vec3(kAmbient);
    Material grey;
    grey.name = "grey";
    grey.diffuse = glm::vec3(kDiffuse);
    scene.materials.push_back(grey);
    const auto extent = static_cast<float>(grid.side * grid.spacing);
    scene.meshes.push_back(makePlane(extent, extent));
    scene.meshes.push_back(makeSphere(static_cast<float>(setup.sphereRadius), setup.slices, setup.stacks));
    scene.objects.push_back({.name = "floor", .mesh = 0});
    scene.objects.reserve(grid.cellCount() + 1);
    scene.lights.reserve(grid.cellCount());
    for (int j = 0; j < grid.side; ++j)
        for (int i = 0; i < grid.side; ++i) {
            const glm::dvec2 c = grid.centre(i, j);
            Object sphere{.name = "sphere", .mesh = 1};
            sphere.transform[3] = glm::vec4(static_cast<float>(c.x), static_cast<float>(setup.sphereHeight),
                                            static_cast<float>(c.y), 1.0f);
            scene.objects.push_back(sphere);
            Light light;
            light.type = setup.type;
            light.position =
                glm::vec3(static_cast<float>(c.x), static_cast<float>(setup.lightHeight), static_cast<float>(c.y));
            light.intensity = glm::vec3(static_cast<float>(setup.intensity));
            light.falloff = Falloff::Range;
            light.range = static_cast<float>(setup.range);
            light.direction = {0.0f, -1.0f, 0.0f};
            light.cutoffDegrees = static_cast<float>(setup.cutoffDegrees);
            light.exponent = 0.0f;
            scene.lights.push_back(light);
        }
    return scene;
}

// Camera straight above `target`, `height` up, seeing the floor around it.
Camera cameraAbove(const glm::vec3& target, float height, float fovY)
{
    return {.eye = target + glm::vec3(0.0f, height, 0.0f),
            .lookAt = target,
            .up = {0.0f, 0.0f, -1.0f},
            .fovYDegrees = fovY,
            .nearPlane = 0.1f,
            .farPlane = 100.0f};
}

struct UmbraResult {
    int shadowed = 0;
    int lit = 0;
    int clamped = 0;  // lit under a clamped bias
    int cellsSeen = 0;
    int failures = 0;
    std::size_t lightsWithFaces = 0;
    std::size_t levelsLowered = 0;
};

// Checks every floor pixel against the analytic umbra of its cell's sphere, with the margin of
// the level its light's lookup reads there. The cells' lights reach no other cell (the callers'
// spacing is more than twice a light's reach on the floor), so a floor pixel gets at most its
// own cell's light.
UmbraResult checkUmbrae(const Renderer& renderer, const Frame& frame, const CellSetup& setup, const CellGrid& grid)
{
    const FaceTexels texels(renderer);
    const double half = (grid.side - 1) / 2.0;
    const auto cellOf = [&](double x, double z) {
        const auto index = [&](double coordinate) {
            return std::clamp(static_cast<int>(std::lround(coordinate / grid.spacing + half)), 0, grid.side - 1);
        };
        return glm::ivec2(index(x), index(z));
    };
    // The renderer orders the lights its own way (render/scene/SceneLights.h): find each cell's.
    std::vector<std::size_t> lightOfCell(grid.cellCount(), 0);
    const GpuScene& scene = renderer.gpuScene();
    for (std::size_t light = 0; light < scene.lightCount(); ++light) {
        const glm::vec4& p = scene.packedLights()[light].positionRadius;
        const glm::ivec2 cell = cellOf(p.x, p.z);
        lightOfCell[static_cast<std::size_t>(cell.y * grid.side + cell.x)] = light;
    }
    const double inner = innerRadius(makeSphere(static_cast<float>(setup.sphereRadius), setup.slices, setup.stacks));
    const double cosCutoff = std::cos(glm::radians(setup.cutoffDegrees));
    const glm::dvec3 ambientOnly(static_cast<double>(kAmbient) * kDiffuse);

    Checks checks;
    std::vector<bool> cellSeen(grid.cellCount(), false);
    for (int y = 0; y < frame.colour.height; ++y)
        for (int x = 0; x < frame.colour.width; ++x) {
            if (!frame.covered(x, y))
                continue;
            const glm::dvec3 position = frame.positionAt(x, y);
            if (position.y > 1e-3 || frame.normalAt(x, y).y < 0.999)
                continue;  // a sphere: the floor is the test
            const glm::ivec2 cell = cellOf(position.x, position.z);
            const std::size_t cellIndex = static_cast<std::size_t>(cell.y * grid.side + cell.x);
            const std::size_t lightIndex = lightOfCell[cellIndex];
            const Light light = scene.light(lightIndex);
            const glm::dvec3 lightPosition(light.position);
            const glm::dvec3 v = position - lightPosition;
            const glm::dvec3 term = localTerm(light, position, {0.0, 1.0, 0.0});
            const double cosAxis = -v.y / glm::length(v);
            if (setup.type == LightType::Spot && std::abs(cosAxis - cosCutoff) < 1e-4)
                continue;  // on the cone's edge: either answer is right
            const bool reached = term.x > 0.0;
            const std::optional<FaceTexels::Lookup> texel = texels.lookup(lightIndex, v);
            if (!texel) {
                if (reached && checks.failures() < 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << "): light " << lightIndex
                                  << " reaches it and has no page there";
                continue;
            }
            const glm::dvec2 centre = grid.centre(cell.x, cell.y);
            const glm::dvec3 toSphere = glm::dvec3(centre.x, setup.sphereHeight, centre.y) - lightPosition;
            const double distance = glm::length(toSphere);
            const double angle = std::atan2(glm::length(glm::cross(v, toSphere)), glm::dot(v, toSphere));
            const double margin = kMarginTexels * texel->texelAngle;
            std::ostringstream what;
            what << "of cell (" << cell.x << ", " << cell.y << "), " << angle << " rad from the sphere's centre, umbra "
                 << std::asin(inner / distance) << " to " << std::asin(setup.sphereRadius / distance) << " rad, margin "
                 << margin << " rad";
            if (angle < std::asin(inner / distance) - margin) {
                checks.shadowed(frame, x, y, what.str());
                cellSeen[cellIndex] = true;
            } else if (angle > std::asin(setup.sphereRadius / distance) + margin && reached) {
                if (biasIsClamped(*texel, {0.0, 1.0, 0.0}, v))
                    checks.litUnderClampedBias(frame, x, y, ambientOnly + term, what.str());
                else
                    checks.lit(frame, x, y, ambientOnly + term, what.str());
            }
        }
    return {.shadowed = checks.shadowedCount(),
            .lit = checks.litCount(),
            .clamped = checks.clampedCount(),
            .cellsSeen = static_cast<int>(std::count(cellSeen.begin(), cellSeen.end(), true)),
            .failures = checks.failures()};
}

UmbraResult renderAndCheckUmbrae(const CellSetup& setup, const CellGrid& grid, const Camera& camera, int size,
                                 int poolMiB = 0)
{
    const Scene scene = cellScene(setup, grid, camera);
    Renderer renderer(scene, expandLights(scene), shadowedDesc(size, size, poolMiB));
    const Frame frame = renderViews(renderer);
    UmbraResult result = checkUmbrae(renderer, frame, setup, grid);
    result.lightsWithFaces = renderer.shadowPool().shadowedLights().size();
    result.levelsLowered = renderer.shadowPool().lastFrame().levelsLowered;
    std::cout << "umbra check: " << result.shadowed << " pixels in umbrae, " << result.lit << " lit, " << result.clamped
              << " lit under a clamped bias, " << result.cellsSeen << " cells, faces "
              << renderer.shadowPool().lastFrame().faces << ", highest level " << FaceTexels(renderer).highestLevel()
              << ", levels lowered " << renderer.shadowPool().lastFrame().levelsLowered << "\n";
    return result;
}

TEST_F(ShadowPagesTest, UmbraOfASphereUnderAHighPointLight)
{
    // Light 4 above the floor, sphere r = 0.5 at 2: the umbra is a disc of radius
    // 4 tan(asin(0.25)) = 1.03; the light reaches 3 on the floor (range 5), all on its −Y face.
    const CellSetup setup;
    const UmbraResult r = renderAndCheckUmbrae(setup, {}, cameraAbove({0.0f, 0.0f, 0.0f}, 9.0f, 45.0f), 96);
    EXPECT_EQ(r.failures, 0);
    EXPECT_EQ(r.clamped, 0);  // every lit receiver's bias is unclamped: all are checked fully lit
    EXPECT_GT(r.shadowed, 40);
    EXPECT_GT(r.lit, 800);
}

TEST_F(ShadowPagesTest, UmbraOfASphereUnderALowPointLight)
{
    // Light 1 above the floor, sphere r = 0.25 at 0.5: umbra radius tan(30°) = 0.58; the light
    // reaches 2.29 on the floor (range 2.5), so its lit disc reaches past the −Y face's edge
    // (1 from the centre) onto the four side faces.
    const CellSetup setup{.lightHeight = 1.0, .sphereHeight = 0.5, .sphereRadius = 0.25, .range = 2.5};
    const UmbraResult r = renderAndCheckUmbrae(setup, {}, cameraAbove({0.0f, 0.0f, 0.0f}, 5.0f, 55.0f), 64);
    EXPECT_EQ(r.failures, 0);
    // The side faces get level 2 at 64x64, texels of about 0.07 on the floor at slopes up to
    // 2.29: the normal offset stays unclamped there, so the whole lit disc, on the side faces
    // too, is checked fully lit. (A depth bias alone, clamped at 0.1, left the floor beyond
    // about 1.1 from the centre reading about 6% of the light as shadow.)
    EXPECT_EQ(r.clamped, 0);
    EXPECT_GT(r.shadowed, 40);
    EXPECT_GT(r.lit, 800);
}

TEST_F(ShadowPagesTest, UmbraOfASphereUnderASpotLight)
{
    // A spot of 30° (one face) 4 above the floor: its cone meets the floor within 2.31, inside
    // its reach of 3, so the cone's edge is seen too.
    const CellSetup setup{.type = LightType::Spot};
    const UmbraResult r = renderAndCheckUmbrae(setup, {}, cameraAbove({0.0f, 0.0f, 0.0f}, 9.0f, 45.0f), 96);
    EXPECT_EQ(r.failures, 0);
    EXPECT_EQ(r.clamped, 0);  // every lit receiver's bias is unclamped: all are checked fully lit
    EXPECT_GT(r.shadowed, 40);
    EXPECT_GT(r.lit, 500);
}

// 1, 1,024 and 65,536 cells 8 apart (a light reaches 3 on the floor, so no two meet, and no
// light reaches another cell's sphere), the camera above the middle seeing the four middle
// cells (the one cell, where there is one): the rest are off screen, their lights' faces
// marked by no pixel. The spheres are coarser (16 x 8) so that 65,536 of them stay cheap to
// draw; the inner radius is the mesh's own.
class UmbraCells : public ShadowPagesTest, public ::testing::WithParamInterface<int> {};

TEST_P(UmbraCells, EachCellOnScreenHasItsUmbra)
{
    const CellGrid grid{.side = GetParam(), .spacing = 8.0};
    const CellSetup setup{.slices = 16, .stacks = 8};
    const UmbraResult r = renderAndCheckUmbrae(setup, grid, cameraAbove({1.5f, 0.0f, 1.5f}, 14.0f, 60.0f), 96);
    EXPECT_EQ(r.failures, 0);
    EXPECT_EQ(r.cellsSeen, grid.side == 1 ? 1 : 4);
    // Only lights whose reach the view meets have faces: at most the 3 x 3 cells around it.
    EXPECT_LE(r.lightsWithFaces, 9u);
    EXPECT_GT(r.shadowed, 20 * r.cellsSeen);
    EXPECT_GT(r.lit, 200 * r.cellsSeen);
}

INSTANTIATE_TEST_SUITE_P(Cells, UmbraCells, ::testing::Values(1, 32, 256),
                         [](const ::testing::TestParamInfo<int>& param) {
                             return std::to_string(param.param * param.param) + "_cells";
                         });

// ---------------------------------------------------------------------------------------------
// Box occluders: a receiver's cone of directions sampled.

using test::Box;
using test::rayEntersBox;

enum class Cover { Shadowed, Lit, Edge };

// Calls `visit` with directions from `light` within `margin` radians of the receiver's: the
// centre and three rings of 24, the outer one on a circle 1/cos(π/24) wider than the margin so
// that its polygon holds the margin's circle. The surfaces here are many margins across, so
// that none fits between the samples.
template <typename Visit>
void forDirectionsAround(const glm::dvec3& light, const glm::dvec3& receiver, double margin, const Visit& visit)
{
    const glm::dvec3 axis = glm::normalize(receiver - light);
    const glm::dvec3 helper = std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 across = glm::normalize(glm::cross(axis, helper));
    const glm::dvec3 up = glm::cross(across, axis);
    constexpr int kRings = 3;
    constexpr int kPerRing = 24;
    for (int ring = 0; ring <= kRings; ++ring) {
        const double radius = margin * ring / kRings / (ring == kRings ? std::cos(std::numbers::pi / kPerRing) : 1.0);
        for (int k = 0; k < (ring == 0 ? 1 : kPerRing); ++k) {
            const double phi = 2.0 * std::numbers::pi * k / kPerRing;
            visit(glm::normalize(axis + std::tan(radius) * (std::cos(phi) * across + std::sin(phi) * up)));
        }
    }
}

// Whether every direction from `light` within `margin` radians of the receiver's passes
// through `box` well before the receiver (Shadowed: 0.2 nearer along the ray, more than the
// 0.1 / cos 54.7° that the largest bias along a face's depth axis can be along a ray), none
// passes through it before the receiver (Lit), or neither (Edge).
Cover coverByBox(const glm::dvec3& light, const glm::dvec3& receiver, double margin, const Box& box)
{
    const double distance = glm::length(receiver - light);
    bool allShadowed = true;
    bool anyBlocked = false;
    forDirectionsAround(light, receiver, margin, [&](const glm::dvec3& direction) {
        const std::optional<double> entry = rayEntersBox(light, direction, box);
        anyBlocked = anyBlocked || (entry && *entry < distance);
        allShadowed = allShadowed && entry && *entry < distance - 0.2;
    });
    return allShadowed ? Cover::Shadowed : (anyBlocked ? Cover::Edge : Cover::Lit);
}

// Checks every pixel that holds a surface against one light and box occluders: exactly
// kd ⊙ ambient where `light`'s directions within the margin all pass through a box, kd ⊙
// ambient plus the light's term where none does. Pixels on the boxes themselves are left out.
// No other light may reach a checked pixel (the room: the walls' shadows are the point).
// `nearCrease` (optional): whether the receiver's directions within the margin meet a surface
// other than its own without an occluder, as at a concave corner: the tap's texels there hold
// the other surface, which the receiver's bias, made for its own slope, need not clear.
using CreaseTest = std::function<bool(const glm::dvec3& light, const glm::dvec3& receiver, double margin)>;
Checks checkAgainstBoxes(const Renderer& renderer, const Frame& frame, std::size_t lightIndex,
                         const std::vector<Box>& occluders, const std::function<void(int, int, Cover)>& seen = {},
                         const CreaseTest& nearCrease = {})
{
    const FaceTexels texels(renderer);
    const Light light = renderer.gpuScene().light(lightIndex);
    const glm::dvec3 lightPosition(light.position);
    const glm::dvec3 ambientOnly(static_cast<double>(kAmbient) * kDiffuse);
    Checks checks;
    for (int y = 0; y < frame.colour.height; ++y)
        for (int x = 0; x < frame.colour.width; ++x) {
            if (!frame.covered(x, y))
                continue;
            const glm::dvec3 position = frame.positionAt(x, y);
            if (std::any_of(occluders.begin(), occluders.end(), [&](const Box& b) { return b.holds(position, 1e-3); }))
                continue;
            const glm::dvec3 normal = frame.normalAt(x, y);
            const glm::dvec3 term = localTerm(light, position, normal);
            const std::optional<FaceTexels::Lookup> texel = texels.lookup(lightIndex, position - lightPosition);
            if (!texel) {
                if (term.x > 0.0 && checks.failures() < 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << "): the light reaches it and has no page there";
                continue;
            }
            Cover cover = Cover::Lit;
            for (const Box& box : occluders) {
                const Cover byBox = coverByBox(lightPosition, position, kMarginTexels * texel->texelAngle, box);
                if (byBox == Cover::Shadowed || (byBox == Cover::Edge && cover == Cover::Lit))
                    cover = byBox;
            }
            if (cover == Cover::Lit && nearCrease &&
                nearCrease(lightPosition, position, kMarginTexels * texel->texelAngle))
                cover = Cover::Edge;
            if (seen)
                seen(x, y, cover);
            std::ostringstream what;
            what << "at (" << position.x << ", " << position.y << ", " << position.z << ")";
            if (cover == Cover::Shadowed && term.x > 0.0)
                checks.shadowed(frame, x, y, what.str());
            else if (cover == Cover::Lit && biasIsClamped(*texel, normal, position - lightPosition))
                checks.litUnderClampedBias(frame, x, y, ambientOnly + term, what.str());
            else if (cover == Cover::Lit)
                checks.lit(frame, x, y, ambientOnly + term, what.str());
        }
    return checks;
}

// ---------------------------------------------------------------------------------------------
// Contact: a box resting on the floor.

TEST_F(ShadowPagesTest, ABoxOnTheFloorCastsFromItsBase)
{
    // A box 1 x 0.4 x 1 standing on the floor, a point light up and to its −x side: the box's
    // shadow runs from its +x base edge (x = 0.5) to x = 0.885 on the floor (the top's far edge's
    // shadow). The floor beside the base edge is seen from the light through the box's top, 0.4
    // nearer along the light's −Y axis: a bias up to that keeps the shadow on the base, and the
    // lookup's is at most 0.1.
    const Scene scene = parseScene(R"({
        "camera": {"eye": [0.7, 3, 0], "look_at": [0.7, 0, 0], "up": [0, 0, -1], "fov_y": 40, "near": 0.1, "far": 50},
        "ambient": [0.1, 0.1, 0.1],
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "lights": [{"type": "point", "pos": [-2, 3, 0], "intensity": [3, 3, 3], "range": 8}],
        "objects": [
            {"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
            {"mesh": {"primitive": "box", "size": [1, 0.4, 1]}, "material": "grey",
             "transform": {"translate": [0, 0.2, 0]}}]})",
                                   "<contact>", ".");
    Renderer renderer(scene, expandLights(scene), shadowedDesc(64, 64));
    const Frame frame = renderViews(renderer);
    const Box box{{-0.5, 0.0, -0.5}, {0.5, 0.4, 0.5}};
    // A pixel is 2 · 3 · tan 20° / 64 = 0.034 across on the floor: the strip three pixels wide
    // along the base edge's far side.
    constexpr double kStrip = 0.1;
    int strip = 0;
    const Checks checks = checkAgainstBoxes(renderer, frame, 0, {box}, [&](int x, int y, Cover cover) {
        const glm::dvec3 p = frame.positionAt(x, y);
        if (p.y > 1e-3 || p.x <= 0.5 || p.x > 0.5 + kStrip || std::abs(p.z) > 0.3)
            return;
        ++strip;
        EXPECT_EQ(cover, Cover::Shadowed) << "pixel (" << x << ", " << y << ") beside the base";
        EXPECT_TRUE(isAmbientOnly(frame.colour.pixel(x, y)))
            << "pixel (" << x << ", " << y << ") at x = " << p.x << " beside the base is lit: got "
            << frame.colour.pixel(x, y)[0];
    });
    EXPECT_EQ(checks.failures(), 0);
    EXPECT_GE(strip, 30);
    EXPECT_GT(checks.shadowedCount(), 100);
    EXPECT_GT(checks.litCount(), 1000);
}

// ---------------------------------------------------------------------------------------------
// No light through walls: a closed room, lights outside it, one inside.

using test::kRoomHalf;
using test::kRoomHeight;
const Box kRoomOccluder{{-0.8, 0.0, -0.8}, {-0.2, 0.8, -0.2}};  // test::roomSceneJson's box

// The light inside the room, in the renderer's order.
std::size_t insideLight(const Renderer& renderer)
{
    for (std::size_t i = 0; i < renderer.gpuScene().lightCount(); ++i) {
        const glm::vec3 p = renderer.gpuScene().light(i).position;
        if (std::abs(p.x) < kRoomHalf && std::abs(p.z) < kRoomHalf && p.y > 0.0f && p.y < kRoomHeight)
            return i;
    }
    ADD_FAILURE() << "no light inside the room";
    return 0;
}

// Whether a directions near the receiver's meets another of the room's six inner planes first
// (the room's inside is convex: the first plane a ray from inside meets is the one it hits).
bool nearRoomCrease(const glm::dvec3& light, const glm::dvec3& receiver, double margin)
{
    const auto firstPlane = [&](const glm::dvec3& direction) {
        int plane = -1;
        double nearest = 1e30;
        const glm::dvec3 low(-kRoomHalf, 0.0, -kRoomHalf);
        const glm::dvec3 high(kRoomHalf, kRoomHeight, kRoomHalf);
        for (int axis = 0; axis < 3; ++axis) {
            if (direction[axis] == 0.0)
                continue;
            const double bound = direction[axis] > 0.0 ? high[axis] : low[axis];
            const double t = (bound - light[axis]) / direction[axis];
            if (t < nearest) {
                nearest = t;
                plane = axis * 2 + (direction[axis] > 0.0 ? 0 : 1);
            }
        }
        return plane;
    };
    const int own = firstPlane(glm::normalize(receiver - light));
    bool crease = false;
    forDirectionsAround(light, receiver, margin,
                        [&](const glm::dvec3& direction) { crease = crease || firstPlane(direction) != own; });
    return crease;
}

// Renders the room and checks every pixel (all are inside) against the inside light alone.
struct RoomResult {
    Checks checks;
    ShadowPoolFrame pool;
    std::size_t shadowedLights = 0;
    // The lights whose sphere holds some visible pixel's point: those strictly inside by a
    // relative 1e-5 (float rounding of the distance), and those inside by that much less.
    std::size_t lightsInViewAtLeast = 0;
    std::size_t lightsInViewAtMost = 0;
};

// Counts the lights that reach some visible pixel (their range; every light here is a point
// light), with a relative slack of 1e-5 either way for float rounding at a sphere's edge.
std::pair<std::size_t, std::size_t> lightsInView(const Renderer& renderer, const Frame& frame)
{
    std::size_t surely = 0;
    std::size_t perhaps = 0;
    for (std::size_t i = 0; i < renderer.gpuScene().lightCount(); ++i) {
        const Light light = renderer.gpuScene().light(i);
        const glm::dvec3 p(light.position);
        double nearest = 1e30;
        for (int y = 0; y < frame.colour.height; ++y)
            for (int x = 0; x < frame.colour.width; ++x)
                if (frame.covered(x, y))
                    nearest = std::min(nearest, glm::length(frame.positionAt(x, y) - p));
        surely += nearest < light.range * (1.0 - 1e-5) ? 1 : 0;
        perhaps += nearest < light.range * (1.0 + 1e-5) ? 1 : 0;
    }
    return {surely, perhaps};
}
RoomResult renderRoom(int poolMiB)
{
    const Scene scene = parseScene(test::roomSceneJson(test::kRoomOutsideLights), "<room>", ".");
    Renderer renderer(scene, expandLights(scene), shadowedDesc(64, 64, poolMiB));
    const Frame frame = renderViews(renderer);
    RoomResult result{
        .checks = checkAgainstBoxes(renderer, frame, insideLight(renderer), {kRoomOccluder}, {}, nearRoomCrease),
        .pool = renderer.shadowPool().lastFrame(),
        .shadowedLights = renderer.shadowPool().shadowedLights().size()};
    std::tie(result.lightsInViewAtLeast, result.lightsInViewAtMost) = lightsInView(renderer, frame);
    std::cout << "room: " << result.checks.shadowedCount() << " pixels in the box's umbra, " << result.checks.litCount()
              << " lit, " << result.checks.clampedCount() << " lit under a clamped bias; " << result.shadowedLights
              << " lights with faces, " << result.pool.faces << " faces, " << result.pool.pagesUsed
              << " pages, levels lowered " << result.pool.levelsLowered << ", faces dropped "
              << result.pool.facesDropped << "\n";
    return result;
}

TEST_F(ShadowPagesTest, NoLightGetsIntoAClosedRoom)
{
    const RoomResult room = renderRoom(0);
    EXPECT_EQ(room.checks.failures(), 0);
    EXPECT_GT(room.checks.shadowedCount(), 30);  // the inside light's own shadow is there
    EXPECT_GT(room.checks.litCount(), 2000);
    // The lights outside reach the walls' inner faces, so they have faces of their own: the
    // walls are shadows, not culling. Every light that reaches a visible pixel has faces.
    EXPECT_GT(room.shadowedLights, 1000u);
    EXPECT_GE(room.shadowedLights, room.lightsInViewAtLeast);
    EXPECT_LE(room.shadowedLights, room.lightsInViewAtMost);
    EXPECT_EQ(room.pool.facesDropped, 0u);
}

// ---------------------------------------------------------------------------------------------
// The pool: a small one lowers levels and still shadows every light.

TEST_F(ShadowPagesTest, ASmallPoolLowersLevelsAndStillShadowsEveryLight)
{
    // 16 MiB (16,384 pages) holds a page for each of the room's faces (about 9,000) and its
    // tables, and not the levels they ask for: the pool lowers them, drops none, and the
    // room's checks hold with the coarser texels (the margins follow each face's level).
    const RoomResult room = renderRoom(16);
    EXPECT_GT(room.pool.levelsLowered, 0u);
    EXPECT_EQ(room.pool.facesDropped, 0u);
    EXPECT_GE(room.shadowedLights, room.lightsInViewAtLeast);
    EXPECT_LE(room.shadowedLights, room.lightsInViewAtMost);
    EXPECT_EQ(room.checks.failures(), 0);
    EXPECT_GT(room.checks.shadowedCount(), 30);
    EXPECT_GT(room.checks.litCount(), 1000);
}

TEST_F(ShadowPagesTest, ASmallPoolKeepsTheUmbraOfALowLight)
{
    // The low light's cell (UmbraOfASphereUnderALowPointLight) seen at 480x480 asks for its
    // five faces at levels whose pages a 4 MiB pool (4,096 pages) cannot hold; lowered, the
    // umbra and the lit floor hold with the coarser texels.
    const CellSetup setup{.lightHeight = 1.0, .sphereHeight = 0.5, .sphereRadius = 0.25, .range = 2.5};
    const UmbraResult r =
        renderAndCheckUmbrae(setup, {}, cameraAbove({0.0f, 0.0f, 0.0f}, 5.0f, 55.0f), 480, kMinShadowPoolMiB);
    EXPECT_GT(r.levelsLowered, 0u);
    EXPECT_EQ(r.lightsWithFaces, 1u);
    EXPECT_EQ(r.failures, 0);
    EXPECT_GT(r.shadowed, 400);
    EXPECT_GT(r.lit, 10000);
}

// ---------------------------------------------------------------------------------------------
// --view shadow-resolution (docs/shadows.md): the texels per pixel of the level a lookup reads.

TEST_F(ShadowPagesTest, ShadowResolutionViewShowsTheTexelsPerPixelOfTheLevelRead)
{
    // Point lights h above the floor, straight below the camera, which is 4 up: every floor
    // receiver under a light's −Y face lies h along the face's axis (tanHalf 1) and 4 from the
    // camera, so all of them ask for the same level, the one whose R texels across are no fewer
    // than the pixels the face spans there, texelsAcross = h · height / (4 tan(fov_y / 2)) (the
    // marking's formula: R ≥ texelsAcross, (R + 2 guard texels) / 16 pages a power of two). Its
    // receivers each read that level (the face's part holds every receiver that marked it), so
    // the light's figure there is R / texelsAcross, and a pixel's is the geometric mean over
    // the lights that reach it. Lights at 1 and 2 ask for levels 2 and 3 (3.6 and 7.1 pages
    // across, away from a level's edge). A pixel no light reaches has 0. Tolerance 1e-4
    // relative: the shader's float arithmetic (a quotient, and the log2 and exp2 of the view's
    // mean) against doubles.
    constexpr int kSize = 128;
    constexpr float kCameraHeight = 4.0f;
    constexpr float kFovY = 60.0f;
    struct LightAbove {
        double height;
        double range;
        int level;  // the level its −Y face's receivers ask for
    };
    const std::vector<std::vector<LightAbove>> cases{
        {{1.0, 2.0, 2}},  // the image's corners beyond its reach
        {{2.0, 5.0, 3}},
        {{1.0, 5.0, 2}, {2.0, 5.0, 3}},  // the mean of two
    };
    for (const std::vector<LightAbove>& lights : cases) {
        const std::string what =
            std::to_string(lights.size()) + " light(s), the first " + std::to_string(lights[0].height) + " up";
        Scene scene = cellScene({}, {}, cameraAbove({0.0f, 0.0f, 0.0f}, kCameraHeight, kFovY));
        scene.objects.resize(1);  // the floor alone
        const Light prototype = scene.lights[0];
        scene.lights.clear();
        for (const LightAbove& above : lights) {
            Light light = prototype;
            light.position = {0.0f, static_cast<float>(above.height), 0.0f};
            light.range = static_cast<float>(above.range);
            scene.lights.push_back(light);
        }
        Renderer renderer(scene, expandLights(scene), shadowedDesc(kSize, kSize));
        // Any technique's name: the view is drawn by the pool's own walk of its lists.
        renderer.renderFrame("volumes", ViewMode::ShadowResolution);
        const Image figure = renderer.readColour();
        renderer.renderFrame("volumes", ViewMode::Position);
        const Image position = renderer.readColour();

        std::vector<double> log2Figures;
        for (const LightAbove& above : lights) {
            const double texelsAcross = above.height * kSize / (kCameraHeight * std::tan(glm::radians(kFovY / 2.0)));
            const double pages =
                (texelsAcross + 2.0 * shadowpages::SHADOW_GUARD_TEXELS) / shadowpages::SHADOW_PAGE_TEXELS;
            ASSERT_EQ(static_cast<int>(std::round(std::log2(pages))), above.level) << what;
            log2Figures.push_back(std::log2(shadowFaceResolution(above.level) / texelsAcross));
        }
        int checked = 0;
        int unreached = 0;
        int failures = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float* p = position.pixel(x, y);
                double sum = 0.0;
                int reaching = 0;
                bool underFaces = true;
                for (std::size_t i = 0; i < lights.size(); ++i) {
                    const glm::dvec3 v = glm::dvec3(p[0], p[1], p[2]) - glm::dvec3(0.0, lights[i].height, 0.0);
                    if (glm::length(v) >= lights[i].range)
                        continue;
                    ++reaching;
                    sum += log2Figures[i];
                    // Under the −Y face, away from its edges (where a neighbour face may be read).
                    underFaces = underFaces && std::max(std::abs(v.x), std::abs(v.z)) < 0.9 * lights[i].height;
                }
                const double got = figure.pixel(x, y)[0];
                if (reaching == 0) {
                    ++unreached;
                    if (got != 0.0 && ++failures <= 5)
                        ADD_FAILURE() << what << ", pixel (" << x << ", " << y << "): no light reaches it, and it has "
                                      << got << " texels per pixel";
                    continue;
                }
                if (!underFaces)
                    continue;
                ++checked;
                const double want = std::exp2(sum / reaching);
                if (std::abs(got - want) > 1e-4 * want && ++failures <= 5)
                    ADD_FAILURE() << what << ", pixel (" << x << ", " << y << "): " << got
                                  << " texels per pixel, expected " << want;
            }
        EXPECT_GT(checked, 1000) << what;
        if (lights.size() == 1 && lights[0].range == 2.0) {
            EXPECT_GT(unreached, 1000) << what;
        }
        EXPECT_EQ(failures, 0) << what;
    }
}

// ---------------------------------------------------------------------------------------------
// Cache counts (issue 47, item 4, beyond tests/gl/ShadowPoolTest.cpp).

TEST_F(ShadowPagesTest, AnObjectMovingInOneLightsReachRedrawsOnlyThatLightsFaces)
{
    // A narrow spot (one face) over a bouncing box, and a point light 10 away over a box of its
    // own, beyond the bouncing box's reach (range 3): when the box moves, the spot's face is
    // drawn again, and none of the point light's.
    const Scene scene = parseScene(R"({
        "camera": {"eye": [5, 12, 10], "look_at": [5, 0, 0], "fov_y": 50},
        "ambient": [0.05, 0.05, 0.05],
        "lights": [
            {"type": "spot", "pos": [0, 4, 0], "direction": [0, -1, 0], "cutoff": 40, "intensity": [3, 3, 3], "range": 6},
            {"type": "point", "pos": [10, 2, 0], "intensity": [2, 2, 2], "range": 3}],
        "objects": [
            {"mesh": {"primitive": "plane", "size": [30, 30]}},
            {"mesh": {"primitive": "box", "size": [0.5, 0.5, 0.5]}, "transform": {"translate": [0, 0.25, 0]},
             "animation": {"bounce": {"height": 1, "period": 1}}},
            {"mesh": {"primitive": "box", "size": [0.5, 0.5, 0.5]}, "transform": {"translate": [10, 0.25, 0]}}]})",
                                   "<moving box>", ".");
    Renderer renderer(scene, expandLights(scene), shadowedDesc(96, 64));
    renderer.setTime(0.25);
    renderer.renderFrame("clustered", ViewMode::Final);
    const ShadowPool& pool = renderer.shadowPool();
    ASSERT_EQ(pool.shadowedLights().size(), 2u);
    std::size_t spot = 0;
    for (std::size_t i = 0; i < 2; ++i)
        if (renderer.gpuScene().light(i).type == LightType::Spot)
            spot = i;
    std::size_t spotParts = 0;
    std::size_t pointFaces = 0;
    for (const ShadowPool::ResidentFace& face : pool.residentFaces()) {
        if (face.light == spot)
            spotParts += face.region.whole ? 1 : 2;  // a part is drawn with its coarse page
        else
            ++pointFaces;
    }
    ASSERT_EQ(spotParts > 0 && pointFaces > 0, true);
    const std::uint64_t drawn = pool.facesDrawnTotal();

    renderer.setTime(0.5);
    renderer.renderFrame("clustered", ViewMode::Final);
    EXPECT_EQ(pool.markingsTotal(), 2u);  // the box moved: the receivers are marked again
    EXPECT_EQ(pool.lastFrame().facesDrawn, spotParts);
    EXPECT_EQ(pool.facesDrawnTotal(), drawn + spotParts);

    // Still again: nothing is marked or drawn.
    renderer.renderFrame("clustered", ViewMode::Final);
    EXPECT_EQ(pool.markingsTotal(), 2u);
    EXPECT_EQ(pool.lastFrame().facesDrawn, 0u);
}

}  // namespace
}  // namespace manylights
