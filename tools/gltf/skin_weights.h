// glTF requires a vertex's skin weights to sum to 1, and validators check the float32 sum to
// within 2e-7 per non-zero weight. Quantized weights (HULLPACK_mesh_compression streams code them
// with a few bits each) drift from that by up to half a step per weight, and some source files do
// not hold it either, so decoders of packed files normalize every decoded vertex's WEIGHTS_0 with
// NormalizeSkinWeights (docs/packed-gltf.md).
#ifndef HULLPACK_TOOLS_GLTF_SKIN_WEIGHTS_H_
#define HULLPACK_TOOLS_GLTF_SKIN_WEIGHTS_H_

#include <cstddef>

namespace hullpack {

// `weights`: 4 per vertex, non-negative. Each vertex whose weights have a positive sum gets them
// divided by that sum (in double), rounded to float, and its largest weight then set to 1 minus the
// others (in double, rounded to float) so the float sum is 1 to within float rounding. Vertices
// whose weights are all zero are left alone. Returns how many vertices' sums were off by more than
// 1e-6.
size_t NormalizeSkinWeights(float* weights, size_t vertex_count);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_SKIN_WEIGHTS_H_
