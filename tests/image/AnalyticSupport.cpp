#include "AnalyticSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <utility>

#include "TestSupport.h"
#include "render/output/Image.h"
#include "tests/support/ImageComparison.h"

namespace manylights::test {

int checkEveryPixel(const std::string& sceneJson, const Expected& expected, const std::string& size,
                    std::filesystem::path directory, const PixelCheck& check)
{
    return checkEveryPixelWithNormal(
        sceneJson, [&](const glm::dvec3& position, const glm::dvec3&) { return expected(position); }, size,
        std::move(directory), check);
}

int checkEveryPixelWithNormal(const std::string& sceneJson, const ExpectedWithNormal& expected, const std::string& size,
                              std::filesystem::path directory, const PixelCheck& check)
{
    const auto dir = directory.empty() ? scratchDirectory() : directory;
    writeFile(dir / "scene.json", sceneJson);
    const std::string technique = ::testing::TestWithParam<std::string>::GetParam();
    const Image colour = renderPfm((dir / "scene.json").string(), dir / "final.pfm",
                                   {"--size", size, "--technique", technique, "--gbuffer", check.gbuffer});
    const Image position = renderPfm((dir / "scene.json").string(), dir / "position.pfm",
                                     {"--size", size, "--view", "position", "--gbuffer", "seed"});
    const Image normal = renderPfm((dir / "scene.json").string(), dir / "normal.pfm",
                                   {"--size", size, "--view", "normal", "--gbuffer", "seed"});
    int checked = 0;
    int failures = 0;
    for (int y = 0; y < colour.height; ++y)
        for (int x = 0; x < colour.width; ++x) {
            const float* n = normal.pixel(x, y);
            if (n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f)
                continue;  // background: no surface
            const float* p = position.pixel(x, y);
            const std::optional<glm::dvec3> maybeWant =
                expected(glm::dvec3(p[0], p[1], p[2]), glm::dvec3(n[0], n[1], n[2]));
            if (!maybeWant)
                continue;
            const glm::dvec3 want = *maybeWant;
            const float* got = colour.pixel(x, y);
            ++checked;
            for (int c = 0; c < 3; ++c) {
                const double allowed = check.absolute + check.relative * std::abs(want[c]);
                if (std::abs(got[c] - want[c]) > allowed && ++failures <= 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << " at (" << p[0] << ", " << p[1]
                                  << ", " << p[2] << "): got " << got[c] << ", expected " << want[c];
            }
        }
    EXPECT_EQ(failures, 0);
    return checked;
}

const char* const kTopCamera = R"("camera": {"eye": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1],
                                      "fov_y": 60, "near": 0.1, "far": 100})";

void writeQuadGltf(const std::filesystem::path& path, const std::array<glm::vec3, 4>& corners, const glm::vec3& normal,
                   const std::optional<std::array<glm::vec4, 4>>& colours, const nlohmann::json& material,
                   const std::vector<std::string>& images)
{
    std::vector<float> floats;
    for (const glm::vec3& corner : corners)
        floats.insert(floats.end(), {corner.x, corner.y, corner.z});
    for (int i = 0; i < 4; ++i)
        floats.insert(floats.end(), {normal.x, normal.y, normal.z});
    floats.insert(floats.end(), {0, 1, 1, 1, 1, 0, 0, 0});
    if (colours)
        for (const glm::vec4& colour : *colours)
            floats.insert(floats.end(), {colour.r, colour.g, colour.b, colour.a});
    const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bytes(floats.size() * 4 + sizeof indices, '\0');
    std::memcpy(bytes.data(), floats.data(), floats.size() * 4);
    std::memcpy(bytes.data() + floats.size() * 4, indices, sizeof indices);
    std::ofstream(path.string() + ".bin", std::ios::binary) << bytes;

    using Json = nlohmann::json;
    Json gltf = {{"asset", {{"version", "2.0"}}}};
    gltf["buffers"] = Json::array({{{"uri", path.filename().string() + ".bin"}, {"byteLength", bytes.size()}}});
    const auto addView = [&](std::size_t offset, std::size_t length, std::size_t count, const char* type,
                             int component) {
        gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
        Json accessor = {{"bufferView", gltf["bufferViews"].size() - 1},
                         {"componentType", component},
                         {"count", count},
                         {"type", type}};
        if (std::string(type) == "VEC3" && gltf["accessors"].empty()) {  // POSITION needs its bounds
            const glm::vec3 low = glm::min(glm::min(corners[0], corners[1]), glm::min(corners[2], corners[3]));
            const glm::vec3 high = glm::max(glm::max(corners[0], corners[1]), glm::max(corners[2], corners[3]));
            accessor["min"] = {low.x, low.y, low.z};
            accessor["max"] = {high.x, high.y, high.z};
        }
        gltf["accessors"].push_back(accessor);
        return gltf["accessors"].size() - 1;
    };
    Json attributes = {{"POSITION", addView(0, 48, 4, "VEC3", 5126)},
                       {"NORMAL", addView(48, 48, 4, "VEC3", 5126)},
                       {"TEXCOORD_0", addView(96, 32, 4, "VEC2", 5126)}};
    std::size_t offset = 128;
    if (colours) {
        attributes["COLOR_0"] = addView(offset, 64, 4, "VEC4", 5126);
        offset += 64;
    }
    const std::size_t indexAccessor = addView(offset, sizeof indices, 6, "SCALAR", 5123);
    gltf["meshes"] =
        Json::array({{{"primitives", {{{"attributes", attributes}, {"indices", indexAccessor}, {"material", 0}}}}}});
    gltf["materials"] = Json::array({material});
    for (std::size_t i = 0; i < images.size(); ++i) {
        gltf["images"].push_back({{"uri", images[i]}});
        gltf["textures"].push_back({{"source", i}});
    }
    gltf["nodes"] = Json::array({{{"mesh", 0}}});
    gltf["scenes"] = Json::array({{{"nodes", {0}}}});
    gltf["scene"] = 0;
    gltf["extensionsUsed"] = Json::array({"KHR_texture_transform"});
    writeFile(path, gltf.dump(1));
}

}  // namespace manylights::test
