// The one place where a scene mesh meets the o3dgc codec: which attribute goes into the stream
// under which semantic and id, how many bits each gets, and how a decoded stream becomes a mesh
// again.
//
// Stream attribute ids (what HULLPACK_mesh_compression's `attributes` and `targets` maps point at,
// see docs/packed-gltf.md): positions 0, normals next when present, then the float attributes
// (UV sets, colours, weights, tangents, then per morph target its position and normal offsets) in
// that order, then the int attributes (joints).
#ifndef HULLPACK_TOOLS_PIPELINE_MESH_CODEC_H_
#define HULLPACK_TOOLS_PIPELINE_MESH_CODEC_H_

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/status.h"
#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_format.h"
#include "scene/scene.h"

namespace hullpack {

struct MeshCodecSettings {
  o3dgc::StreamType stream_type = o3dgc::StreamType::kBinary;
  bool keep_order = false;  // true: decoded vertex and triangle order equal the input's
  // o3dgc::EncodeParams::keep_degenerate_triangles (keep_order keeps them too).
  bool keep_degenerate_triangles = false;
  bool fast_decode = false;      // o3dgc::EncodeParams::fast_decode
  bool max_compression = false;  // o3dgc::EncodeParams::max_compression
  int position_bits = 14;
  // How the position quantization cube is sized: kUniform (largest extent) or kDiagonal (the
  // bounding-box diagonal: coarser cells at the same bits, for budgets that kUniform overshoots).
  o3dgc::RangeMode position_range = o3dgc::RangeMode::kUniform;
  // Optional: quantize positions in this box (min x, y, z, max x, y, z) instead of the mesh's own
  // (o3dgc::EncodeParams::position_box): parts of one mesh coded on one grid.
  std::optional<std::array<float, 6>> position_box;
  int normal_bits = 10;
  int uv_bits = 12;
  // How the UV quantization square is sized. kUniform: one range for u and v, as Draco and glTF
  // quantize them (see MakeCodecInput); EncodeMesh and EncodeWithinError also try kPerAxis where
  // it gives another stream (u and v extents differ) and keep the smaller: its cells are no larger.
  o3dgc::RangeMode uv_range = o3dgc::RangeMode::kUniform;
  int color_bits = 10;
  int weight_bits = 10;
  int tangent_bits = 10;
  // The largest distance a decoded morph-target position offset may lie from the source's; 0: the
  // half cell diagonal of a position grid of position_bits over the mesh's largest extent. Normal
  // offsets get normal_bits.
  double morph_error = 0;
  // Encoding progress (a fraction; false cancels: kCancelled); may be empty.
  o3dgc::ProgressFn progress;
};

// `mesh` as the codec takes it: views of its arrays (which must outlive this), the parameters
// from the settings, and the stream attribute ids.
struct CodecInput {
  o3dgc::MeshView view;
  o3dgc::EncodeParams params;
  EncodedMesh attributes;       // gltf_attributes only
  std::vector<int32_t> joints;  // the joints widened for the codec (the view points here)
  // Without keep_order: the mesh with the vertices the codec stores alike welded
  // (WeldNormalsStoredAlike), when any are; the view points here then.
  std::optional<Mesh> welded;
};
Status MakeCodecInput(const Mesh& mesh, const std::vector<uint32_t>& groups,
                      const MeshCodecSettings& settings, CodecInput* in);

// True when some UV set of `mesh` has u and v extents that differ, so that kUniform and kPerAxis
// UV ranges give different streams.
bool UvExtentsDiffer(const Mesh& mesh);

// An encoder status as a Status naming the mesh.
Status EncoderStatus(o3dgc::Status status, const std::string& mesh_name);

// Encodes every attribute of `mesh`. `groups` (one per triangle, or empty) are stored as the
// stream's triangle groups; DecodeMesh returns them.
Result<EncodedMesh> EncodeMesh(const Mesh& mesh, const std::vector<uint32_t>& groups,
                               const MeshCodecSettings& settings);

// Decodes a stream into a mesh (name, material ids left empty) and its triangle groups. Skin
// weights are normalized, the packed format's decode rule (DecodePackedStream). Streams of
// the original Open3DGC tool (StreamFormat::kOpen3dgc2013) carry OBJ-convention texture
// coordinates: their v is flipped into the scene model's (glTF) convention. Safe on untrusted
// bytes; `name` prefixes error messages. `info` (may be null) gets the part sizes.
// `targets` (may be null): which stream attributes hold each morph target's offsets
// (EncodedMesh::gltf_targets); a stream alone does not say.
Result<Mesh> DecodeMesh(
    const uint8_t* data, size_t size, std::vector<uint32_t>* groups, const std::string& name,
    o3dgc::StreamInfo* info = nullptr,
    const std::vector<std::vector<std::pair<std::string, int>>>* targets = nullptr);

// The triangles whose group is `group`, with the vertices they use renumbered in increasing order
// of their index in `mesh` (the HULLPACK_mesh_compression `group` rule).
Mesh ExtractGroup(const Mesh& mesh, const std::vector<uint32_t>& groups, uint32_t group);

// Position bits that keep every decoded position within `max_error` (Euclidean) of the original,
// for uniform quantization of a cube of side `range`. Clamped to 1..30.
int PositionBitsForMaxError(double range, double max_error);

// Per-axis extent of the positions (zero for an empty mesh).
std::array<double, 3> PositionExtent(const Mesh& mesh);

// Largest extent of the mesh's positions (the side of its quantization cube) and bbox diagonal.
double PositionRange(const Mesh& mesh);
double BoundingBoxDiagonal(const Mesh& mesh);

// Symmetric vertex-set distance: the largest distance from a vertex of one mesh to the nearest
// vertex of the other. After quantization this is the position error, whatever order the codec
// chose for the vertices.
double MaxVertexDistance(const Mesh& a, const Mesh& b);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_MESH_CODEC_H_
