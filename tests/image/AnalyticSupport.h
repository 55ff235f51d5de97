// What the analytic image tests share (tests/image/AnalyticTest.cpp, AnalyticGltfTest.cpp,
// MetallicRoughnessTest.cpp): the check of every covered pixel against a colour derived by hand,
// with the tolerance AnalyticTest.cpp's opening comment gives, a camera looking straight down,
// and a one-quad glTF file.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "tests/support/ImageComparison.h"

namespace manylights::test {

// The expected colour at a world position; nullopt where either answer is right (a pixel
// within float rounding of a cut-off edge).
using Expected = std::function<std::optional<glm::dvec3>(const glm::dvec3& position)>;

// How checkEveryPixel renders and compares: by default the seed G-buffer layout and the analytic
// tolerance (2e-5 + 1e-4·|expected|, tests/support/ImageComparison.h).
struct PixelCheck {
    std::string gbuffer = "seed";
    double absolute = kAnalyticTolerance.absolute;
    double relative = kAnalyticTolerance.relative;
};

// Renders the scene's final image and position view with the technique the running test is
// parameterised with (a TestWithParam<std::string>), checks every covered pixel against
// `expected`, and returns how many pixels were checked. The files go to `directory` (which may
// hold the scene's model files), by default a fresh scratch directory.
int checkEveryPixel(const std::string& sceneJson, const Expected& expected, const std::string& size = "65x65",
                    std::filesystem::path directory = {}, const PixelCheck& check = {});

// The expected colour at a world position with the shading normal there (the seed layout's
// --view normal, 32-bit floats: the interpolated normal the lighting used, not the position's
// direction from a sphere's centre, which a tessellated sphere's flat triangles do not share).
using ExpectedWithNormal =
    std::function<std::optional<glm::dvec3>(const glm::dvec3& position, const glm::dvec3& normal)>;
// checkEveryPixel with the normal as well.
int checkEveryPixelWithNormal(const std::string& sceneJson, const ExpectedWithNormal& expected,
                              const std::string& size = "65x65", std::filesystem::path directory = {},
                              const PixelCheck& check = {});

// The camera straight above the origin looking down, so the centre of an odd-sized image
// sees exactly the origin.
extern const char* const kTopCamera;

// A glTF file of one quad: `corners` in order (glTF's front face is counter-clockwise seen from
// the side it faces), one `normal` for all four, glTF uvs (0, 1), (1, 1), (1, 0), (0, 0) (the
// texture's bottom-left, bottom-right, top-right, top-left) and RGBA vertex colours if given,
// drawn with `material`; `images` are paths for the textures 0, 1, ... in that order.
// A glTF file of one quad: `corners` in order (glTF's front face is counter-clockwise seen from
// the side it faces), one `normal` for all four, glTF uvs (0, 1), (1, 1), (1, 0), (0, 0) (the
// texture's bottom-left, bottom-right, top-right, top-left) and RGBA vertex colours if given,
// drawn with `material`; `images` are paths for the textures 0, 1, ... in that order.
void writeQuadGltf(const std::filesystem::path& path, const std::array<glm::vec3, 4>& corners, const glm::vec3& normal,
                   const std::optional<std::array<glm::vec4, 4>>& colours, const nlohmann::json& material,
                   const std::vector<std::string>& images = {});

}  // namespace manylights::test
