// A closed room with lights outside it and one inside (issue 47, "No light through walls"),
// as scene-file text: tests/gl/ShadowPagesTest.cpp renders it through the Renderer and
// tests/image/ShadowPoolCliTest.cpp through the executable, which reads scene files.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include <glm/glm.hpp>

namespace manylights::test {

// The room's inside: x and z from −2 to 2, y from 0 to 2.4; walls, floor and ceiling are boxes
// 0.4 thick that overlap at the edges, so no ray gets in between them.
inline constexpr double kRoomHalf = 2.0;
inline constexpr double kRoomHeight = 2.4;
inline constexpr double kWall = 0.4;

// `outside` lights around the room, each 0.1 to 0.4 outside a wall (one in four exactly 0.1),
// reaching 1.0 past the wall's inner face; one light inside and a box on the floor that casts
// its shadow. The lights outside are spread over the six outer faces by a low-discrepancy
// sequence (deterministic).
inline std::string roomSceneJson(int outside)
{
    std::ostringstream json;
    json.precision(9);
    const double outer = kRoomHalf + kWall;
    json << R"({"camera": {"eye": [1.6, 2.1, -1.7], "look_at": [-1.3, 0.3, -0.9], "fov_y": 70, "near": 0.05, "far": 20},
        "ambient": [0.1, 0.1, 0.1],
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "lights": [{"type": "point", "pos": [0.8, 1.6, 0.6], "intensity": [1.5, 1.5, 1.5], "range": 7})";
    for (int k = 0; k < outside; ++k) {
        const double u = std::fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double v = std::fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double gap = k % 4 == 0 ? 0.1 : 0.1 + 0.3 * std::fmod(k * 0.6180339887498949, 1.0);
        const int face = k % 6;
        const int axis = face / 2;
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        glm::dvec3 p;
        // Across the outer face: x and z over ±outer, y over −kWall to kRoomHeight + kWall.
        const double a = -outer + 2.0 * outer * u;
        const double b = axis == 1 ? -outer + 2.0 * outer * v : -kWall + (kRoomHeight + 2.0 * kWall) * v;
        if (axis == 0)
            p = {sign * (outer + gap), b, a};
        else if (axis == 2)
            p = {a, b, sign * (outer + gap)};
        else
            p = {a, sign > 0 ? kRoomHeight + kWall + gap : -kWall - gap, b};
        json << R"(, {"type": "point", "pos": [)" << p.x << ", " << p.y << ", " << p.z
             << R"(], "intensity": [1, 1, 1], "range": )" << gap + kWall + 1.0 << "}";
    }
    json << R"(],
        "objects": [
            {"mesh": {"primitive": "box", "size": [4.8, 0.4, 4.8]}, "material": "grey", "transform": {"translate": [0, -0.2, 0]}},
            {"mesh": {"primitive": "box", "size": [4.8, 0.4, 4.8]}, "material": "grey", "transform": {"translate": [0, 2.6, 0]}},
            {"mesh": {"primitive": "box", "size": [0.4, 3.2, 4.8]}, "material": "grey", "transform": {"translate": [2.2, 1.2, 0]}},
            {"mesh": {"primitive": "box", "size": [0.4, 3.2, 4.8]}, "material": "grey", "transform": {"translate": [-2.2, 1.2, 0]}},
            {"mesh": {"primitive": "box", "size": [4.8, 3.2, 0.4]}, "material": "grey", "transform": {"translate": [0, 1.2, 2.2]}},
            {"mesh": {"primitive": "box", "size": [4.8, 3.2, 0.4]}, "material": "grey", "transform": {"translate": [0, 1.2, -2.2]}},
            {"mesh": {"primitive": "box", "size": [0.6, 0.8, 0.6]}, "material": "grey", "transform": {"translate": [-0.5, 0.4, -0.5]}}]})";
    return json.str();
}

inline constexpr int kRoomOutsideLights = 4096;

}  // namespace manylights::test
