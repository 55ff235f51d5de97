// The scene on the GPU: one vertex and one index buffer for every mesh, the objects with
// their transforms and materials, the local lights in one storage buffer, and the per-frame
// uniform buffer.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"
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

// std140 layout of shaders/lib/frame.glsl: Frame.
struct FrameUniforms {
    glm::mat4 viewProjection;
    glm::mat4 view;
    glm::vec4 eye;
    glm::vec4 viewAxis;
    glm::vec4 ambient;
    glm::vec4 directionalToLight;
    glm::vec4 directionalIntensity;
    glm::vec4 background;
    glm::uvec4 counts;
    glm::vec4 projection;  // tan(fovX / 2), tan(fovY / 2), near, far
    glm::vec4 viewport;    // width, height, 1 / width, 1 / height
};

// The camera matrices for an image of the given size.
FrameUniforms makeFrameUniforms(const Scene& scene, int width, int height, std::uint32_t lightCount);

class GpuScene {
public:
    // `lights` are the scene's lights as rendered (explicit and generated, see expandLights).
    GpuScene(const Scene& scene, const std::vector<Light>& lights);

    // Binds the vertex array, the frame uniforms and the light buffer.
    void bind() const;
    // Draws every object with `program`, setting the uniforms of shaders/mesh.vert and
    // shaders/lib/material.glsl.
    void drawObjects(const gl::Program& program) const;
    // Depth-only passes (shadow maps): draws the objects whose world bounds pass `keep`,
    // setting only the model matrix (location 0); returns how many draws were made.
    // The union of the drawn objects' world bounds.
    Bounds objectsWorldBounds() const;
    std::size_t drawObjectsDepthOnly(const gl::Program& program, const std::function<bool(const Bounds&)>& keep) const;
    void setViewport(int width, int height);

    std::size_t lightCount() const { return lightCount_; }
    const std::vector<GpuLight>& packedLights() const { return packedLights_; }
    const FrameUniforms& frameUniforms() const { return frame_; }
    const Scene& scene() const { return scene_; }
    // Changes whenever an object's transform changes (cached shadow maps compare it). The
    // scene is static today; a per-frame transform update must call noteTransformsChanged().
    std::uint64_t transformsVersion() const { return transformsVersion_; }
    void noteTransformsChanged() { ++transformsVersion_; }

private:
    // One sub-mesh's place in the shared buffers.
    struct MeshRange {
        GLint baseVertex;
        std::size_t firstIndex;
        GLsizei indexCount;
        std::optional<std::size_t> material;  // the mesh file's own, if any
    };
    struct DrawItem {
        glm::mat4 model;
        glm::mat3 normalMatrix;
        MeshRange range;
        std::size_t material;
        Bounds worldBounds;  // for culling depth-only passes against a light's volume
    };

    const Scene& scene_;
    std::vector<std::vector<MeshRange>> meshRanges_;  // per mesh, its sub-meshes
    std::vector<DrawItem> draws_;
    std::vector<GpuLight> packedLights_;
    std::size_t lightCount_ = 0;
    std::uint64_t transformsVersion_ = 0;
    FrameUniforms frame_{};
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertexArray_;
    gl::Buffer lightBuffer_;
    gl::Buffer frameBuffer_;
};

}  // namespace manylights
