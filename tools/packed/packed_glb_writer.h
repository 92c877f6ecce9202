// Assembles the packed GLB (docs/packed-gltf.md): the plain glTF of the DECODED scene, each render
// primitive pointing at its compressed stream through HULLPACK_mesh_compression; collision hulls as
// plain accessors on a grid (floats, or bytes/shorts with KHR_mesh_quantization; no hullpack
// extension), referenced as
// OMI_physics_shape convex shapes by one collider child node per hull of the body node (or by
// KHR_physics_rigid_bodies colliders, the draft's geometry.node form).
// The mirror image is packed_glb_reader.h.
#ifndef HULLPACK_TOOLS_PACKED_PACKED_GLB_WRITER_H_
#define HULLPACK_TOOLS_PACKED_PACKED_GLB_WRITER_H_

#include <cstdint>
#include <vector>

#include "common/status.h"
#include "packed/packed_glb_format.h"
#include "packed/packed_glb_reader.h"
#include "scene/scene.h"

namespace hullpack {

enum class PhysicsForm { kOmi, kKhr };

// Where each mesh of the decoded scene comes from.
struct MeshSource {
  int stream = -1;       // index into PackedStreams::streams (-1: plain accessors)
  bool grouped = false;  // the stream has triangle groups: primitives select theirs
  bool hull = false;     // a collision hull: quantized plain accessors from hull_grid
  HullGrid hull_grid;
};

struct PackedStreams {
  std::vector<EncodedMesh> streams;
  std::vector<MeshSource> sources;         // one per decoded-scene mesh
  std::vector<std::vector<int>> hulls_of;  // per decoded-scene mesh: indices of its hull meshes
};

struct PackedGlbOptions {
  bool fallback = false;  // also keep the decoded data as plain accessors
  // Hull points as unsigned bytes/shorts with KHR_mesh_quantization (required then) instead of
  // FLOATs holding the same grid integers (no extension needed because of hulls): smaller, for
  // readers that have the extension (docs/packed-gltf.md). Ignored in fallback files.
  bool quantized_hulls = false;
  // Animation key frames with EXT_meshopt_compression (GlbWriteOptions::compress_animations).
  // Ignored in fallback files.
  bool compress_animations = true;
  PhysicsForm physics = PhysicsForm::kOmi;
};

// What WritePackedGlb stored besides the streams: the animation key frames' bytes as plain
// accessors and as written.
struct PackedGlbStats {
  size_t key_frame_bytes = 0;
  size_t key_frame_stored_bytes = 0;
};

// `decoded` holds the render meshes as their streams decode (vertex and triangle order, values,
// material ids = stream groups) followed by the hull meshes; no node shows a hull mesh. Taken by
// value: a caller that moves it in spares a copy of every mesh. `stats` may be null.
Result<std::vector<uint8_t>> WritePackedGlb(Scene decoded, const PackedStreams& streams,
                                            const PackedGlbOptions& options,
                                            PackedGlbStats* stats = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PACKED_PACKED_GLB_WRITER_H_
