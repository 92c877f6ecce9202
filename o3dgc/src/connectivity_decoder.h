// Connectivity decoder: the mirror of connectivity_encoder.h.
#ifndef O3DGC_SRC_CONNECTIVITY_DECODER_H_
#define O3DGC_SRC_CONNECTIVITY_DECODER_H_

#include <cstdint>
#include <vector>

#include "arithmetic_coder.h"
#include "o3dgc/o3dgc.h"

namespace o3dgc {

// Decodes exactly `num_triangles` triangles using at most `max_vertices` vertices. On success
// `triangles` holds 3 * num_triangles ids < *num_vertices, every vertex referenced, and
// `opposite` and `opposite_vertices` (if not null) the neighbours found by the traversal (see
// Front::TakeOpposite and TakeOppositeVertices). `vertex_triangles` (if not null) receives the
// number of triangles at each vertex when the traversal knows it (every triangle attached to the
// front: no repeated or degenerate ones), else stays empty. `minor`: the stream's format minor
// version (0 or 1: see EncodeConnectivity).
Status DecodeConnectivity(ArithmeticDecoder* dec, size_t num_triangles, size_t max_vertices,
                          std::vector<uint32_t>* triangles, uint32_t* num_vertices,
                          std::vector<uint32_t>* opposite, std::vector<uint32_t>* opposite_vertices,
                          std::vector<uint32_t>* vertex_triangles, uint32_t minor);

}  // namespace o3dgc

#endif  // O3DGC_SRC_CONNECTIVITY_DECODER_H_
