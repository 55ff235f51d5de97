#include "render/volumes/VolumeDrawer.h"
#include "render/programs/Bindings.h"

#include "core/Error.h"
#include "render/frame/ScreenPasses.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {
// Locations and binding of shaders/volume.vert.
constexpr GLint kFirstVolumeLight = 0;
constexpr GLint kVolumeShape = 1;
constexpr GLuint kVolumeLightsBinding = bindings::VOLUME_LIGHTS_BUFFER_BINDING;
}  // namespace

VolumeDrawer::VolumeDrawer(const TechniqueVariant& technique)
    : global_("global terms", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "global.frag"}}, technique),
      lighting_("light volumes", {{GL_VERTEX_SHADER, "volume.vert"}, {GL_FRAGMENT_SHADER, "volume.frag"}}, technique),
      vertexArray_("light volume meshes")
{
    const Mesh sphere = makeBoundingSphere();
    const Mesh cone = makeBoundingCone();
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    const auto append = [&](const Mesh& mesh) {
        const MeshRange range{indices.size(), static_cast<GLsizei>(mesh.indices.size()),
                              static_cast<GLint>(positions.size())};
        for (const Vertex& vertex : mesh.vertices)
            positions.push_back(vertex.position);
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
        return range;
    };
    sphere_ = append(sphere);
    cone_ = append(cone);
    vertices_ = gl::Buffer::fromSpan<glm::vec3>("light volume vertices", positions, 0);
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("light volume indices", indices, 0);
    vertexArray_.setVertexBuffer(0, vertices_, sizeof(glm::vec3));
    vertexArray_.setFloatAttribute(0, 0, 3, 0);
    vertexArray_.setIndexBuffer(indices_);
}

void VolumeDrawer::prepare(const GpuScene& scene)
{
    globalVariant_ = &global_.variant(scene.lightingFeatures());
    lightingVariant_ = &lighting_.variant(scene.lightingFeatures());
    // Moving lights regroup: a light's volume shape depends on where the camera is.
    if (preparedFor_ == &scene && preparedVersion_ == scene.lightsVersion())
        return;
    preparedFor_ = &scene;
    preparedVersion_ = scene.lightsVersion();
    groups_ = groupLightVolumes(scene.packedLights());
    std::vector<std::uint32_t> lists = groups_.spheres;
    lists.insert(lists.end(), groups_.cones.begin(), groups_.cones.end());
    lists.insert(lists.end(), groups_.fullScreen.begin(), groups_.fullScreen.end());
    lightLists_ = gl::Buffer::fromSpan<std::uint32_t>("light volume lists", lists, 0);
}

void VolumeDrawer::drawGlobalTerms() const
{
    ML_ASSERT(globalVariant_);
    drawCoveredPixels(*globalVariant_);
}

const gl::Program& VolumeDrawer::lightingProgram() const
{
    ML_ASSERT(lightingVariant_);
    return *lightingVariant_;
}

void VolumeDrawer::drawVolumes(VolumeShape shape, std::size_t first, std::size_t count) const
{
    drawVolumes(shape, first, count, lightingProgram());
}

void VolumeDrawer::drawVolumes(VolumeShape shape, std::size_t first, std::size_t count,
                               const gl::Program& program) const
{
    std::size_t listStart = first;
    if (shape != VolumeShape::Sphere)
        listStart += groups_.spheres.size();
    if (shape == VolumeShape::FullScreen)
        listStart += groups_.cones.size();
    drawListed(lightLists_, shape, listStart, count, program);
}

void VolumeDrawer::drawListed(const gl::Buffer& list, VolumeShape shape, std::size_t first, std::size_t count,
                              const gl::Program& program) const
{
    if (count == 0)
        return;
    list.bindBase(GL_SHADER_STORAGE_BUFFER, kVolumeLightsBinding);
    program.set(kFirstVolumeLight, static_cast<unsigned>(first));
    program.set(kVolumeShape, static_cast<int>(shape));
    program.use();
    vertexArray_.bind();
    const auto instances = static_cast<GLsizei>(count);
    if (shape == VolumeShape::FullScreen) {
        gl::counted(glDrawArraysInstanced, GL_TRIANGLES, 0, 3, instances);
        return;
    }
    const MeshRange& range = shape == VolumeShape::Sphere ? sphere_ : cone_;
    gl::counted(glDrawElementsInstancedBaseVertex, GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)), instances, range.baseVertex);
}

}  // namespace manylights
