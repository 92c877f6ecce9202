// Connectivity encoder: codes a triangle list (any topology) by region growing over gates.
//
// Per gate a->b the coder says whether a triangle is attached across it and, if so, where its third
// vertex comes from: a new vertex, the end of the gate leaving b ("right"), the start of the gate
// entering a ("left"), or any earlier vertex (a walk along the front from format 1.1 on, else an
// explicit back reference). Inconsistently oriented
// triangles carry a flip bit, repeated triangles (same vertex set) a copy count and orientation,
// degenerate triangles (a repeated vertex) are coded at the end with explicit references, and
// disconnected parts start with a seed triangle. Vertices are numbered in order of appearance.
#ifndef O3DGC_SRC_CONNECTIVITY_ENCODER_H_
#define O3DGC_SRC_CONNECTIVITY_ENCODER_H_

#include <cstdint>
#include <vector>

#include "arithmetic_coder.h"
#include "decision_log.h"

namespace o3dgc {

struct ConnectivityEncoding {
  std::vector<uint32_t> triangles;   // 3 per triangle, decoded order, new vertex ids
  std::vector<uint32_t> source;      // input triangle of each decoded triangle
  std::vector<uint32_t> old_of_new;  // input vertex of each new vertex id
  std::vector<uint32_t> opposite;    // neighbours found by the traversal (see Front::TakeOpposite)
  std::vector<uint32_t> opposite_vertices;  // their opposite vertices (Front::TakeOppositeVertices)
  // Triangles at each new vertex when every triangle went through the front (no repeated or
  // degenerate ones), else empty (see DecodeConnectivity).
  std::vector<uint32_t> vertex_triangles;
  // One past each part's last new vertex id, when no triangle joins two parts (see
  // DecodeConnectivity's component_ends), else empty.
  std::vector<uint32_t> component_ends;
};

// `triangles`: 3 * num_triangles vertex ids < num_vertices, every vertex referenced at least once.
// Without `keep_edges`, out->opposite stays empty (only parallelogram-coded attributes besides
// positions need it). `minor`: the format minor version to write (0: format 1.0's gate contexts
// and back references; 1: format 1.1's).
void EncodeConnectivity(const std::vector<uint32_t>& triangles, uint32_t num_vertices,
                        ArithmeticEncoder* enc, ConnectivityEncoding* out, bool keep_edges,
                        uint32_t minor);
// The same decisions recorded into `log` (see decision_log.h), to be replayed into an encoder;
// the triangles as 3 * num_triangles ids.
void EncodeConnectivity(const uint32_t* triangles, size_t num_triangles, uint32_t num_vertices,
                        DecisionLog* log, ConnectivityEncoding* out, bool keep_edges,
                        uint32_t minor);

}  // namespace o3dgc

#endif  // O3DGC_SRC_CONNECTIVITY_ENCODER_H_
