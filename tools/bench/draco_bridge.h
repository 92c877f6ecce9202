// The benchmarks' way into Debian's libdraco: a scene mesh as a draco::Mesh (positions, normals,
// first UV set, colours, joints and weights as generic attributes; points deduplicated as
// draco_encoder does), encoding at given bits and level, and
// the decoded positions.
#ifndef HULLPACK_TOOLS_BENCH_DRACO_BRIDGE_H_
#define HULLPACK_TOOLS_BENCH_DRACO_BRIDGE_H_

#include <draco/mesh/mesh.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "scene/scene.h"

namespace hullpack {

std::unique_ptr<draco::Mesh> ToDracoMesh(const Mesh& mesh);

// Encodes with quantization bits (position, normal, UV) and compression level 0..10; empty on
// failure.
std::vector<uint8_t> DracoEncode(const draco::Mesh& mesh, int qp, int qn, int qt, int level);

// Decodes and returns the positions (one per draco point); empty on failure.
Mesh DracoDecodePositions(const std::vector<uint8_t>& bytes);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_DRACO_BRIDGE_H_
