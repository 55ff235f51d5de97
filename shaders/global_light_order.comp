#version 450 core
// The global list in the lights' order (render/culling/ClusterLists.h), once per frame after the
// counting run of cluster_pairs.comp, which listed the candidates in whatever order its
// invocations ran. A rank sort: an invocation per candidate counts the candidates before it
// in the lights' order (their indices are distinct) and puts its light there, with the
// light's record beside it (lib/cluster_lists.glsl says why). The
// pixels then sum the global lights in one order on every run. Where the candidates are more
// than the list holds, globalLightCount() is 0 and nothing is written: they are wide lights.
// The list's length goes after its last possible entry, where the lighting reads it with the
// entries (a texel for all lanes on llvmpipe, not the status buffer lane by lane).
// Loop iterations: GLOBAL_LIGHT_CAPACITY at most, within render/programs/LightBatches.h's bound.
#include "lib/bindings.glsl"
#include "lib/lights.glsl"
#include "lib/cluster_list_status.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING) readonly buffer GlobalLightCandidates {
    uint candidate[];
};
layout(std430, binding = GLOBAL_LIGHTS_BUFFER_BINDING) writeonly buffer GlobalLights {
    uint globalLight[];  // GLOBAL_LIGHT_CAPACITY entries, then the count
};
layout(std430, binding = GLOBAL_LIGHT_RECORDS_BUFFER_BINDING) writeonly buffer GlobalLightRecords {
    GpuLight globalLightRecord[];
};

void main()
{
    uint count = globalLightCount();
    uint i = gl_GlobalInvocationID.x;
    if (i == 0u)
        globalLight[GLOBAL_LIGHT_CAPACITY] = count;
    if (i >= count)
        return;
    uint lightIndex = candidate[i];
    uint rank = 0u;
    for (uint j = 0u; j < count; ++j)
        rank += candidate[j] < lightIndex ? 1u : 0u;
    globalLight[rank] = lightIndex;
    globalLightRecord[rank] = lights[lightIndex];
}
