// Analytic scenes of glTF material features (docs/scene-format.md, "Model files"): alpha masks,
// single- and double-sided faces, vertex colours and the metallic-roughness map per texel, and
// texture transforms, each pixel checked against the formula of docs/lighting.md written here by
// hand, in every technique, as tests/image/AnalyticTest.cpp (whose opening comment gives the
// tolerance, 2e-5 + 1e-4 relative, and why). These scenes load their glTF materials with the
// mapping to Blinn-Phong (`"model_materials": "blinn-phong"`), which their expected colours
// follow; tests/image/MetallicRoughnessTest.cpp checks glTF's own model.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "AnalyticSupport.h"
#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"

namespace manylights {
namespace {

using test::checkEveryPixel;
using test::kTopCamera;
using test::scratchDirectory;
using test::writeQuadGltf;

// How far from a shadow's edge the shadow test's filter can reach (as tests/image/ShadowTest.cpp).
constexpr double kPenumbraMargin = 0.05;

class AnalyticGltf : public ::testing::TestWithParam<std::string> {};

// A glTF dielectric (metallic 0, roughness 1: ks = 0.04, exponent 1) lit by a directional
// light: ambient · kd + (kd · N·L + ks · max(N·H, 0)^1) · intensity (docs/lighting.md).
glm::dvec3 dielectricRoughColour(const glm::dvec3& base, const glm::dvec3& p, const glm::dvec3& n,
                                 const glm::dvec3& toLight, double ambient, const glm::dvec3& eye)
{
    const double NdotL = glm::dot(n, toLight);
    if (NdotL <= 0.0)
        return ambient * base;
    const glm::dvec3 h = glm::normalize(toLight + glm::normalize(eye - p));
    return ambient * base + base * NdotL + glm::dvec3(0.04 * std::max(glm::dot(n, h), 0.0));
}

// Returned where a pixel shows a surface it must not (the check fails there).
constexpr glm::dvec3 kWrongSurface{-1.0};

TEST_P(AnalyticGltf, AlphaMaskCutsTheSurfaceAndItsShadow)
{
    // A 2x2 quad at y = 1 over a grey plane (kd 0.5), alphaMode MASK at 0.5, its coverage the
    // vertex colours' alpha: 1 at x = −1, 0 at x = 1, so a(x) = (1 − x)/2 (affine across the
    // quad, which faces the camera squarely, so perspective-correct interpolation is affine in
    // the image too): cut where x > 0. Ambient 0.2 and a shadowing directional light along
    // (1, −1, 0), L = (−1, 1, 0)/√2, N·L = 1/√2 on both surfaces.
    // - The quad shows exactly where a(x) ≥ 0.5; its colour: a glTF dielectric of base colour
    //   (1, 0.5, 0.25) (dielectricRoughColour).
    // - The plane shows where the eye ray misses the quad's uncut part; it is in shadow where
    //   the ray from it towards the light meets the uncut part at y = 1, i.e. at (x − 1, z):
    //   0.5 · 0.2, else 0.5 · (0.2 + 1/√2). Under the cut half (0 < x < 1) it is shadowed (the
    //   light passes the uncut half); at 1 < x < 2 it is lit, as the light passes the hole:
    //   a shadow pass that ignored the mask would darken it.
    const auto dir = scratchDirectory();
    const std::array<glm::vec4, 4> colours = {glm::vec4(1, 1, 1, 1), glm::vec4(1, 1, 1, 0), glm::vec4(1, 1, 1, 0),
                                              glm::vec4(1, 1, 1, 1)};
    writeQuadGltf(dir / "quad.gltf",
                  {glm::vec3(-1, 1, 1), glm::vec3(1, 1, 1), glm::vec3(1, 1, -1), glm::vec3(-1, 1, -1)}, {0, 1, 0},
                  colours,
                  {{"alphaMode", "MASK"},
                   {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.5, 0.25, 1.0}}, {"metallicFactor", 0.0}}}});
    const std::string scene = std::string("{") + kTopCamera + R"(, "model_materials": "blinn-phong",
        "ambient": [0.2, 0.2, 0.2],
        "directional": {"direction": [1, -1, 0], "intensity": [1, 1, 1], "shadows": true},
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [{"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
                    {"mesh": ")" +
                              (dir / "quad.gltf").string() + R"("}]})";
    const glm::dvec3 eye(0, 10, 0);
    const glm::dvec3 toLight = glm::normalize(glm::dvec3(-1, 1, 0));
    const auto coverage = [](double x) { return (1.0 - x) / 2.0; };
    // Whether (x, z) at y = 1 is on the quad's uncut part; nullopt within `margin` of an edge.
    const auto onUncutQuad = [&](double x, double z, double margin) -> std::optional<bool> {
        if (std::abs(std::abs(x) - 1.0) < margin || std::abs(std::abs(z) - 1.0) < margin ||
            std::abs(coverage(x) - 0.5) < margin)
            return std::nullopt;
        return std::abs(x) < 1.0 && std::abs(z) < 1.0 && coverage(x) >= 0.5;
    };
    int quad = 0, lit = 0, shadowed = 0, litThroughTheHole = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        if (std::abs(p.y - 1.0) < 1e-3) {  // the quad
            const auto uncut = onUncutQuad(p.x, p.z, 1e-3);
            if (!uncut)
                return std::nullopt;
            if (!*uncut)
                return kWrongSurface;  // drawn where it is cut
            ++quad;
            return dielectricRoughColour({1.0, 0.5, 0.25}, p, {0, 1, 0}, toLight, 0.2, eye);
        }
        // The plane: the eye ray must not have passed through the uncut quad.
        const glm::dvec3 atQuad = eye + (p - eye) * ((eye.y - 1.0) / (eye.y - p.y));
        const auto hidden = onUncutQuad(atQuad.x, atQuad.z, 1e-3);
        if (!hidden)
            return std::nullopt;
        if (*hidden)
            return kWrongSurface;
        const auto inShadow = onUncutQuad(p.x - 1.0, p.z, kPenumbraMargin);
        if (!inShadow)
            return std::nullopt;
        if (*inShadow) {
            ++shadowed;
            return glm::dvec3(0.5 * 0.2);
        }
        ++lit;
        if (p.x > 1.0 && p.x < 2.0 && std::abs(p.z) < 1.0)
            ++litThroughTheHole;
        return glm::dvec3(0.5 * (0.2 + 1.0 / std::sqrt(2.0)));
    };
    checkEveryPixel(scene, expected, "97x97", dir);
    // Pixels are 0.12 units on the plane: the quad's uncut half (1 x 2 units) holds about 170.
    EXPECT_GT(quad, 120);
    EXPECT_GT(shadowed, 70);
    EXPECT_GT(litThroughTheHole, 70);
    EXPECT_GT(lit, 3000);
}

