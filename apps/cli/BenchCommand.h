// `manylights bench` (docs/cli.md): sweeps techniques × light counts × image sizes over one
// scene and reports frame times and work counts as a table, a CSV, JSON and an SVG plot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "apps/cli/CommandSupport.h"
#include "apps/cli/Shard.h"
#include "render/frame/GBuffer.h"
#include "render/scene/TextureCache.h"

namespace CLI {
class App;
}

namespace manylights {

struct BenchOptions {
    std::string scenePath;                // empty: the built-in default scene
    std::vector<std::string> techniques;  // empty: every technique there is (techniqueNames())
    std::vector<int> lightCounts;         // empty: the scene's own lights
    std::vector<ImageSize> sizes{kDefaultImageSize};
    int frames = 5;
    // --warmup N: frames rendered before timing. None (--warmup auto, the default): until
    // the frame time settles (measure(): kSettledFrames in a row within kSettledSpread of each
    // other), within kWarmupTimeBox and kMaxWarmupFrames.
    std::optional<int> warmup;
    // --fps F: frame k of a combination (warm-up frames first, k from 1) is rendered at scene
    // time k / F, so that what the scene animates moves every frame, and its time counts the
    // posing (Renderer::setTime) as well as the frame. None: every frame at time 0.
    std::optional<double> fps;
    std::string csvPath;   // empty: no CSV
    std::string plotPath;  // empty: no plot
    // --json FILE: the sweep for scripts (scripts/lib/bench.py); "-" writes it to stdout, and the
    // table then goes to stderr. Empty: no JSON.
    std::string jsonPath;
    bool countWork = false;
    bool strict = false;     // --strict: model files' forgiven problems are errors
    CameraOptions camera;    // --camera, --eye, --look-at, --up, --fov-y
    DisplayOptions display;  // --exposure, --tonemap, --srgb, --aa: time the display pass too
    GBufferLayout gbufferLayout = kDefaultGBufferLayout;
    int anisotropy = kAutoAnisotropy;  // --anisotropy (TextureCache::setAnisotropy)
    // When a technique's median frame exceeds this at one light count, its later (larger)
    // counts at that size are skipped: a sweep to a million lights need not wait hours for
    // forward. 0: no budget.
    double budgetMs = 0.0;
    ShadowOptions shadows;        // --shadow-lights, --shadow-pool-mib
    bool rebuildShadows = false;  // draw every shadow page every frame (--rebuild-shadows)
    DriverOptions driver;         // --driver-profile, --device
    // --shard I/N: only the cases (size, count, technique), numbered in the sweep's order, with
    // number mod N = I − 1. Only shard 1's CSV has the header line, so the shards' CSVs
    // concatenate into the whole sweep's (in another row order).
    Shard shard;
};

// Adds the `bench` subcommand to `app`; what it parses lands in `options`. Malformed values
// (a size, a light count, an unknown technique, a repeated entry) are CLI11 parse errors.
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);

// Runs the sweep: progress on stderr, the table on stdout, then the CSV, the JSON and the plot.
// Throws manylights::Error on failure (the files are written only after the whole sweep).
void runBench(const BenchOptions& options);

}  // namespace manylights
