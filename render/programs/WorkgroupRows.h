// Dispatches whose workgroups may outnumber the 65,535 GL promises along x (a million lights
// at 64 a workgroup are 16,384; the format's 16,777,216 are 262,144): x up to
// kWorkgroupsPerRow, then rows along z. A shader finds its workgroup's place in the run with
// listedGroup() (shaders/lib/listed_dispatch.glsl, whose GROUPS_PER_ROW is this number); the
// indirect dispatches over lists the GPU makes grow the same rows there.
#pragma once

#include <algorithm>

#include <epoxy/gl.h>

namespace manylights {

inline constexpr GLuint kWorkgroupsPerRow = 32768;

// Dispatches `groups` workgroups (at least one) of the bound compute program in rows: the
// last row may run past `groups`, and the shader returns there.
inline void dispatchComputeInRows(GLuint groups)
{
    groups = std::max<GLuint>(groups, 1);
    const GLuint perRow = std::min(groups, kWorkgroupsPerRow);
    glDispatchCompute(perRow, 1, (groups + perRow - 1) / perRow);
}

}  // namespace manylights
