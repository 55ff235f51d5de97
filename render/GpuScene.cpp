#include "render/GpuScene.h"

#include <cmath>
#include <cstddef>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/Falloff.h"
#include "scene/ShadowSelection.h"
#include "scene/Transform.h"

namespace manylights {

namespace {
// Binding points shared with the shaders (lib/frame.glsl, lib/lights.glsl).
constexpr GLuint kFrameBinding = 0;
constexpr GLuint kLightsBinding = 0;
// Point lights get cos(cutoff) = −2: every direction passes the spot test and S = 1.
constexpr float kPointLightCosCutoff = -2.0f;
}  // namespace

GpuLight packLight(const Light& light, float attenuationThreshold)
{
    GpuLight packed{};
    packed.positionRadius = glm::vec4(light.position, lightRadius(light, attenuationThreshold));
    const bool spot = light.type == LightType::Spot;
    packed.intensityExponent = glm::vec4(light.intensity, spot ? light.exponent : 0.0f);
    if (light.falloff == Falloff::Classic)
        packed.attenuation = glm::vec4(light.attenuation.constant, light.attenuation.linear,
                                       light.attenuation.quadratic, 0.0f);
    else
        packed.attenuation = glm::vec4(light.range, 0.0f, 0.0f, 1.0f);
    packed.spotAxisCosCutoff =
        spot ? glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.cutoffDegrees)))
             : glm::vec4(0.0f, 0.0f, 0.0f, kPointLightCosCutoff);
    return packed;
}

FrameUniforms makeFrameUniforms(const Scene& scene, int width, int height, std::uint32_t lightCount)
{
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const Camera& camera = scene.camera;
    FrameUniforms frame{};
    frame.view = glm::lookAt(camera.eye, camera.lookAt, camera.up);
    const glm::mat4 projection =
        glm::perspective(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane, camera.farPlane);
    frame.viewProjection = projection * frame.view;
    frame.eye = glm::vec4(camera.eye, 1.0f);
    frame.viewAxis = glm::vec4(glm::normalize(camera.lookAt - camera.eye), 0.0f);
    frame.ambient = glm::vec4(scene.ambient, 0.0f);
    if (scene.directional) {
        frame.directionalToLight = glm::vec4(-glm::normalize(scene.directional->direction), 0.0f);
        frame.directionalIntensity = glm::vec4(scene.directional->intensity, 0.0f);
    }
    frame.background = glm::vec4(scene.background, 1.0f);
    frame.counts = glm::uvec4(lightCount, 0u, 0u, 0u);
    const float tanHalfFovY = std::tan(glm::radians(camera.fovYDegrees) / 2.0f);
    frame.projection = glm::vec4(tanHalfFovY * aspect, tanHalfFovY, camera.nearPlane, camera.farPlane);
    frame.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height), 1.0f / static_cast<float>(width),
                               1.0f / static_cast<float>(height));
    return frame;
}

GpuScene::GpuScene(const Scene& scene, const std::vector<Light>& lights)
    : scene_(scene), lightCount_(lights.size()), vertexArray_("scene vertices")
{
    std::vector<Vertex> allVertices;
    std::vector<std::uint32_t> allIndices;
    for (const Mesh& mesh : scene.meshes) {
        const auto baseVertex = static_cast<GLint>(allVertices.size());
        if (mesh.subMeshes.empty())
            meshRanges_.push_back({{baseVertex, allIndices.size(), static_cast<GLsizei>(mesh.indices.size()), {}}});
        else {
            std::vector<MeshRange> ranges;
            for (const SubMesh& sub : mesh.subMeshes)
                ranges.push_back({baseVertex, allIndices.size() + sub.firstIndex,
                                  static_cast<GLsizei>(sub.indexCount), sub.material});
            meshRanges_.push_back(std::move(ranges));
        }
        allVertices.insert(allVertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        allIndices.insert(allIndices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    vertices_ = gl::Buffer::fromSpan<Vertex>("mesh vertices", allVertices, 0);
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("mesh indices", allIndices, 0);
    vertexArray_.setVertexBuffer(0, vertices_, sizeof(Vertex));
    vertexArray_.setFloatAttribute(0, 0, 3, offsetof(Vertex, position));
    vertexArray_.setFloatAttribute(1, 0, 3, offsetof(Vertex, normal));
    vertexArray_.setFloatAttribute(2, 0, 2, offsetof(Vertex, uv));
    vertexArray_.setFloatAttribute(3, 0, 4, offsetof(Vertex, tangent));
    vertexArray_.setIndexBuffer(indices_);

    std::vector<Bounds> meshBounds;
    for (const Mesh& mesh : scene.meshes)
        meshBounds.push_back(mesh.bounds());
    for (const Object& object : scene.objects)
        for (const MeshRange& range : meshRanges_[object.mesh]) {
            const std::size_t material =
                object.materialOverridesMesh || !range.material ? object.material : *range.material;
            draws_.push_back({object.transform, normalMatrix(object.transform), range, material,
                              transformedBounds(meshBounds[object.mesh], object.transform)});
        }

    packedLights_.reserve(lights.size());
    for (const Light& light : lights)
        packedLights_.push_back(packLight(light, scene.attenuationThreshold));
    lightBuffer_ = gl::Buffer::fromSpan<GpuLight>("lights", packedLights_);
    frameBuffer_ = gl::Buffer("frame uniforms", sizeof(FrameUniforms), nullptr);
    setViewport(1, 1);
}

void GpuScene::setViewport(int width, int height)
{
    frame_ = makeFrameUniforms(scene_, width, height, static_cast<std::uint32_t>(lightCount_));
    frameBuffer_.update(0, sizeof(FrameUniforms), &frame_);
}

void GpuScene::bind() const
{
    vertexArray_.bind();
    frameBuffer_.bindBase(GL_UNIFORM_BUFFER, kFrameBinding);
    lightBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding);
}

void GpuScene::drawObjects(const gl::Program& program) const
{
    // Locations of shaders/mesh.vert and shaders/lib/material.glsl.
    enum : GLint { kModel = 0, kNormalMatrix = 1, kDiffuse = 10, kSpecular = 11, kShininess = 12, kEmissive = 13 };
    program.use();
    for (const DrawItem& draw : draws_) {
        const Material& material = scene_.materials[draw.material];
        program.set(kModel, draw.model);
        program.set(kNormalMatrix, draw.normalMatrix);
        program.set(kDiffuse, material.diffuse);
        program.set(kSpecular, material.specular);
        program.set(kShininess, material.shininess);
        program.set(kEmissive, material.emissive);
        const MeshRange& range = draw.range;
        glDrawElementsBaseVertex(GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)),
                                 range.baseVertex);
    }
}

Bounds GpuScene::objectsWorldBounds() const
{
    Bounds all;
    for (const DrawItem& draw : draws_)
        if (!draw.worldBounds.empty()) {
            all.extend(draw.worldBounds.min);
            all.extend(draw.worldBounds.max);
        }
    return all;
}

std::size_t GpuScene::drawObjectsDepthOnly(const gl::Program& program,
                                           const std::function<bool(const Bounds&)>& keep) const
{
    constexpr GLint kModel = 0;  // shaders/shadow_depth.vert
    program.use();
    std::size_t drawn = 0;
    for (const DrawItem& draw : draws_) {
        if (draw.worldBounds.empty() || !keep(draw.worldBounds))
            continue;
        program.set(kModel, draw.model);
        const MeshRange& range = draw.range;
        glDrawElementsBaseVertex(GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)),
                                 range.baseVertex);
        ++drawn;
    }
    return drawn;
}

}  // namespace manylights