TEST_P(AnalyticGltf, SingleSidedBackFacesAreCulledDoubleSidedOnesLitFromTheirSide)
{
    // Two quads at y = 1 facing down (normal −Y, wound clockwise seen from above), so the
    // camera above sees their back faces; a directional light straight down, ambient 0.1.
    // - Left (x in [−3, −1]), single-sided: culled, the plane (kd 0.5) shows: 0.5 · 1.1.
    // - Right (x in [1, 3]), doubleSided: drawn and lit as a face with normal +Y:
    //   dielectricRoughColour with N·L = 1 (lit with its own −Y normal it would be ambient only).
    const auto dir = scratchDirectory();
    const nlohmann::json material = {
        {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.8, 1.0}}, {"metallicFactor", 0.0}}}};
    nlohmann::json doubleSided = material;
    doubleSided["doubleSided"] = true;
    const auto corners = [](float x0, float x1) {
        return std::array<glm::vec3, 4>{glm::vec3(x0, 1, -1), glm::vec3(x1, 1, -1), glm::vec3(x1, 1, 1),
                                        glm::vec3(x0, 1, 1)};
    };
    writeQuadGltf(dir / "single.gltf", corners(-3, -1), {0, -1, 0}, std::nullopt, material);
    writeQuadGltf(dir / "double.gltf", corners(1, 3), {0, -1, 0}, std::nullopt, doubleSided);
    const std::string scene = std::string("{") + kTopCamera + R"(, "model_materials": "blinn-phong",
        "ambient": [0.1, 0.1, 0.1],
        "directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1]},
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [{"mesh": {"primitive": "plane", "size": [12, 12]}, "material": "grey"},
                    {"mesh": ")" +
                              (dir / "single.gltf").string() + R"("},
                    {"mesh": ")" +
                              (dir / "double.gltf").string() + R"("}]})";
    const glm::dvec3 eye(0, 10, 0);
    int planeUnderSingle = 0, doubleSidedQuad = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const bool nearEdge = std::abs(std::abs(p.z) - 1.0) < 1e-3 || std::abs(std::abs(p.x) - 1.0) < 1e-3 ||
                              std::abs(std::abs(p.x) - 3.0) < 1e-3;
        if (std::abs(p.y - 1.0) < 1e-3) {
            if (nearEdge)
                return std::nullopt;
            if (p.x < 0.0)
                return kWrongSurface;  // the single-sided quad's back face was drawn
            ++doubleSidedQuad;
            return dielectricRoughColour({0.2, 0.4, 0.8}, p, {0, 1, 0}, {0, 1, 0}, 0.1, eye);
        }
        const glm::dvec3 atQuads = eye + (p - eye) * ((eye.y - 1.0) / (eye.y - p.y));
        if (std::abs(atQuads.z) < 1.0 && atQuads.x > -3.0 && atQuads.x < -1.0 && !nearEdge)
            ++planeUnderSingle;
        return glm::dvec3(0.5 * 1.1);
    };
    checkEveryPixel(scene, expected, "65x65", dir);
    EXPECT_GT(planeUnderSingle, 50);
    EXPECT_GT(doubleSidedQuad, 50);
}

