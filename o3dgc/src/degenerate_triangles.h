// The encoder's first stage in its default mode: the input without its degenerate triangles (two
// corners at one position, so no area) and without the vertices that only they use. Such
// triangles would each be coded with explicit references and their own vertices as isolated
// ones; Draco's encoder leaves them out too. Vertices the input itself leaves unreferenced stay.
#ifndef O3DGC_SRC_DEGENERATE_TRIANGLES_H_
#define O3DGC_SRC_DEGENERATE_TRIANGLES_H_

#include <cstdint>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace o3dgc {

// The arrays `view` points into, where they differ from the input's.
struct KeptMesh {
  MeshView view;
  std::vector<uint32_t> indices, groups;
  std::vector<float> positions, normals;  // dense; empty when no vertex is left out
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<int32_t>> ints;
};

// Fills `*out` and returns true when `mesh` has a degenerate triangle; else returns false and
// leaves `*out` alone. Positions compare as floats (-0 equals 0). Precondition: every index is
// below mesh.num_vertices. Triangles and vertices keep their relative order; with no triangle
// left, the view's index and group pointers are the input's (never read, and a group pointer
// still tells that the mesh has groups).
bool LeaveOutDegenerateTriangles(const MeshView& mesh, KeptMesh* out);

}  // namespace o3dgc

#endif  // O3DGC_SRC_DEGENERATE_TRIANGLES_H_
