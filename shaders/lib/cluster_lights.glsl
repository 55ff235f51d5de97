// The lights of one cluster of the current batch (lib/clusters.glsl), shaded at a surface:
// the cluster's bit mask walked in light index order (the order forward adds them in), only
// the words its summary marks as not empty. Shared by the clustered technique
// (shaders/clustered.frag) and the transparency pass (shaders/transparent.frag).
//
// One loop iteration per light, fetching the next word where the last one ran out, rather
// than a loop over words around a loop over each word's bits: llvmpipe runs 8 pixels in lock
// step, and pixels of different clusters then iterate as long as the pixel with the most
// lights, where the nested loops ran, word after word, as long as the pixel with the most
// lights in that word. On the courtyard at 4096 lights (1280x720) the lighting pass went from
// 109-112 to 80-84 ms; where every pixel of a tile has the same mask (LearnOpenGL's scene,
// every light everywhere) the fetch that every iteration carries costs 566 -> 632 ms at 512
// lights (docs/performance.md). Choosing the nested loops where all lanes share the cluster
// (ARB_shader_ballot and _group_vote) kept the worse of both: llvmpipe runs both branches.
//
// Loop iterations: at most 8 summary words plus one, and per summary word one per light of
// the batch in it plus one: at most 8,192 + 17, under the bound of render/programs/LightBatches.h.
// Needs lib/lighting.glsl and lib/clusters.glsl first.
vec3 shadeClusterLights(uint cluster, Surface s, vec3 V, inout uint evaluated)
{
    vec3 color = vec3(0.0);
    uint words = lightBatchMaskWords();
    uint summaryWords = lightBatchSummaryWords();
    for (uint g = 0u; g < summaryWords; ++g) {
        uint nonEmpty = clusterMaskSummaries[cluster * summaryWords + g];
        uint bits = 0u;
        uint wordBase = 0u;
        while (bits != 0u || nonEmpty != 0u) {
            if (bits == 0u) {  // a word the summary marks, so not empty
                uint word = g * 32u + uint(findLSB(nonEmpty));
                nonEmpty &= nonEmpty - 1u;
                bits = clusterLightMasks[cluster * words + word];
                wordBase = word * 32u;
            }
            uint bit = uint(findLSB(bits));
            bits &= bits - 1u;
            color += shadeLocal(lightBatch.x + wordBase + bit, s, V);
            ++evaluated;
        }
    }
    return color;
}
