// Model files through the executable: a file's own materials reach the image (per-material
// draw ranges), glTF scenes render, and broken assets end in exit 1 with one line naming the
// file, nothing written, never a crash (run as a child process, so a crash shows as one).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;
using test::renderPfm;
using test::runExecutable;
using test::scratchDirectory;
using test::writeFile;

const fs::path kModels = fs::path(MANYLIGHTS_TEST_DATA_DIR) / "models";
const fs::path kAssimpGltf = "/usr/share/assimp/models/glTF2";

// The four quads of two-materials.obj (x from 0 to 4, y from 0 to 1, facing +Z) seen head-on,
// lit by the ambient term only: colour = ke + ambient ⊙ kd (docs/lighting.md).
TEST(ModelFile, ObjMaterialsReachTheImage)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", R"({
        "camera": { "eye": [2, 0.5, 6], "look_at": [2, 0.5, 0], "fov_y": 30 },
        "ambient": [1, 1, 1],
        "objects": [ { "mesh": ")" + (kModels / "two-materials.obj").string() +
                                      R"(" } ] })");
    const Image image = renderPfm((dir / "scene.json").string(), dir / "final.pfm", {"--size", "64x32"});
    // The half-width at the quads is 6 · tan 15° · 2 = 3.215, so x maps to column
    // 32 + 32 · (x − 2) / 3.215. Quad centres at x = 0.5 (no material: the scene's default
    // 0.8 grey), 1.5 and 3.5 (the file's "red": kd (1, 0, 0), ke (0.1, 0, 0)).
    const auto column = [](float x) { return static_cast<int>(32.0f + 32.0f * (x - 2.0f) / 3.215f); };
    const float* plain = image.pixel(column(0.5f), 16);
    EXPECT_NEAR(plain[0], 0.8f, 1e-4f);
    EXPECT_NEAR(plain[1], 0.8f, 1e-4f);
    for (const float x : {1.5f, 3.5f}) {
        const float* red = image.pixel(column(x), 16);
        EXPECT_NEAR(red[0], 1.1f, 1e-4f) << x;
        EXPECT_NEAR(red[1], 0.0f, 1e-4f) << x;
        EXPECT_NEAR(red[2], 0.0f, 1e-4f) << x;
    }
}

// The glTF scene (engine, boxes in all three containers, lanterns with punctual lights) in
// every technique against forward, with TechniqueAgreementTest's tolerance: 1e-5 · |forward|
// + 1e-6 per channel (bit-identical on llvmpipe; the margin is for a GPU compiler's fused
// multiply-adds). The exact seed G-buffer layout: the compact layout's own bound is checked
// on other scenes by TechniqueAgreementTest.
TEST(ModelFile, GltfScenesEveryTechniqueMatchesForward)
{
    if (!fs::is_directory(kAssimpGltf))
        GTEST_SKIP() << "assimp-testmodels is not installed (scripts/setup.sh installs it)";
    const auto dir = scratchDirectory();
    const std::string scene = (fs::path(MANYLIGHTS_SOURCE_DIR) / "scenes/gltf-models.json").string();
    const Image forward = renderPfm(scene, dir / "forward.pfm", {"--size", "64x36", "--technique", "forward"});
    float brightest = 0.0f;
    for (const float value : forward.rgb)
        brightest = std::max(brightest, value);
    EXPECT_GT(brightest, 0.05f);  // the models are there and lit
    for (const std::string& technique : techniqueNames()) {
        if (technique == "forward")
            continue;
        const Image image = renderPfm(scene, dir / (technique + ".pfm"),
                                      {"--size", "64x36", "--technique", technique, "--gbuffer", "seed"});
        test::expectImagesNear(forward, image, test::kAgreementTolerance, technique);
    }
}

struct BrokenModel {
    std::string name;
    std::string mesh;  // the object's mesh path
    std::vector<std::string> parts;
    friend void PrintTo(const BrokenModel& c, std::ostream* os) { *os << c.name; }
};

class BrokenModelCli : public ::testing::TestWithParam<BrokenModel> {};

