#include "scene/Revolution.h"

#include <cmath>

#include "scene/Mesh.h"

namespace manylights {

namespace {

constexpr float kTwoPi = 6.28318530718f;

// The wave's phase in turns, reduced to [0, 1) in double first: the shader does the same with
// fract() on the float time, and both then see a small angle.
float wavePhase(const RevolutionProfile& p, float v, double t)
{
    const double travelled = static_cast<double>(p.speed) * t;
    const auto offset = static_cast<float>(travelled - std::floor(travelled));
    return p.waves * v - offset;
}

}  // namespace

glm::vec3 revolutionPosition(const RevolutionProfile& p, float u, float v, double t)
{
    const float r = p.radius + p.amplitude * std::sin(kTwoPi * wavePhase(p, v, t));
    const float angle = kTwoPi * u;
    return {r * std::cos(angle), p.height * v, r * std::sin(angle)};
}

glm::vec3 revolutionNormal(const RevolutionProfile& p, float u, float v, double t)
{
    // ∂P/∂v = (r' cos, h, r' sin), ∂P/∂u = 2πr (−sin, 0, cos): their cross product points along
    // (h cos, −r', h sin), outwards for h > 0.
    const float slope = p.amplitude * kTwoPi * p.waves * std::cos(kTwoPi * wavePhase(p, v, t));
    const float angle = kTwoPi * u;
    return glm::normalize(glm::vec3{p.height * std::cos(angle), -slope, p.height * std::sin(angle)});
}

Mesh makeRevolutionMesh(const RevolutionProfile& profile, double t, int around, int up)
{
    Mesh mesh;
    mesh.name = "surface of revolution";
    for (int j = 0; j <= up; ++j) {
        const float v = static_cast<float>(j) / static_cast<float>(up);
        for (int i = 0; i <= around; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(around);
            const float angle = kTwoPi * u;
            Vertex vertex{};
            vertex.position = revolutionPosition(profile, u, v, t);
            vertex.normal = revolutionNormal(profile, u, v, t);
            vertex.uv = {u, v};
            // Along increasing u; right-handed with the outward normal.
            vertex.tangent = {-std::sin(angle), 0.0f, std::cos(angle), 1.0f};
            mesh.vertices.push_back(vertex);
        }
    }
    const auto row = static_cast<std::uint32_t>(around + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(up); ++j)
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(around); ++i) {
            const std::uint32_t a = j * row + i;
            const std::uint32_t b = a + 1;
            const std::uint32_t c = a + row;
            const std::uint32_t d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

}  // namespace manylights
