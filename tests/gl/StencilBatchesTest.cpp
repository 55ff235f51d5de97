// The stencil technique's light batches (render/volumes/StencilBatches.h); no GL context needed.
// What makes a batch exact is that its volumes rasterise disjoint pixels. The test checks that
// apart from the batcher's own rectangles: it places every vertex of each light's drawn mesh as
// shaders/volume.vert does, projects it as the GPU does, and requires the pixel boxes of a
// batch's volumes (widened by a pixel, as a triangle covers the pixels whose centres it holds)
// to be disjoint where both volumes can draw anything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "PackedLights.h"
#include "render/volumes/LightVolumes.h"
#include "render/volumes/StencilBatches.h"

namespace manylights {
namespace {

using test::pointLight;
using test::spotLight;

struct TestCamera {
    glm::mat4 view;
    glm::mat4 projection;
    StencilBatchView batchView;
};

TestCamera camera(const glm::vec3& eye, const glm::vec3& target, float fovYDegrees, int width, int height)
{
    TestCamera result;
    result.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    result.projection = glm::perspective(glm::radians(fovYDegrees), aspect, 0.5f, 200.0f);
    const float tanY = std::tan(glm::radians(fovYDegrees) / 2.0f);
    result.batchView = {.view = result.view,
                        .eye = eye,
                        .tanHalfFovX = tanY * aspect,
                        .tanHalfFovY = tanY,
                        .width = width,
                        .height = height};
    return result;
}

// Where a light's volume can draw: the box of its mesh's projected vertices in pixels, clipped
// to the image; nullopt when it draws nothing (wholly behind the eye, or beside the image); the
// whole image when the eye's plane cuts it (its projection is unbounded).
struct PixelBox {
    float x0, x1, y0, y1;
};

std::optional<PixelBox> drawnPixels(const TestCamera& cam, const GpuLight& light, bool cone)
{
    static const Mesh sphere = makeBoundingSphere();
    static const Mesh coneMesh = makeBoundingCone();
    const glm::vec3 centre(light.positionRadius);
    const float radius = light.positionRadius.w;
    // shaders/volume.vert.
    const glm::vec3 axis(light.spotAxisCosCutoff);
    const float cosCutoff = light.spotAxisCosCutoff.w;
    const float baseRadius = radius * std::sqrt(std::max(1.0f - cosCutoff * cosCutoff, 0.0f)) / cosCutoff;
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = cone ? glm::normalize(glm::cross(helper, axis)) : glm::vec3(0.0f);
    const glm::vec3 v = glm::cross(axis, u);
    const float width = static_cast<float>(cam.batchView.width);
    const float height = static_cast<float>(cam.batchView.height);
    PixelBox box{1e30f, -1e30f, 1e30f, -1e30f};
    int behind = 0;
    const std::vector<Vertex>& vertices = cone ? coneMesh.vertices : sphere.vertices;
    for (const Vertex& vertex : vertices) {
        const glm::vec3 p = vertex.position;
        const glm::vec3 world =
            cone ? centre + baseRadius * (p.x * u + p.y * v) + radius * p.z * axis : centre + radius * p;
        const glm::vec4 clip = cam.projection * cam.view * glm::vec4(world, 1.0f);
        if (clip.w <= 0.0f) {
            ++behind;
            continue;
        }
        const float x = (clip.x / clip.w + 1.0f) * 0.5f * width;
        const float y = (clip.y / clip.w + 1.0f) * 0.5f * height;
        box = {std::min(box.x0, x), std::max(box.x1, x), std::min(box.y0, y), std::max(box.y1, y)};
    }
    if (behind == static_cast<int>(vertices.size()))
        return std::nullopt;
    if (behind > 0)
        return PixelBox{0.0f, width, 0.0f, height};
    // A pixel is drawn when its centre lies inside a triangle: within the box, widened by a
    // pixel for the rasteriser's snapping.
    box = {std::max(box.x0 - 1.0f, 0.0f), std::min(box.x1 + 1.0f, width), std::max(box.y0 - 1.0f, 0.0f),
           std::min(box.y1 + 1.0f, height)};
    if (box.x0 >= box.x1 || box.y0 >= box.y1)
        return std::nullopt;
    return box;
}

bool overlap(const PixelBox& a, const PixelBox& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// Every light of the groups exactly once: the spheres around the eye first, then each batch's
// spheres and cones, each part ascending; and no two volumes of a batch that draw anything
// draw a common pixel. Returns how many lights shared a batch with another that draws.
int expectExactBatches(const TestCamera& cam, const std::vector<GpuLight>& lights, const StencilBatches& batches)
{
    const LightVolumeGroups groups = groupLightVolumes(lights);
    std::multiset<std::uint32_t> expected(groups.spheres.begin(), groups.spheres.end());
    expected.insert(groups.cones.begin(), groups.cones.end());
    EXPECT_EQ(std::multiset<std::uint32_t>(batches.order.begin(), batches.order.end()), expected);
    const std::set<std::uint32_t> cones(groups.cones.begin(), groups.cones.end());
    for (std::uint32_t i = 0; i < batches.order.size(); ++i) {
        const std::uint32_t light = batches.order[i];
        EXPECT_EQ(i < batches.aroundEye,
                  !cones.contains(light) && eyeInsideSphereVolume(lights[light], cam.batchView.eye))
            << "light " << light;
    }
    std::uint32_t next = batches.aroundEye;
    int shared = 0;
    for (const StencilBatch& batch : batches.batches) {
        EXPECT_EQ(batch.first, next);
        next += batch.spheres + batch.cones;
        const auto begin = batches.order.begin() + batch.first;
        EXPECT_TRUE(std::is_sorted(begin, begin + batch.spheres));
        EXPECT_TRUE(std::is_sorted(begin + batch.spheres, begin + batch.spheres + batch.cones));
        std::vector<std::pair<std::uint32_t, PixelBox>> drawing;
        for (std::uint32_t i = 0; i < batch.spheres + batch.cones; ++i) {
            const std::uint32_t light = *(begin + i);
            const bool cone = i >= batch.spheres;
            EXPECT_EQ(cones.contains(light), cone) << "light " << light;
            if (const std::optional<PixelBox> box = drawnPixels(cam, lights[light], cone))
                drawing.emplace_back(light, *box);
        }
        for (std::size_t a = 0; a < drawing.size(); ++a)
            for (std::size_t b = a + 1; b < drawing.size(); ++b)
                EXPECT_FALSE(overlap(drawing[a].second, drawing[b].second))
                    << "lights " << drawing[a].first << " and " << drawing[b].first << " share pixels in a batch";
        shared += drawing.size() > 1 ? static_cast<int>(drawing.size()) : 0;
    }
    EXPECT_EQ(next, batches.order.size());
    return shared;
}

// Lights of every kind about a camera looking down at a slant, as the courtyard's does: small
// and large spheres and cones on the ground, some around the eye, some cut by the eye's plane,
// some behind it, some beside the image.
TEST(StencilBatches, VolumesOfABatchShareNoPixel)
{
    const TestCamera cam = camera({0.0f, 20.0f, 14.0f}, {0.0f, 0.0f, -4.0f}, 50.0f, 320, 180);
    std::mt19937 random(7);
    const auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); };
    std::vector<GpuLight> lights;
    for (int i = 0; i < 3000; ++i) {
        glm::vec3 position(uniform(-30.0f, 30.0f), uniform(0.1f, 1.0f), uniform(-30.0f, 30.0f));
        float radius = uniform(0.2f, 2.0f);
        if (i % 50 == 0) {  // near or around the eye, or behind it
            position = cam.batchView.eye + glm::vec3(uniform(-4.0f, 4.0f), uniform(-4.0f, 4.0f), uniform(-4.0f, 4.0f));
            radius = uniform(0.5f, 5.0f);
        }
        if (i % 3 == 0)
            lights.push_back(
                spotLight(position, radius, {uniform(-1.0f, 1.0f), -1.0f, uniform(-1.0f, 1.0f)}, uniform(5.0f, 60.0f)));
        else
            lights.push_back(pointLight(position, radius));
    }
    StencilBatcher batcher;
    const StencilBatches& batches = batcher.group(cam.batchView, lights, groupLightVolumes(lights));
    const int shared = expectExactBatches(cam, lights, batches);
    // The cases are there: spheres around the eye, and most lights batched with others.
    EXPECT_GT(batches.aroundEye, 5u);
    EXPECT_GT(shared, 1000);
    EXPECT_LT(batches.batches.size(), lights.size() / 8);
    RecordProperty("batches", static_cast<int>(batches.batches.size()));
}

// Lights that all cover one spot can share no batch: one each, past the batches the batcher
// keeps open (StencilCellOccupancy), placed without searching the closed ones. Off-screen lights
// among them join the first batch. The batcher is reused with fewer lights after.
TEST(StencilBatches, LightsOnOneSpotTakeABatchEach)
{
    const TestCamera cam = camera({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, 45.0f, 160, 90);
    std::vector<GpuLight> lights(3000, pointLight({0.0f, 0.0f, 0.05f}, 0.2f));
    lights[10] = pointLight({0.0f, 0.0f, 30.0f}, 0.5f);   // behind the eye
    lights[11] = pointLight({500.0f, 0.0f, 0.0f}, 0.5f);  // beside the image
    StencilBatcher batcher;
    const StencilBatches& batches = batcher.group(cam.batchView, lights, groupLightVolumes(lights));
    EXPECT_EQ(batches.batches.size(), lights.size() - 2);
    EXPECT_EQ(batches.batches[0].spheres, 3u);
    expectExactBatches(cam, lights, batches);
    lights.resize(100);
    EXPECT_EQ(batcher.group(cam.batchView, lights, groupLightVolumes(lights)).batches.size(), 98u);
}

}  // namespace
}  // namespace manylights