TEST_P(BrokenModelCli, ExitOneOneLineNothingWritten)
{
    const BrokenModel& c = GetParam();
    if (c.mesh.starts_with(kAssimpGltf.string()) && !fs::is_directory(kAssimpGltf))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const auto dir = scratchDirectory();
    writeFile(dir / "nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir / "truncated.glb", "glTF\x02\0\0\0");
    writeFile(dir / "scene.json", R"({ "objects": [ { "mesh": ")" + c.mesh + R"(" } ] })");
    const test::ProcessResult result =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--size", "16x16"});
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
    for (const std::string& part : c.parts)
        EXPECT_NE(result.stderrText.find(part), std::string::npos)
            << "missing '" << part << "' in: " << result.stderrText;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BrokenModelCli,
    ::testing::Values(BrokenModel{"obj_nan_position", "nan.obj", {"nan.obj: line 2:", "non-finite"}},
                      BrokenModel{"glb_truncated", "truncated.glb", {"truncated.glb: "}},
                      BrokenModel{"gltf_index_out_of_range",
                                  (kAssimpGltf / "IndexOutOfRange/IndexOutOfRange.gltf").string(),
                                  {"IndexOutOfRange.gltf: meshes[0].primitives[0].indices: index"}},
                      BrokenModel{"gltf_missing_bin",
                                  (kAssimpGltf / "MissingBin/BoxTextured.gltf").string(),
                                  {"MissingBin/BoxTextured.gltf: ", "BoxTextured0.bin"}},
                      BrokenModel{"glb_infinite_positions",
                                  (kAssimpGltf / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb").string(),
                                  {"BoxWithInfinites.glb: ", "non-finite"}},
                      BrokenModel{"gltf_recursive_nodes",
                                  (kAssimpGltf / "RecursiveNodes/RecursiveNodes.gltf").string(),
                                  {"RecursiveNodes.gltf: ", "cycle"}}),
    [](const ::testing::TestParamInfo<BrokenModel>& param) { return param.param.name; });

// A texture the material library names but that is not there: the model draws with the
// material's colour, and one warning line says so (exit 0); with --strict it is the error.
TEST(ModelFiles, MissingTextureIsAWarningAndStrictMakesItAnError)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
    writeFile(dir / "bad.mtl", "newmtl m\nKd 1 1 1\nmap_Kd missing.png\n");
    writeFile(dir / "scene.json", R"({ "objects": [ { "mesh": "bad.obj" } ] })");
    const test::ProcessResult forgiven =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--size", "16x16"});
    EXPECT_EQ(forgiven.exitCode, 0) << forgiven.stderrText;
    EXPECT_EQ(std::count(forgiven.stderrText.begin(), forgiven.stderrText.end(), '\n'), 1) << forgiven.stderrText;
    for (const char* part : {"manylights: warning: ", "scene.json: /objects/0/mesh: ",
                             "bad.mtl: material 'm': map_Kd 'missing.png' not found"})
        EXPECT_NE(forgiven.stderrText.find(part), std::string::npos) << part << " in: " << forgiven.stderrText;
    EXPECT_TRUE(fs::exists(dir / "out.png"));
    const test::ProcessResult strict = runExecutable(
        {"render", (dir / "scene.json").string(), "-o", (dir / "strict.png").string(), "--size", "16x16", "--strict"});
    EXPECT_EQ(strict.exitCode, 1) << strict.stderrText;
    EXPECT_NE(strict.stderrText.find("map_Kd 'missing.png' not found"), std::string::npos) << strict.stderrText;
    EXPECT_FALSE(fs::exists(dir / "strict.png"));
    // bench takes --strict the same way (it fails while loading, before any frame).
    const test::ProcessResult bench = runExecutable({"bench", (dir / "scene.json").string(), "--strict"});
    EXPECT_EQ(bench.exitCode, 1) << bench.stderrText;
    EXPECT_NE(bench.stderrText.find("map_Kd 'missing.png' not found"), std::string::npos) << bench.stderrText;
}

// A glTF file breaking the schema where tinygltf does not look (assimp's wrongTypes/badUint:
// a texture index of -1) renders with one warning naming the file, the JSON pointer and the
// field; --strict makes it the error of render and bench (exit 1, nothing written).
TEST(ModelFiles, GltfSchemaBreakIsAWarningAndStrictMakesItAnError)
{
    const fs::path model = kAssimpGltf / "wrongTypes/badUint.gltf";
    if (!fs::exists(model))
        GTEST_SKIP() << "assimp-testmodels is not installed (scripts/setup.sh installs it)";
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", R"({"camera": {"eye": [2, 2, 3], "look_at": [0, 0, 0]},
        "ambient": [1, 1, 1], "objects": [{"mesh": ")" +
                                      model.string() + R"("}]})");
    const std::string expected = model.string() +
                                 ": /materials/0/pbrMetallicRoughness/baseColorTexture/index: index must be an "
                                 "integer ≥ 0, got -1; read as none";
    const test::ProcessResult forgiven =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--size", "16x16"});
    EXPECT_EQ(forgiven.exitCode, 0) << forgiven.stderrText;
    EXPECT_EQ(std::count(forgiven.stderrText.begin(), forgiven.stderrText.end(), '\n'), 1) << forgiven.stderrText;
    EXPECT_TRUE(forgiven.stderrText.starts_with("manylights: warning: ")) << forgiven.stderrText;
    EXPECT_NE(forgiven.stderrText.find(expected), std::string::npos) << forgiven.stderrText;
    EXPECT_TRUE(fs::exists(dir / "out.png"));
    const std::vector<std::vector<std::string>> strictRuns = {
        {"render", (dir / "scene.json").string(), "-o", (dir / "strict.png").string(), "--size", "16x16", "--strict"},
        {"bench", (dir / "scene.json").string(), "--csv", (dir / "strict.csv").string(), "--size", "16x16",
         "--strict"}};
    for (const std::vector<std::string>& args : strictRuns) {
        const test::ProcessResult strict = runExecutable(args);
        EXPECT_EQ(strict.exitCode, 1) << args[0] << ": " << strict.stderrText;
        EXPECT_NE(strict.stderrText.find(expected), std::string::npos) << args[0] << ": " << strict.stderrText;
        EXPECT_EQ(strict.stderrText.find("warning"), std::string::npos) << args[0] << ": " << strict.stderrText;
    }
    EXPECT_FALSE(fs::exists(dir / "strict.png"));
    EXPECT_FALSE(fs::exists(dir / "strict.csv"));
}

// Debian's assimp-testmodels OBJ folder, files that assimp and most viewers open: every one
// with faces renders (with warnings saying what was forgiven), the stats count the warnings,
// and --strict turns the first into the error. The files without a triangle to draw stay
// errors: three hold only points or lines, and number_formats.obj's one face is degenerate
// (its corners (0, 0, 0), (1, 2, 3), (−1, −2, −3) are collinear).
TEST(ModelFiles, AssimpObjFolderRendersAsOtherToolsOpenIt)
{
    const fs::path folder = "/usr/share/assimp/models/OBJ";
    if (!fs::is_directory(folder))
        GTEST_SKIP() << "assimp-testmodels is not installed (scripts/setup.sh installs it)";
    const std::set<std::string> nothingToDraw = {"point_cloud.obj", "testline.obj", "testpoints.obj",
                                                 "number_formats.obj"};
    const auto dir = scratchDirectory();
    int rendered = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() != ".obj")
            continue;
        const std::string name = entry.path().filename().string();
        writeFile(dir / "scene.json", R"({"objects": [{"mesh": ")" + entry.path().string() + R"("}]})");
        const test::ProcessResult result =
            runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--size", "64x48",
                           "--stats", (dir / "stats.json").string()});
        if (nothingToDraw.contains(name)) {
            EXPECT_EQ(result.exitCode, 1) << name << ": " << result.stderrText;
            continue;
        }
        EXPECT_EQ(result.exitCode, 0) << name << ": " << result.stderrText;
        ++rendered;
        const std::size_t warningLines =
            static_cast<std::size_t>(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'));
        std::ifstream statsFile(dir / "stats.json");
        const nlohmann::json stats = nlohmann::json::parse(statsFile);
        EXPECT_EQ(stats.at("warnings").get<std::size_t>(), warningLines) << name << ": " << result.stderrText;
    }
    EXPECT_GE(rendered, 18);

    // box.obj uses "Default" with no material library: a warning, or under --strict the error.
    writeFile(dir / "scene.json", R"({"objects": [{"mesh": ")" + (folder / "box.obj").string() + R"("}]})");
    const test::ProcessResult strict = runExecutable(
        {"render", (dir / "scene.json").string(), "-o", (dir / "strict.png").string(), "--size", "64x48", "--strict"});
    EXPECT_EQ(strict.exitCode, 1) << strict.stderrText;
    EXPECT_NE(strict.stderrText.find("box.obj: line 22: usemtl 'Default'"), std::string::npos) << strict.stderrText;
    EXPECT_EQ(strict.stderrText.find("warning"), std::string::npos) << strict.stderrText;
    EXPECT_FALSE(fs::exists(dir / "strict.png"));
}

