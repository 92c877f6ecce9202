// The collision hulls of one mesh as one compressed stream (docs/packed-gltf.md: one group per
// hull, read back with compactVertices).
//
// Neighbouring hulls of one decomposition meet on the faces vhacd cut along, and many of their
// corners coincide exactly (10-20 % of them on the corpus). Those corners are welded: one stream
// vertex used by several hulls' triangles, coded once; a decoder extracting one group still gets
// that hull's complete vertex set. The stream is then quantized to the hulls' own error budget
// (EncodeWithinError picks the grid).
#ifndef HULLPACK_TOOLS_PIPELINE_HULL_STREAM_H_
#define HULLPACK_TOOLS_PIPELINE_HULL_STREAM_H_

#include <vector>

#include "common/status.h"
#include "pipeline/mesh_codec.h"
#include "scene/scene.h"

namespace hullpack {

struct EncodedHulls {
  EncodedMesh encoded;        // one stream; triangle group h holds hull h
  std::vector<Mesh> decoded;  // hull h as a decoder extracts group h (ExtractGroup)
  int position_bits = 0;
  o3dgc::RangeMode position_range = o3dgc::RangeMode::kUniform;
  double max_error = 0;        // largest hull vertex error reached, model units
  size_t stream_vertices = 0;  // vertices the stream codes (after welding)
  bool welded = false;         // the welded stream was the smaller one
};

// Encodes `hulls` (closed meshes, positions and indices only) so that every hull vertex moves by
// at most `max_error` (model units, > 0). Hull names are not kept.
Result<EncodedHulls> EncodeHulls(const std::vector<Mesh>& hulls, const MeshCodecSettings& settings,
                                 double max_error);

// One mesh of all `hulls` where bitwise-equal positions of different hulls share one vertex (never
// two vertices of one hull), and `groups` gets the hull index of every triangle.
Mesh WeldAcrossHulls(const std::vector<Mesh>& hulls, std::vector<uint32_t>* groups);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_HULL_STREAM_H_
