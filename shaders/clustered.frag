#version 450 core
// clustered: each covered pixel shades the global terms and the lights of its cluster in
// the current light batch, walking the cluster's bit mask word by word (only the words its
// summary marks as not empty) and each word bit by bit, in light index order. Loop
// iterations: at most 9 summary words, 256 + 1 per mask-word walk and one per light of the
// batch plus one per word: about 8,700, under the bound of render/LightBatches.h.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    uint tile = clusterTileOfPixel(uvec2(gl_FragCoord.xy));
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
    uint words = clusterMaskWords();
    uint summaryWords = clusterSummaryWords();
    uint evaluated = 0u;
    for (uint g = 0u; g < summaryWords; ++g) {
        uint nonEmpty = clusterMaskSummaries[cluster * summaryWords + g];
        while (nonEmpty != 0u) {
            uint word = g * 32u + uint(findLSB(nonEmpty));
            nonEmpty &= nonEmpty - 1u;
            uint bits = clusterLightMasks[cluster * words + word];
            while (bits != 0u) {
                uint bit = uint(findLSB(bits));
                bits &= bits - 1u;
                color += shadeLocal(lightBatch.x + word * 32u + bit, s, V);
                ++evaluated;
            }
        }
    }
    recordLightEvaluations(evaluated);
    outColor = vec4(color, 1.0);
}