// A glTF camera by index or by name, and the same view given part by part on the command line,
// render the same image; an unknown camera names those the scene has.
TEST(ModelFiles, CamerasFromFilesAndFromTheCommandLineAgree)
{
    if (!fs::is_directory(kAssimpGltf))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json",
              R"({"objects": [{"name": "cams", "mesh": ")" + (kAssimpGltf / "cameras/Cameras.gltf").string() + R"("}],
                                     "lights": [{"type": "point", "pos": [0.5, 0.5, 2], "intensity": [1, 1, 1], "range": 5}]})");
    const std::string scene = (dir / "scene.json").string();
    const Image byIndex = renderPfm(scene, dir / "index.pfm", {"--size", "48x48", "--camera", "0"});
    const Image byName = renderPfm(scene, dir / "name.pfm", {"--size", "48x48", "--camera", "cams/nodes[1]"});
    const Image byParts = renderPfm(scene, dir / "parts.pfm",
                                    {"--size", "48x48", "--eye", "0.5,0.5,3", "--look-at", "0.5,0.5,2", "--up", "0,1,0",
                                     "--fov-y", "40.1070456", "--camera", "0"});
    EXPECT_EQ(byIndex.rgb, byName.rgb);
    EXPECT_EQ(byIndex.rgb, byParts.rgb);
    const auto lit = std::count_if(byIndex.rgb.begin(), byIndex.rgb.end(), [](float v) { return v > 0.0f; });
    EXPECT_GT(lit, 0);  // the square is in view

    const test::ProcessResult unknown =
        runExecutable({"render", scene, "-o", (dir / "x.png").string(), "--camera", "front"});
    EXPECT_EQ(unknown.exitCode, 1) << unknown.stderrText;
    EXPECT_NE(unknown.stderrText.find("--camera 'front': no such camera (it has 1: cams/nodes[1])"), std::string::npos)
        << unknown.stderrText;
    EXPECT_EQ(runExecutable({"render", scene, "-o", (dir / "x.png").string(), "--eye", "1,2"}).exitCode, 2);
    EXPECT_EQ(runExecutable({"render", scene, "-o", (dir / "x.png").string(), "--fov-y", "nan"}).exitCode, 2);
    const test::ProcessResult same =
        runExecutable({"render", scene, "-o", (dir / "x.png").string(), "--eye", "1,1,1", "--look-at", "1,1,1"});
    EXPECT_EQ(same.exitCode, 1) << same.stderrText;
    EXPECT_NE(same.stderrText.find("look_at must differ from eye"), std::string::npos) << same.stderrText;
    // The same check as the scene file's camera (scene/Scene.h: cameraProblem).
    const test::ProcessResult alongView = runExecutable(
        {"render", scene, "-o", (dir / "x.png").string(), "--eye", "0,5,0", "--look-at", "0,0,0", "--up", "0,2,0"});
    EXPECT_EQ(alongView.exitCode, 1) << alongView.stderrText;
    EXPECT_NE(alongView.stderrText.find("up is parallel to the view direction"), std::string::npos)
        << alongView.stderrText;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace manylights
