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
// version (0 or 1: see EncodeConnectivity). `compact_front`: the front's closed gates are
// dropped between steps (Front::MakeRoom; the same result in less memory, see
// kCompactFrontTriangles). `component_ends` (if not null) receives, for each part the front
// decoded in turn, one past its last vertex id, when no triangle uses vertices of two parts (then
// part k's vertices are the ids from the previous end up to its own); else it stays empty.
Status DecodeConnectivity(ArithmeticDecoder* dec, size_t num_triangles, size_t max_vertices,
                          std::vector<uint32_t>* triangles, uint32_t* num_vertices,
                          std::vector<uint32_t>* opposite, std::vector<uint32_t>* opposite_vertices,
                          std::vector<uint32_t>* vertex_triangles, uint32_t minor,
                          bool compact_front = false,
                          std::vector<uint32_t>* component_ends = nullptr);

// From this many triangles on the decoder compacts the front's gates: without, they take about
// 56 bytes per triangle (every gate ever opened is kept); with, about the front. On igea (268k
// triangles) compacting cost 7 % of the decode time; at 1.07M and 4.3M triangles decoding was
// 10 % and 2.5 % faster with it (the gates stay in cache).
constexpr size_t kCompactFrontTriangles = size_t(1) << 19;

}  // namespace o3dgc

#endif  // O3DGC_SRC_CONNECTIVITY_DECODER_H_
