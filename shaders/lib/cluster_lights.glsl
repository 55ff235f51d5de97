// The lights of one cluster of the current batch (lib/clusters.glsl), shaded at a surface:
// the cluster's bit mask walked word by word (only the words its summary marks as not
// empty) and each word bit by bit, in light index order, the order forward adds them in.
// Shared by the clustered technique (shaders/clustered.frag) and the transparency pass
// (shaders/transparent.frag). Loop iterations: at most 9 summary words, 256 + 1 per
// mask-word walk and one per light of the batch plus one per word: about 8,700, under the
// bound of render/LightBatches.h. Needs lib/lighting.glsl and lib/clusters.glsl first.
vec3 shadeClusterLights(uint cluster, Surface s, vec3 V, inout uint evaluated)
{
    vec3 color = vec3(0.0);
    uint words = clusterMaskWords();
    uint summaryWords = clusterSummaryWords();
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
    return color;
}
