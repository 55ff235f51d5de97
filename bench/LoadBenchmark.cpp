// Model-file loading speed (Google Benchmark): `load_benchmark FILE...` times loading each OBJ,
// .gltf or .glb file (parsing, validation, normals; no GL) and reports bytes per second, which
// stays about constant when loading is linear in the file's size (docs/performance.md).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core/Error.h"
#include "scene/GltfLoader.h"
#include "scene/ObjLoader.h"

namespace {

void loadModel(benchmark::State& state, const std::filesystem::path& path)
{
    const bool obj = path.extension() == ".obj";
    std::size_t triangles = 0;
    for (auto _ : state) {
        manylights::Warnings warnings;
        const manylights::Model model =
            obj ? manylights::loadObjModelFile(path, warnings) : manylights::loadGltfFile(path);
        triangles = 0;
        for (const manylights::Mesh& mesh : model.meshes)
            triangles += mesh.indices.size() / 3;
        benchmark::DoNotOptimize(triangles);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(std::filesystem::file_size(path)));
    state.counters["triangles"] = static_cast<double>(triangles);
}

}  // namespace

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: load_benchmark [--benchmark_...] FILE.obj|FILE.gltf|FILE.glb...\n");
        return 2;
    }
    try {
        for (int i = 1; i < argc; ++i) {
            const std::filesystem::path path = argv[i];
            // Loaded once first, so that a broken file is one error line, not a benchmark.
            manylights::Warnings warnings;
            if (path.extension() == ".obj")
                manylights::loadObjModelFile(path, warnings);
            else
                manylights::loadGltfFile(path);
            benchmark::RegisterBenchmark(path.filename().string().c_str(), loadModel, path)
                ->Unit(benchmark::kMillisecond);
        }
    } catch (const manylights::Error& e) {
        std::fprintf(stderr, "load_benchmark: %s\n", e.what());
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
