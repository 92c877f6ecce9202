// Reading a MeshView into a clean indexed mesh: validation, welding of bit-identical positions,
// degenerate and duplicate triangles dropped. Shared by every decomposer and the simplifier.
#ifndef VHACD_SRC_INPUT_MESH_H_
#define VHACD_SRC_INPUT_MESH_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "context.h"
#include "convex_hull.h"
#include "vhacd/vhacd.h"

namespace vhacd {
namespace internal {

struct InputMesh {
  std::vector<Vec3> points;                        // welded, referenced only
  std::vector<std::array<uint32_t, 3>> triangles;  // no degenerate, no duplicate
  std::vector<uint32_t> point_source;              // an input point index of each welded point
  std::vector<uint32_t> triangle_source;           // the input triangle index of each triangle
  bool closed = false;
};

// Validates `m` and fills *out; on failure returns the status and names the problem in *why.
// Without `keep_sources`, point_source and triangle_source stay empty (for callers that do not
// map back to the input).
Status ReadMesh(const MeshView& m, Context* ctx, InputMesh* out, std::string* why,
                bool keep_sources = true);

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_INPUT_MESH_H_
