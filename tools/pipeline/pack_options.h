// What `hullpack pack` can be asked for, what it reports, and how it shows progress: shared by
// every stage of the pipeline (pack.h).
#ifndef HULLPACK_TOOLS_PIPELINE_PACK_OPTIONS_H_
#define HULLPACK_TOOLS_PIPELINE_PACK_OPTIONS_H_

#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_writer.h"
#include "pipeline/check_and_repair.h"
#include "pipeline/collision.h"
#include "pipeline/prune.h"
#include "scene/scene.h"

namespace hullpack {

// PackOptions::part_triangles by default.
constexpr size_t kDefaultPartTriangles = 600000;

struct PackOptions {
  // Largest position error allowed, as a fraction of each mesh's bounding-box diagonal; it sets the
  // position bits unless position_bits is given.
  double max_error = 0.0005;
  // The same for collision-hull vertices. Hulls already stand off the surface by up to their
  // concavity (the preset's max_concavity, 0.08 of the diagonal), so they need far fewer bits than
  // the render mesh.
  double hull_error = 0.002;
  int position_bits = 0;  // 0 = from max_error
  int normal_bits = 10;
  int uv_bits = 12;
  o3dgc::StreamType stream_type = o3dgc::StreamType::kBinary;
  bool keep_order = false;
  bool fast_decode = false;  // o3dgc::EncodeParams::fast_decode, for render meshes and hulls
  // o3dgc::EncodeParams::max_compression (excludes fast_decode): smaller large meshes, slower
  // decoding.
  bool max_compression = false;
  // A render mesh of more triangles (without skin or morph targets) is coded in spatially compact
  // parts of at most this many, each a stream and a glTF mesh of its own on the mesh's node, all
  // on the mesh's quantization grid: the encoder's memory follows a part, not the mesh. 0: never.
  size_t part_triangles = kDefaultPartTriangles;
  PackedGlbOptions glb;
  CollisionSettings collision;
  CheckRepairOptions repair;
  PruneOptions prune;
  // Threads for every stage (0 = every core). The output bytes do not depend on it.
  int threads = 0;
};

struct MeshPackReport {
  std::string name;
  size_t triangles = 0, vertices = 0;
  size_t bytes_before = 0;     // the mesh's vertex and index data as plain glTF accessors
  size_t bytes_after = 0;      // its compressed streams
  size_t parts = 1;            // streams (more than one: split, PackOptions::part_triangles)
  double bits_per_vertex = 0;  // bytes_after * 8 / vertices
  int position_bits = 0;
  std::string position_range;     // the quantization grid: "uniform", "per-axis" or "diagonal"
  double max_error = 0;           // largest position error reached, in model units
  double max_error_fraction = 0;  // ... as a fraction of the bounding-box diagonal
  std::string no_hulls_reason;    // why the mesh has no hulls, "" when it has some
  size_t hull_count = 0;
  size_t hull_vertices = 0;
  size_t hull_bytes = 0;  // the hulls' accessor data (their points as stored: floats or integers)
  int hull_position_bits = 0;
  std::string hull_position_range;
  double hull_concavity = -1;  // vhacd's report (fractions of the diagonal); -1 = not measured
  double hull_iou = -1;
  // Whether the decomposition reached its --max-concavity or --hulls target, and if not, why.
  bool hull_target_reached = true;
  std::string hull_target_note;
  double hull_quantization_error = 0;  // hull vertex error after quantization, fraction of diagonal
  // encode: the render stream's candidate grids (encoded in parallel); decode: the chosen streams
  // once, in the assemble stage; hull_encode: quantizing, welding and encoding the hulls. The
  // render stream and the hulls are made at the same time, so these add up to more than the mesh's
  // share of the wall time.
  double seconds_encode = 0, seconds_decode = 0, seconds_decompose = 0, seconds_hull_encode = 0;
};

struct PackReport {
  std::vector<MeshPackReport> meshes;
  // What the repair and prune stages changed or removed, one line per kind.
  std::vector<std::string> left_out;
  std::vector<std::string> not_kept;             // what the reader could not keep (Scene::dropped)
  size_t images_embedded = 0;                    // external images put inside (PackInput)
  std::vector<std::string> images_kept_outside;  // ... and those that could not be (PackInput)
  std::vector<std::string> image_uris;           // every image URI the file referenced (PackInput)
  size_t output_bytes = 0;
  // Animation key frames as plain accessors, and as written (EXT_meshopt_compression or plain).
  size_t key_frame_bytes_before = 0, key_frame_bytes_after = 0;
  // Wall seconds of each stage, in pipeline order; they add up to seconds_total. load is
  // PackInput's (0 from PackScene), write the caller's who writes the file; assemble is the packed
  // GLB's making, the decoding of the render streams included.
  double seconds_load = 0, seconds_repair = 0, seconds_prune = 0, seconds_meshes = 0,
         seconds_assemble = 0, seconds_write = 0, seconds_total = 0;
};

// Progress and cancellation for a long pack. Calls may come from several threads, never two at
// once.
class PackObserver {
 public:
  virtual ~PackObserver() = default;
  // fraction in [0, 1] of the whole scene; stage says what runs ("mesh 3/7 'wheel': decompose
  // 40%").
  virtual void OnProgress(double fraction, const std::string& stage) {}
  virtual bool IsCancelled() { return false; }
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_PACK_OPTIONS_H_
