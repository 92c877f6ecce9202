// The collision hulls of one mesh as a packed file stores them (docs/packed-gltf.md): plain glTF
// accessors that any physics importer reads, positions on a grid (stored as floats, or as
// bytes/shorts with KHR_mesh_quantization).
//
// All hulls of a mesh lie on one grid whose step is the largest that keeps every vertex within the
// hull budget (half a cell diagonal), except that a hull thinner than four steps gets a step of a
// quarter of its thickness, so that no hull comes out flat. Each hull is stored as small unsigned
// integers relative to its own lowest grid corner, so most hulls fit 8 bits per coordinate; its
// collider node's translation (that corner) and uniform scale (the step) dequantize it.
#ifndef HULLPACK_TOOLS_PIPELINE_HULL_QUANTIZE_H_
#define HULLPACK_TOOLS_PIPELINE_HULL_QUANTIZE_H_

#include <vector>

#include "common/status.h"
#include "packed/packed_glb_writer.h"
#include "scene/scene.h"

namespace hullpack {

struct QuantizedHulls {
  std::vector<HullGrid> grids;  // per hull: what the writer stores
  std::vector<Mesh> decoded;    // per hull: the positions an engine computes (DequantizeHull)
  double max_error = 0;         // largest hull vertex error reached, model units
  int position_bits = 0;        // bits of the widest hull coordinate range
};

// Quantizes `hulls` (closed meshes, positions and indices only) so that every vertex moves by at
// most `max_error` (model units, > 0). Hull names are not kept.
Result<QuantizedHulls> QuantizeHulls(const std::vector<Mesh>& hulls, double max_error);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_HULL_QUANTIZE_H_
