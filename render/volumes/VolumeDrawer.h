// What the volume techniques share: the bounding meshes, the per-shape light lists, the
// global-terms pass, and the draw of one shape's volumes.
#pragma once

#include <cstdint>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"
#include "render/programs/LightingPrograms.h"
#include "render/volumes/LightVolumes.h"

namespace manylights {

class GpuScene;

enum class VolumeShape : int { Sphere = 0, Cone = 1, FullScreen = 2 };

class VolumeDrawer {
public:
    explicit VolumeDrawer(const TechniqueVariant& technique);

    // Picks the programs for the scene's lighting features and rebuilds the per-shape light
    // lists when the scene's lights changed. Once per frame, before the draws below.
    void prepare(const GpuScene& scene);
    const LightVolumeGroups& groups() const { return groups_; }

    // ke + ambient + directional for every covered pixel, replacing the lit colour.
    void drawGlobalTerms() const;
    // Draws `count` lights of `shape` starting at `first` within that shape's list, with the
    // lighting program (or `program`, for the stencil pass). The pass it runs in sets the GL
    // state (render/frame/FramePasses.h).
    void drawVolumes(VolumeShape shape, std::size_t first, std::size_t count) const;
    void drawVolumes(VolumeShape shape, std::size_t first, std::size_t count, const gl::Program& program) const;
    // The same from a list of the caller's: `count` lights of `shape` whose indices into the
    // light buffer are `list`'s uints from `first` on (the stencil technique's batches).
    void drawListed(const gl::Buffer& list, VolumeShape shape, std::size_t first, std::size_t count,
                    const gl::Program& program) const;
    // The lighting program of the frame's lighting features (prepare).
    const gl::Program& lightingProgram() const;

private:
    struct MeshRange {
        std::size_t firstIndex;
        GLsizei indexCount;
        GLint baseVertex;
    };

    LightingProgram global_;
    LightingProgram lighting_;
    // The variants of this frame's lighting features (prepare).
    const gl::Program* globalVariant_ = nullptr;
    const gl::Program* lightingVariant_ = nullptr;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertexArray_;
    MeshRange sphere_{};
    MeshRange cone_{};
    LightVolumeGroups groups_;
    gl::Buffer lightLists_;  // spheres, then cones, then full-screen lights
    const GpuScene* preparedFor_ = nullptr;
    std::uint64_t preparedVersion_ = 0;
};

}  // namespace manylights
