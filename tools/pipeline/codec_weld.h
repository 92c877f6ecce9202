// Vertices the codec would store alike, welded before encoding.
#ifndef HULLPACK_TOOLS_PIPELINE_CODEC_WELD_H_
#define HULLPACK_TOOLS_PIPELINE_CODEC_WELD_H_

#include <optional>

#include "scene/scene.h"

namespace hullpack {

// `mesh` with the vertices welded whose every attribute but the normal is equal bit for bit and
// whose normals the codec stores alike at `normal_bits` (o3dgc::OctahedralNormalKey): each keeps
// the first such vertex, whose index every triangle takes; the others are dropped. What decodes
// is the same per corner; the stream codes fewer vertices and seams. Why: CAD exports give each
// face its own normal, computed per triangle, so the triangles of one flat face carry normals
// that differ in their last bits and split every vertex they share. nullopt when nothing welds
// (or `normal_bits` is above 16, or the mesh has no normals).
std::optional<Mesh> WeldNormalsStoredAlike(const Mesh& mesh, int normal_bits);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_CODEC_WELD_H_
