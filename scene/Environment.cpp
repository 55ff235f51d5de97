#include "scene/Environment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace manylights {

namespace {

constexpr double kPi = std::numbers::pi;

// Hermite step from 0 at `edge0` to 1 at `edge1`.
double smoothStep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A soft-edged rectangular area light of the studio: centred at azimuth `azimuth` (radians,
// as atan2(x, −z)) and elevation `elevation` (radians above the horizon), `halfWidth` and
// `halfHeight` radians across, its edge fading over `soft` radians.
struct Softbox {
    double azimuth;
    double elevation;
    double halfWidth;
    double halfHeight;
    double soft;
    glm::dvec3 radiance;

    double weight(double az, double el) const
    {
        const double dAz = std::remainder(az - azimuth, 2.0 * kPi) * std::cos(el);
        const double dEl = el - elevation;
        return (1.0 - smoothStep(halfWidth - soft, halfWidth, std::abs(dAz))) *
               (1.0 - smoothStep(halfHeight - soft, halfHeight, std::abs(dEl)));
    }
};

// The studio's radiances: a grey sky that brightens from the horizon to the zenith, a darker
// warm floor, and softboxes 10 to 30 times the sky, bright enough to show as highlights on a
// rough metal, dim enough that the prefiltered map's samples stay smooth.
constexpr glm::dvec3 kSkyHorizon{0.30, 0.32, 0.35};
constexpr glm::dvec3 kSkyZenith{0.45, 0.48, 0.55};
constexpr glm::dvec3 kFloorNear{0.05, 0.045, 0.04};
constexpr glm::dvec3 kFloorFar{0.10, 0.09, 0.08};
constexpr double kDegree = kPi / 180.0;
const Softbox kSoftboxes[] = {
    // key: in front and to the left of a camera looking along −Z, raised 35°
    {-140.0 * kDegree, 35.0 * kDegree, 22.0 * kDegree, 14.0 * kDegree, 4.0 * kDegree, {10.0, 9.5, 8.8}},
    // fill: to the right, lower and dimmer
    {120.0 * kDegree, 15.0 * kDegree, 16.0 * kDegree, 12.0 * kDegree, 4.0 * kDegree, {3.0, 3.2, 3.6}},
    // a long strip high behind the subject
    {0.0, 60.0 * kDegree, 50.0 * kDegree, 4.0 * kDegree, 2.0 * kDegree, {6.0, 6.0, 6.0}},
};
// The horizon's blend between floor and sky, in radians of elevation: a few texels of the
// built-in map, so that the mirror reflection of the horizon is not a jagged line.
constexpr double kHorizonBlend = 1.5 * kDegree;

glm::dvec3 studioRadiance(const glm::dvec3& d)
{
    const double elevation = std::asin(std::clamp(d.y, -1.0, 1.0));
    const double azimuth = std::atan2(d.x, -d.z);
    const glm::dvec3 sky = glm::mix(kSkyHorizon, kSkyZenith, std::max(d.y, 0.0));
    const glm::dvec3 floor = glm::mix(kFloorNear, kFloorFar, std::clamp(1.0 + d.y, 0.0, 1.0));
    glm::dvec3 radiance = glm::mix(floor, sky, smoothStep(-kHorizonBlend, kHorizonBlend, elevation));
    for (const Softbox& box : kSoftboxes)
        radiance = glm::mix(radiance, box.radiance, box.weight(azimuth, elevation));
    return radiance;
}

}  // namespace

bool isBuiltinEnvironment(std::string_view map) { return map.starts_with(kBuiltinEnvironmentPrefix); }

glm::vec2 environmentUv(const glm::dvec3& d)
{
    return {0.5 + std::atan2(d.x, -d.z) / (2.0 * kPi), std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi};
}

glm::dvec3 environmentDirection(const glm::dvec2& uv)
{
    const double phi = (uv.x - 0.5) * 2.0 * kPi;
    const double theta = uv.y * kPi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

glm::dvec3 environmentLookup(const glm::dvec3& d, double rotationDegrees)
{
    const double angle = rotationDegrees * kDegree;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {d.x * c - d.z * s, d.y, d.x * s + d.z * c};
}

double environmentTexelSolidAngle(int row, int height)
{
    const double theta0 = kPi * row / height;
    const double theta1 = kPi * (row + 1) / height;
    return kPi / height * (std::cos(theta0) - std::cos(theta1));
}

EnvironmentImage studioEnvironment(int height)
{
    EnvironmentImage map{.width = 2 * height, .height = height, .radiance = {}};
    map.radiance.resize(static_cast<std::size_t>(map.width) * height);
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec2 uv((i + 0.5) / map.width, (j + 0.5) / map.height);
            map.at(i, j) = glm::vec3(studioRadiance(environmentDirection(uv)));
        }
    return map;
}

IrradianceSh irradianceSh(const EnvironmentImage& map)
{
    // Each texel's radiance times the exact integral over its (u, v) rectangle of the
    // monomials 1, y, z, x, xy, yz, z², xz, x², y² (x = sinθ sinφ, y = cosθ, z = −sinθ cosφ;
    // dω = sinθ dθ dφ), which separate into an integral over θ and one over φ.
    std::array<glm::dvec3, 10> moments{};
    const double dPhi = 2.0 * kPi / map.width;
    // The integrals over each column's φ interval, the same for every row.
    struct Column {
        double sin, cos, sin2, cos2, sinCos;
    };
    std::vector<Column> columns(static_cast<std::size_t>(map.width));
    for (int i = 0; i < map.width; ++i) {
        const double p0 = (i - map.width / 2.0) * dPhi;  // φ = (u − 0.5) · 2π
        const double p1 = p0 + dPhi;
        const double sin2 = dPhi / 2.0 - (std::sin(2 * p1) - std::sin(2 * p0)) / 4.0;
        columns[static_cast<std::size_t>(i)] = {std::cos(p0) - std::cos(p1), std::sin(p1) - std::sin(p0), sin2,
                                                dPhi - sin2,
                                                (std::sin(p1) * std::sin(p1) - std::sin(p0) * std::sin(p0)) / 2.0};
    }
    for (int j = 0; j < map.height; ++j) {
        const double t0 = kPi * j / map.height;
        const double t1 = kPi * (j + 1) / map.height;
        const double c0 = std::cos(t0), c1 = std::cos(t1), s0 = std::sin(t0), s1 = std::sin(t1);
        const double tSin = c0 - c1;                                                         // ∫ sinθ
        const double tCos = (s1 * s1 - s0 * s0) / 2.0;                                       // ∫ cosθ sinθ
        const double tSin2 = (t1 - t0) / 2.0 - (std::sin(2 * t1) - std::sin(2 * t0)) / 4.0;  // ∫ sin²θ
        const double tCos2 = (c0 * c0 * c0 - c1 * c1 * c1) / 3.0;                            // ∫ cos²θ sinθ
        const double tSin3 = tSin - tCos2;                                                   // ∫ sin³θ
        const double tSin2Cos = (s1 * s1 * s1 - s0 * s0 * s0) / 3.0;                         // ∫ sin²θ cosθ
        for (int i = 0; i < map.width; ++i) {
            const Column& p = columns[static_cast<std::size_t>(i)];
            const glm::dvec3 L(map.at(i, j));
            moments[0] += L * (tSin * dPhi);        // 1
            moments[1] += L * (tCos * dPhi);        // y
            moments[2] += L * (-tSin2 * p.cos);     // z
            moments[3] += L * (tSin2 * p.sin);      // x
            moments[4] += L * (tSin2Cos * p.sin);   // xy
            moments[5] += L * (-tSin2Cos * p.cos);  // yz
            moments[6] += L * (tSin3 * p.cos2);     // z²
            moments[7] += L * (-tSin3 * p.sinCos);  // xz
            moments[8] += L * (tSin3 * p.sin2);     // x²
            moments[9] += L * (tCos2 * dPhi);       // y²
        }
    }
    // c = (Â_l / π) · K² · ∫ L · m, with the clamped cosine's Â_l / π = 1, 2/3, 1/4 and the
    // real harmonics Y = K · m: K² = 1/(4π); 3/(4π); 15/(4π) for xy, yz, xz; 5/(16π) for
    // 3z² − 1; 15/(16π) for x² − y².
    const double band0 = 1.0 / (4.0 * kPi);
    const double band1 = 2.0 / 3.0 * 3.0 / (4.0 * kPi);
    const double band2 = 0.25 * 15.0 / (4.0 * kPi);
    const double band2Zonal = 0.25 * 5.0 / (16.0 * kPi);
    const double band2Sectoral = 0.25 * 15.0 / (16.0 * kPi);
    const std::array<glm::dvec3, 9> c = {
        band0 * moments[0],
        band1 * moments[1],
        band1 * moments[2],
        band1 * moments[3],
        band2 * moments[4],
        band2 * moments[5],
        band2Zonal * (3.0 * moments[6] - moments[0]),
        band2 * moments[7],
        band2Sectoral * (moments[8] - moments[9]),
    };
    IrradianceSh sh;
    for (std::size_t k = 0; k < c.size(); ++k)
        sh[k] = glm::vec3(c[k]);
    return sh;
}

glm::dvec3 irradianceOverPi(const IrradianceSh& sh, const glm::dvec3& n)
{
    const std::array<double, 9> basis = {
        1.0, n.y, n.z, n.x, n.x * n.y, n.y * n.z, 3.0 * n.z * n.z - 1.0, n.x * n.z, n.x * n.x - n.y * n.y};
    glm::dvec3 e(0.0);
    for (std::size_t k = 0; k < basis.size(); ++k)
        e += glm::dvec3(sh[k]) * basis[k];
    return e;
}

}  // namespace manylights
