// The scene's local lights on the GPU: at rest and posed at a time, packed into one storage
// buffer (shaders/lib/lights.glsl), read as texels or uniform windows where the driver allows
// (render/programs/LightBatches.h), with a version counter for passes that cache what they derive
// from the lights. Made from the expanded light list alone (scene/LightSets.h): no other
// route to the lights.
//
// Moving lights are posed on the GPU (shaders/pose_lights.comp): their motions are uploaded
// once, and a frame whose time moved them runs one dispatch that writes their positions. The
// CPU poses them too, but only when something on the CPU asks for the posed lights (light
// markers, shadow selection, the CPU-culled techniques): a frame of tiled or clustered with a
// million moving lights costs the CPU nothing per light.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/driver/DriverProfile.h"
#include "render/programs/LightBatches.h"
#include "render/programs/LightingPrograms.h"
#include "scene/Scene.h"

namespace manylights {

// std430 layout of shaders/lib/lights.glsl: GpuLight.
struct GpuLight {
    glm::vec4 positionRadius;
    glm::vec4 intensityExponent;
    glm::vec4 attenuation;
    glm::vec4 spotAxisCosCutoff;
};
static_assert(sizeof(GpuLight) == 64);

// Packs a light for the GPU with its culling radius (lightRadius).
GpuLight packLight(const Light& light, float attenuationThreshold);

// std430 layout of shaders/pose_lights.comp: LightMotion. An animated light's motion, with its
// rest position and its index among the lights.
struct GpuLightMotion {
    glm::vec4 restPosition;  // w: the light's index, as bits
    glm::vec4 settings;
    glm::vec4 periods;  // w: the kind, as bits
};
static_assert(sizeof(GpuLightMotion) == 48);

// Packs light `index`'s motion (it has an animation) for the GPU.
GpuLightMotion packMotion(const Light& light, std::uint32_t index);

class SceneLights {
public:
    // `lights` are the scene's lights as rendered (explicit and generated, see expandLights),
    // at rest; `attenuationThreshold` the scene's (its classic lights' radii). `driver`: the
    // driver profile's choices (render/driver/DriverProfile.h). Posed at time 0, with light texels.
    // The lights are kept, and given to the shaders, in the order of their rest positions
    // along a Morton curve (scene/SpatialOrder.h), not in `lights`' order: a cluster's lights
    // are then neighbours in memory (docs/techniques.md, "The light lists of tiled and
    // clustered"). Every index below is into that order.
    SceneLights(const std::vector<Light>& lights, float attenuationThreshold, const DriverChoices& driver);

    // Poses the lights at time t (scene/Animation.h): notes the time; the GPU pose runs at
    // applyPose(), the CPU's when posed() or packed() is next asked for. Nothing when none
    // animates or t is the last pose's. The version changes only when something moved.
    void pose(double t);
    // Whether a pose() has moved lights that the buffer does not have yet.
    bool posePending() const { return gpuPosedAt_ != posedAt_; }
    // Whether any light has an animation: only then does a new time move a light.
    bool hasAnimatedLights() const { return !animated_.empty(); }
    // Writes the animated lights' positions at the last pose() into the buffer, on the GPU (one
    // dispatch), and makes them visible to every later read of the lights; nothing when
    // !posePending(). Renderer runs it as the frame's first pass.
    void applyPose();

    std::size_t count() const { return rest_.size(); }
    float attenuationThreshold() const { return attenuationThreshold_; }
    // The lights at rest, and light i's position as posed by pose() (its animation applied;
    // posed on the CPU at the first call after a pose). The GPU's positions agree with these
    // to within the float sine's rounding (shaders/pose_lights.comp). No posed copy of every
    // light is kept: at 16.7 million lights a Light is 144 bytes, 2.4 GB.
    const std::vector<Light>& rest() const { return rest_; }
    glm::vec3 posedPosition(std::size_t i) const
    {
        poseOnCpu();
        return glm::vec3(packed_[i].positionRadius);
    }
    // Light i as posed: its rest record at its posed position.
    Light posed(std::size_t i) const
    {
        Light light = rest_[i];
        light.position = posedPosition(i);
        return light;
    }
    // The posed lights as the shaders get them.
    const std::vector<GpuLight>& packed() const
    {
        poseOnCpu();
        return packed_;
    }
    // Changes whenever the lights move, for passes that cache data derived from them.
    std::uint64_t version() const { return version_; }
    // GPU memory held: the light buffer (whole windows) and the moving lights' motions.
    std::size_t memoryBytes() const { return buffer_.size() + motions_.size(); }

    // Binds the storage buffer and, where there are some, the light texels.
    void bind() const;
    // Binds lights [batch.first, batch.first + kLightsPerWindow) as the uniform block at
    // kLightWindowBinding; batch.first must be a multiple of kLightsPerWindow.
    void bindWindow(const LightBatch& batch) const;
    // Makes the light texels (render/programs/LightBatches.h; bound by bind()) when `wanted` and the
    // driver has them for this many lights (lightTexelsSupported); drops them otherwise
    // (RendererDesc::lightTexels). They are wanted from the start.
    void setTexels(bool wanted);
    // Where a pass that reads any light by index reads them: the light texels where there are
    // some, else the storage buffer.
    LightSource indexedSource() const { return texels_ ? LightSource::TexelBuffer : LightSource::StorageBuffer; }
    // Whether a pass whose pixels walk a batch of lights in order (deferred, forward; tiled and
    // clustered when the scene fits one window) reads the batch's uniform window
    // (bindWindow) rather than as by index. On a GPU, yes where the driver has the block
    // size: a read that every thread of a warp shares is a broadcast, what the vendors advise.
    // On a software rasteriser only without light texels, which it fetches faster than it
    // gathers from a uniform block, even at an index every lane shares (docs/performance.md:
    // LearnOpenGL's scene, 512 lights, deferred's lighting pass 620 ms from windows, 492 ms
    // from texels). The profile decides (DriverChoices::lightTexelsBeforeWindows).
    bool readsWindows() const { return windowsSupported_ && (!texelsBeforeWindows_ || !texels_); }
    // Where such a pass reads its lights: the batch's uniform window where readsWindows(),
    // else as by index. Its batches are lightsPerBatch(source) lights.
    LightSource walkedSource() const { return readsWindows() ? LightSource::UniformWindow : indexedSource(); }
    // Binds what reading `batch` from `source` needs beyond bind(): a uniform window's range.
    void bindSource(LightSource source, const LightBatch& batch) const
    {
        if (source == LightSource::UniformWindow)
            bindWindow(batch);
    }

private:
    void poseOnCpu() const;

    std::vector<Light> rest_;               // their animations move them
    mutable std::vector<GpuLight> packed_;  // posed at cpuPosedAt_
    std::vector<std::size_t> animated_;     // the lights with an animation, in order
    // The time of the last pose, and the times the CPU's copies and the buffer were posed at
    // (all three 0 from the constructor, which packs and uploads the lights as at t = 0).
    double posedAt_ = 0.0;
    mutable double cpuPosedAt_ = 0.0;
    double gpuPosedAt_ = 0.0;
    gl::Buffer motions_;       // the animated lights' GpuLightMotion, uploaded once
    gl::Program poseProgram_;  // shaders/pose_lights.comp, where some light moves
    float attenuationThreshold_;
    bool texelsBeforeWindows_;
    std::uint64_t version_ = 0;
    gl::Buffer buffer_;
    gl::BufferTexture texels_;  // buffer_ as texels, where the driver allows them
    bool windowsSupported_ = lightWindowsSupported();
};

}  // namespace manylights
