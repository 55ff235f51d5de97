#version 450 core
// tiled-quads: the local lights of this pixel's tile (a run of at most a light batch of
// them per quad), added by blending onto the global terms. Compiled once per light-count
// bucket with MAX_TILE_LIGHTS set to the bucket's bound.
#include "lib/bindings.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;

// Every tile's light indices, one list after another (render/culling/TileCulling.h).
layout(std430, binding = TILE_LIGHTS_BUFFER_BINDING) readonly buffer TileLights {
    uint tileLights[];
};

layout(location = 0) flat in uvec2 lightRange;  // offset, count
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    uint first = lightRange.x;
    uint count = lightRange.y;
    vec3 color = vec3(0.0);
    // A constant trip limit; the CPU puts only quads with count ≤ MAX_TILE_LIGHTS here.
    for (uint i = 0u; i < MAX_TILE_LIGHTS; ++i) {
        if (i == count)
            break;
        color += shadeLocal(tileLights[first + i], s, V);
    }
    recordLightEvaluations(count);
    outColor = vec4(color, 0.0);
}