TEST_P(AnalyticGltf, VertexColoursAndMetallicRoughnessMapShadePerTexel)
{
    // A large quad facing up with constant vertex colour c = (0.5, 1, 0.25), base colour
    // factor (0.8, 0.8, 0.8), metallicFactor 1 and roughnessFactor 1 times a constant
    // metallic-roughness map (G = 128: roughness 128/255; B = 102: metallic 0.4). Per texel
    // (docs/scene-format.md): base = 0.8 · c, kd = base · (1 − m), ks = 0.04 · (1 − m) + base · m,
    // s = 2/roughness⁴ − 2 (roughness⁴ = α² with α = roughness²). A point light above, range
    // falloff 10: colour = I · A(d) · (kd · N·L + ks · max(N·H, 0)^s).
    const auto dir = scratchDirectory();
    std::vector<unsigned char> map(16 * 16 * 4, 0);
    for (std::size_t i = 0; i < map.size(); i += 4) {
        map[i + 1] = 128;
        map[i + 2] = 102;
        map[i + 3] = 255;
    }
    ASSERT_NE(stbi_write_png((dir / "mr.png").string().c_str(), 16, 16, 4, map.data(), 16 * 4), 0);
    const glm::vec4 c(0.5f, 1.0f, 0.25f, 1.0f);
    writeQuadGltf(dir / "quad.gltf",
                  {glm::vec3(-20, 0, 20), glm::vec3(20, 0, 20), glm::vec3(20, 0, -20), glm::vec3(-20, 0, -20)},
                  {0, 1, 0}, std::array<glm::vec4, 4>{c, c, c, c},
                  {{"pbrMetallicRoughness",
                    {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}},
                     {"metallicFactor", 1.0},
                     {"roughnessFactor", 1.0},
                     {"metallicRoughnessTexture", {{"index", 0}}}}}},
                  {"mr.png"});
    const std::string scene = std::string("{") + kTopCamera + R"(, "model_materials": "blinn-phong",
        "lights": [{"type": "point", "pos": [0.5, 2, -0.5], "intensity": [1, 1, 1], "range": 10}],
        "objects": [{"mesh": ")" +
                              (dir / "quad.gltf").string() + R"("}]})";
    const double metallic = 102.0 / 255.0;
    const double roughness = 128.0 / 255.0;
    const glm::dvec3 base = 0.8 * glm::dvec3(0.5, 1.0, 0.25);
    const glm::dvec3 kd = base * (1.0 - metallic);
    const glm::dvec3 ks = glm::dvec3(0.04 * (1.0 - metallic)) + base * metallic;
    const double shininess = 2.0 / std::pow(roughness, 4.0) - 2.0;
    const glm::dvec3 light(0.5, 2, -0.5);
    const glm::dvec3 eye(0, 10, 0);
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        const double d = glm::length(light - p);
        const double attenuation = 1.0 / (d * d) - 1.0 / 100.0;
        const glm::dvec3 l = (light - p) / d;
        const glm::dvec3 h = glm::normalize(l + glm::normalize(eye - p));
        return attenuation * (kd * l.y + ks * std::pow(std::max(h.y, 0.0), shininess));
    };
    EXPECT_EQ(checkEveryPixel(scene, expected, "65x65", dir), 65 * 65);
}

