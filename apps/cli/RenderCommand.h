// `manylights render` (docs/cli.md): renders a scene to PNG, PFM or EXR, one frame or an
// animation's frames, with statistics; the options as the command line gives them.
#pragma once

#include <optional>
#include <string>

#include "apps/cli/CommandSupport.h"
#include "apps/cli/Recording.h"
#include "apps/cli/Shard.h"
#include "render/Views.h"
#include "render/frame/GBuffer.h"
#include "render/scene/TextureCache.h"

namespace manylights {

struct RenderOptions {
    std::string scenePath;  // empty: the built-in default scene
    OutputImage output;     // with a time range, a pattern of paths (apps/cli/Recording.h)
    ImageSize size = kDefaultImageSize;
    std::string technique{kDefaultTechnique};
    ViewMode view = ViewMode::Final;
    double time = 0.0;
    std::optional<int> lights;
    int frames = 1;
    std::string statsPath;
    bool countWork = false;
    GBufferLayout gbufferLayout = kDefaultGBufferLayout;
    int anisotropy = kAutoAnisotropy;  // --anisotropy (TextureCache::setAnisotropy)
    // Recording: with a time range, `output` is a pattern (apps/cli/Recording.h) and every
    // frame of the range at `fps` is written.
    std::optional<TimeRange> timeRange;
    double fps = 30.0;
    Shard shard;                  // --shard I/N: only the frames k with k mod N = I − 1
    bool skipExisting = false;    // --skip-existing: only the frames whose files are missing
    ShadowOptions shadows;        // --shadow-lights, --shadow-pool-mib
    bool rebuildShadows = false;  // draw every shadow page every frame (--rebuild-shadows)
    bool strict = false;          // model files' forgiven problems are errors (--strict)
    CameraOptions camera;         // --camera, --eye, --look-at, --up, --fov-y
    DisplayOptions display;       // --exposure, --tonemap, --srgb, --aa (8-bit outputs)
    int supersample = 1;          // --supersample N: render N x N pixels per output pixel
    bool exrFloat = false;        // --exr-float: 32-bit float EXR channels instead of half
    bool aovs = false;            // --aovs: the G-buffer quantities as further EXR layers
    DriverOptions driver;         // --driver-profile, --device
    bool legend = true;           // the light-count view's colour bar in PNG outputs (--no-legend)
};

// Renders and writes the image (and the statistics); throws manylights::Error on failure.
void runRender(const RenderOptions& options);

}  // namespace manylights