TEST_P(AnalyticGltf, TextureTransformMovesTurnsAndScalesTheUvs)
{
    // A 4x4 quad facing up, its base colour texture four flat quadrants (glTF image space:
    // top-left white, top-right blue, bottom-left red, bottom-right green), lit by ambient 1
    // alone: colour = kd = the texel (0 or 1 per channel, exact through the sRGB decode).
    // KHR_texture_transform offset (0.25, 0.5), rotation 0.5, scale (1.5, 0.75): at glTF uv
    // (u, v) the texture is read at T · R · S · (u, v) with R = [cos sin; −sin cos] (the
    // extension's definition), wrapped (repeat); pixels within 0.1 of a quadrant edge in the
    // texture (where filtering blends quadrants) are not checked.
    const auto dir = scratchDirectory();
    const int size = 64;
    std::vector<unsigned char> texels(size * size * 4, 255);
    const auto quadrantColour = [](bool left, bool top) {
        return top ? (left ? glm::dvec3(1, 1, 1) : glm::dvec3(0, 0, 1))
                   : (left ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    };
    for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
            const glm::dvec3 colour = quadrantColour(column < size / 2, row < size / 2);
            for (int c = 0; c < 3; ++c)
                texels[static_cast<std::size_t>((row * size + column) * 4 + c)] = colour[c] > 0.0 ? 255 : 0;
        }
    ASSERT_NE(stbi_write_png((dir / "quadrants.png").string().c_str(), size, size, 4, texels.data(), size * 4), 0);
    const double rotation = 0.5;
    const glm::dvec2 offset(0.25, 0.5);
    const glm::dvec2 scale(1.5, 0.75);
    writeQuadGltf(
        dir / "quad.gltf", {glm::vec3(-2, 0, 2), glm::vec3(2, 0, 2), glm::vec3(2, 0, -2), glm::vec3(-2, 0, -2)},
        {0, 1, 0}, std::nullopt,
        {{"pbrMetallicRoughness",
          {{"metallicFactor", 0.0},
           {"baseColorTexture",
            {{"index", 0},
             {"extensions",
              {{"KHR_texture_transform",
                {{"offset", {offset.x, offset.y}}, {"rotation", rotation}, {"scale", {scale.x, scale.y}}}}}}}}}}},
        {"quadrants.png"});
    const std::string scene = std::string("{") + kTopCamera + R"(, "model_materials": "blinn-phong",
        "ambient": [1, 1, 1],
        "objects": [{"mesh": ")" +
                              (dir / "quad.gltf").string() + R"("}]})";
    int checked = 0;
    const auto expected = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
        // The quad's glTF uv: u from x = −2 to 2, v from z = −2 (v = 0, the image's top) to 2.
        const glm::dvec2 uv((p.x + 2.0) / 4.0, (p.z + 2.0) / 4.0);
        const glm::dvec2 scaled = uv * scale;
        const glm::dvec2 turned(std::cos(rotation) * scaled.x + std::sin(rotation) * scaled.y,
                                -std::sin(rotation) * scaled.x + std::cos(rotation) * scaled.y);
        const glm::dvec2 read = turned + offset;
        const glm::dvec2 wrapped = read - glm::floor(read);
        const auto nearEdge = [](double t) { return std::abs(t - 0.5) < 0.1 || t < 0.1 || t > 0.9; };
        if (nearEdge(wrapped.x) || nearEdge(wrapped.y) || std::abs(std::abs(p.x) - 2.0) < 0.05 ||
            std::abs(std::abs(p.z) - 2.0) < 0.05)
            return std::nullopt;
        ++checked;
        return quadrantColour(wrapped.x < 0.5, wrapped.y < 0.5);
    };
    checkEveryPixel(scene, expected, "129x129", dir);
    EXPECT_GT(checked, 200);
}

}  // namespace

INSTANTIATE_TEST_SUITE_P(Techniques, AnalyticGltf, ::testing::ValuesIn(techniqueNames()), test::techniqueTestName);

}  // namespace manylights
