// o3dgc: in-memory triangle mesh compression (connectivity + quantized, predicted attributes,
// adaptive binary arithmetic coding). Standard library only.
//
// Typical use:
//   o3dgc::MeshView mesh;               // plain pointers into the caller's arrays
//   mesh.positions = xyz; mesh.num_vertices = n; mesh.indices = idx; mesh.num_triangles = t;
//   std::vector<uint8_t> stream;
//   o3dgc::Status s = o3dgc::Encode(mesh, o3dgc::EncodeParams(), &stream);
//   o3dgc::DecodedMesh out;
//   s = o3dgc::Decode(stream.data(), stream.size(), o3dgc::DecodeOptions(), &out);
//
// How it codes (details in src/*.h):
//  - unless asked to keep them, degenerate triangles (two corners at one position) are left out
//    first, with the vertices only they use (EncodeParams::keep_degenerate_triangles);
//  - positions are welded (bitwise-equal positions of referenced vertices share one "position
//    vertex"); connectivity is coded over position vertices by region growing over gates (a
//    cut-border traversal: per gate "boundary / new vertex / right / left / back reference",
//    flip bits for inconsistent winding, copy counts for repeated triangles, explicit references
//    for degenerate triangles and new parts), so open, non-manifold, non-oriented and
//    multi-component meshes and isolated vertices all code losslessly;
//  - seams: per position vertex its number of attribute vertices and, per corner, which one;
//  - attributes are quantized, predicted (parallelogram mode: multi-parallelogram in
//    max-prediction-degree order, where a vertex may select a single parallelogram when the
//    combination spans a crease, as on CAD parts; texture coordinates (Semantic::kTexCoord, 2
//    components) are predicted from the 3D shape instead; surface-normal mode: octahedral
//    coordinates against the normal of the decoded surface) and the residuals are coded with
//    context-adaptive binary arithmetic coding (from 4096 vertices on, a residual's sign and low
//    bits are read raw: 13-20 % faster decoding for 0-3 % more bytes on large meshes);
//  - stream: "O3DG", format version (major, minor), flags, CRC32, payload length, one
//    arithmetic-coded payload. The ASCII form ("O3DA") is the same stream repacked 7 bits per
//    byte. The format is specified in docs/o3dgc-stream-format.md.
//
// Format versions: Encode writes the lowest version that has the stream's features (1.3 with
// EncodeParams::max_compression; 1.2 when it models residuals' low bits, which pays on models built
// on a design grid; else 1.1, which older decoders read), at most kFormatMajor.kFormatMinor. Decode
// reads every stream of major version 1 up to its own minor version (a later feature is a new minor
// version or a new flag, never a change of what an existing version means); a stream of another
// major version, or of a later minor version than the decoder's, is kBadVersion.
//
// Trust model: Encode trusts nothing it cannot check cheaply but expects the pointers of a
// MeshView to be valid for the sizes stated below (it is not hardened against hostile callers).
// Decode is safe on untrusted input: it validates every count, size and value, bounds its
// allocations by what the stream can hold (a valid stream pays at least one byte per 64
// vertices/triangles/components, so a short stream claiming 2^32 vertices is rejected before
// anything is allocated), returns a Status for any malformed or truncated stream, always
// terminates, and never reads outside [data, data + size).
// Neither function ever produces NaN or infinite values.
#ifndef O3DGC_O3DGC_H_
#define O3DGC_O3DGC_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace o3dgc {

// The newest stream format version, which Encode writes when a stream needs it (see "Format
// versions" above) and Decode reads.
constexpr uint32_t kFormatMajor = 1;
constexpr uint32_t kFormatMinor = 3;

// "1.3": the newest stream format version this library writes and reads, for --version output.
const char* FormatVersionString();

enum class Status : uint8_t {
  kOk = 0,
  kInvalidArgument,  // Encode: bad MeshView/EncodeParams (null pointer, index out of range, NaN...)
  kUnsupported,      // a feature/option this version cannot encode or decode
  kBadMagic,         // Decode: not an o3dgc stream
  kBadVersion,       // Decode: stream of another major version or of a later minor version
  kTruncated,        // Decode: the stream ends before its declared content
  kCorrupt,          // Decode: inconsistent content (bad count, value out of range, ...)
  kChecksumMismatch,  // Decode: CRC32 of the stream does not match
  kLimitExceeded,     // Decode: declared sizes exceed DecodeOptions limits or what the stream holds
  kCancelled,         // the progress callback asked to stop
};

// Stable name of a status ("ok", "corrupt", ...); never null.
const char* StatusName(Status status);

enum class StreamType : uint8_t {
  kBinary = 0,  // arithmetic-coded bytes
  kAscii = 1,   // the same content as 7-bit bytes (every byte < 128), meant to be served gzip'd
};

enum class Prediction : uint8_t {
  kNone = 0,           // values coded as they are
  kDifferential = 1,   // residual against the previous vertex in coding order
  kParallelogram = 2,  // multi-parallelogram over the mesh, falling back to neighbour averages;
                       // 2-component kTexCoord attributes are predicted from the 3D shape
  kSurfaceNormal = 3,  // normals only: predicted from the decoded surface; output is unit length
  kDefault = 255,      // per-semantic default (see Semantic)
};

// What an attribute means. Defaults: kPosition parallelogram; kNormal surface-normal;
// kTexCoord parallelogram; kColor differential; kWeight parallelogram; kGeneric parallelogram;
// int attributes (kJointId, kGeneric) unquantized, differential.
enum class Semantic : uint8_t {
  kGeneric = 0,
  kPosition = 1,  // internal use; positions are given in MeshView::positions
  kNormal = 2,
  kTexCoord = 3,
  kColor = 4,
  kWeight = 5,
  kJointId = 6,
};

// How the quantization range of a float attribute is chosen.
enum class RangeMode : uint8_t {
  kUniform = 0,   // one range for all components (largest extent): cubic cells
  kPerAxis = 1,   // one range per component
  kDiagonal = 2,  // one range for all components: the length of the bounding-box diagonal
};

// A per-vertex float attribute: `dimension` floats per vertex, vertex i at
// (const char*)data + i * stride (stride 0 means dimension * sizeof(float)).
struct FloatAttributeView {
  const float* data = nullptr;
  size_t stride = 0;
  uint32_t dimension = 2;  // 1..4
  Semantic semantic = Semantic::kGeneric;
  int bits = 12;  // quantization bits per component, 1..30
  Prediction prediction = Prediction::kDefault;
  RangeMode range = RangeMode::kPerAxis;
};

// A per-vertex int attribute (joint ids, generic); coded exactly.
struct IntAttributeView {
  const int32_t* data = nullptr;
  size_t stride = 0;       // 0 means dimension * sizeof(int32_t)
  uint32_t dimension = 4;  // 1..4
  Semantic semantic = Semantic::kJointId;
  Prediction prediction = Prediction::kDefault;  // kNone or kDifferential (default)
};

// The mesh to encode. Every pointer must be valid for the sizes given:
//  positions: num_vertices vertices of 3 floats, vertex i at (const char*)positions + i*stride;
//  indices: 3 * num_triangles values, each < num_vertices (may be null when num_triangles == 0);
//  normals: optional (null = none), 3 floats per vertex;
//  triangle_groups: optional (null = none), one id per triangle (e.g. an OBJ usemtl group).
// Triangles may be degenerate, duplicated, inconsistently oriented or non-manifold; vertices may
// be unreferenced. Every triangle is coded but, by default, degenerate ones
// (EncodeParams::keep_degenerate_triangles).
struct MeshView {
  const float* positions = nullptr;
  size_t position_stride = 0;
  size_t num_vertices = 0;
  const uint32_t* indices = nullptr;
  size_t num_triangles = 0;
  const float* normals = nullptr;
  size_t normal_stride = 0;
  std::vector<FloatAttributeView> float_attributes;
  std::vector<IntAttributeView> int_attributes;
  const uint32_t* triangle_groups = nullptr;
};

// Progress hook: called with a fraction in [0,1]; return false to cancel (Status::kCancelled).
using ProgressFn = std::function<bool(float)>;

struct EncodeParams {
  StreamType stream_type = StreamType::kBinary;
  // false (default): vertices and triangles may be reordered (and triangle corners rotated, with
  // winding kept) for size. true: the decoded vertex order, triangle order and corner order are
  // exactly those of the input.
  bool keep_order = false;
  // false (default): degenerate triangles (two corners at equal positions: no area) are left
  // out, with the vertices only they use, as Draco's encoder does; on welded CAD exports they can
  // be a few % of the stream. Vertices the input leaves unreferenced are kept.
  // true, or keep_order: every input triangle and vertex is coded.
  bool keep_degenerate_triangles = false;
  // true: values predicted by parallelograms are coded in vertex id order instead of the order that
  // finds the most parallelograms: a few % more bytes, faster decoding, because the decoder reads
  // and writes the vertices in memory order instead of jumping over the mesh
  // (docs/decode-speed.md has the figures).
  bool fast_decode = false;
  // With fast_decode false: on meshes of 4096 position vertices or more the encoder codes the
  // positions in both orders and takes the vertex id order (the stream's fast_decode flag) when
  // it costs at most 2.5 % more bytes for the positions. Noisy scans lose 0.3-2.4 % and decode in
  // about 0.7x the time; CAD parts and most smooth meshes keep the default order. Encoding the
  // positions three times takes longer.
  bool auto_fast_decode = true;
  // true: the smallest stream this coder makes, for slower decoding (format 1.3): residuals code
  // their sign and low bits adaptively in sections of every size (not raw from 4096 vertices on),
  // and parallelogram-predicted values keep the order with the most parallelograms
  // (auto_fast_decode is not applied; fast_decode must be false). Large scans come out 2-5 %
  // smaller and decode in about 1.2-1.5x the time (docs/benchmarks.md).
  bool max_compression = false;
  int position_bits = 14;  // 1..30
  Prediction position_prediction = Prediction::kParallelogram;
  RangeMode position_range = RangeMode::kUniform;
  // Optional: the box (min x, y, z, then max x, y, z) whose grid the positions are quantized on,
  // instead of their own bounding box; every position must lie inside it (else kInvalidArgument).
  // Parts of one mesh coded as separate streams in the whole mesh's box decode the vertices they
  // share to the same positions, so no crack opens between them.
  std::optional<std::array<float, 6>> position_box;
  int normal_bits = 10;  // 1..30
  Prediction normal_prediction = Prediction::kSurfaceNormal;
  ProgressFn progress;  // optional
};

struct DecodeOptions {
  bool verify_checksum = true;
  size_t max_vertices = size_t(1) << 28;
  size_t max_triangles = size_t(1) << 28;
  ProgressFn progress;  // optional
};

struct DecodedFloatAttribute {
  Semantic semantic = Semantic::kGeneric;
  uint32_t dimension = 0;
  std::vector<float> values;  // dimension per vertex
};

struct DecodedIntAttribute {
  Semantic semantic = Semantic::kGeneric;
  uint32_t dimension = 0;
  std::vector<int32_t> values;  // dimension per vertex
};

struct DecodedMesh {
  std::vector<float> positions;                         // 3 per vertex
  std::vector<uint32_t> indices;                        // 3 per triangle
  std::vector<float> normals;                           // 3 per vertex or empty
  std::vector<DecodedFloatAttribute> float_attributes;  // in MeshView order
  std::vector<DecodedIntAttribute> int_attributes;      // in MeshView order
  std::vector<uint32_t> triangle_groups;                // 1 per triangle or empty
  size_t num_vertices() const { return positions.size() / 3; }
  size_t num_triangles() const { return indices.size() / 3; }
};

// Which encoder wrote a stream. Decode reads both; Encode writes only kNative.
enum class StreamFormat : uint8_t {
  kNative = 0,        // this library ("O3DG" / "O3DA")
  kOpen3dgc2013 = 1,  // the original Open3DGC SC3DMC encoder (amd/rest3d, 2013), binary or ASCII
};

// Byte sizes of the parts of a stream (binary form; for an ASCII stream `total` is the ASCII size).
// For kOpen3dgc2013 streams the sizes are those of the stream as it is (either form), the version
// is 0.0 and keep_order false.
struct StreamInfo {
  StreamFormat format = StreamFormat::kNative;
  StreamType stream_type = StreamType::kBinary;
  uint32_t version_major = 0;  // format version of the stream (kNative)
  uint32_t version_minor = 0;
  bool keep_order = false;
  bool fast_decode =
      false;              // values in vertex id order (EncodeParams::fast_decode, auto_fast_decode)
  bool low_bits = false;  // format 1.2: modelled low bits (grid-built meshes; chosen by Encode)
  bool all_adaptive = false;  // format 1.3: adaptive low bits in large sections (max_compression)
  size_t num_vertices = 0;
  size_t num_triangles = 0;
  size_t total = 0;
  size_t header = 0;        // magic, version, counts, quantization parameters, checksum
  size_t connectivity = 0;  // triangles, seams, duplicates (and order tables in keep_order mode)
  size_t positions = 0;
  size_t normals = 0;
  std::vector<size_t> float_attributes;
  std::vector<size_t> int_attributes;
  size_t groups = 0;
};

// Encodes `mesh`. On success `*out` holds the stream (replacing its content) and, if `info` is not
// null, the per-part sizes. Returns kInvalidArgument for null pointers with non-zero counts,
// indices
// >= num_vertices, bits outside 1..30, dimensions outside 1..4, non-finite values, or counts above
// 2^28.
Status Encode(const MeshView& mesh, const EncodeParams& params, std::vector<uint8_t>* out,
              StreamInfo* info = nullptr);

// Encodes one mesh on several position grids (bits and RangeMode) for about the cost of one: the
// stages that do not depend on the grid (checks, welding, connectivity, seams, order tables, the
// positions' prediction wedges) run once in Prepare and are shared; each Encode codes the header,
// positions and attributes of one grid. For callers that choose a grid by the stream's size (an
// error budget met by several grids).
//
//   o3dgc::GridEncoder grids;
//   if (grids.Prepare(mesh, params) == o3dgc::Status::kOk)
//     grids.Encode(12, o3dgc::RangeMode::kPerAxis, &stream);  // one call per grid, any thread
class GridEncoder {
 public:
  GridEncoder();
  ~GridEncoder();
  GridEncoder(const GridEncoder&) = delete;
  GridEncoder& operator=(const GridEncoder&) = delete;

  // Checks `mesh` and runs the shared stages. params.position_bits and position_range are not
  // used (each Encode gives its own); params.progress sees 0 to 0.4. The arrays `mesh` points at
  // must stay valid and unchanged until the last Encode. Returns what Encode would for a mesh it
  // rejects.
  Status Prepare(const MeshView& mesh, const EncodeParams& params);
  // The stream that o3dgc::Encode(mesh, params with these position_bits and position_range) gives,
  // byte for byte, and its part sizes. Several threads may call it at once. `progress` (may be
  // empty) sees 0.6 to 1. kInvalidArgument before a successful Prepare or for bits outside 1..30.
  Status Encode(int position_bits, RangeMode position_range, std::vector<uint8_t>* out,
                StreamInfo* info = nullptr, const ProgressFn& progress = ProgressFn()) const;

  struct Prepared;  // (src/encoder.cc)

 private:
  std::unique_ptr<Prepared> prepared_;
};

// Decodes `size` bytes at `data` (binary or ASCII stream, detected from the magic). Streams written
// by the original Open3DGC encoder (2013; binary or ASCII, recognised by their start code) are
// decoded too: values as stored, triangles in the encoder's input order when the stream keeps it
// (see src/legacy_decoder.h); verify_checksum does not apply to them (they have none), and as they
// are not padded the allocation guard allows them 256 elements per byte instead of 64. A build
// that defines O3DGC_NO_LEGACY_DECODER (the default WebAssembly decoder) returns kUnsupported for
// them, from ReadStreamInfo too. Safe on untrusted input. On success `*out` is replaced by the
// mesh; on failure its content is unspecified.
Status Decode(const uint8_t* data, size_t size, const DecodeOptions& options, DecodedMesh* out,
              StreamInfo* info = nullptr);

// The largest Euclidean distance (computed in double) between one of `num_vertices` positions
// (3 floats at positions + i * stride bytes) and the position Decode returns for it, when Encode
// quantizes them with `bits` bits and `range`: a stream's position error, known without coding.
// Returns -1 for bits outside 1..30, a null pointer with vertices, or values Encode rejects.
double PositionQuantizationError(const float* positions, size_t stride, size_t num_vertices,
                                 int bits, RangeMode range);

// Normals that Encode stores alike with surface-normal prediction at `bits` (1..16) per
// octahedral coordinate get the same key, and Decode returns the same normal for both, whatever
// the mesh around them: a caller may weld vertices that differ only in such normals before
// encoding without changing what decodes. 0 for bits outside 1..16.
uint64_t OctahedralNormalKey(const float normal[3], int bits);

// Parses only the header and section table of a stream (no checksum check, no decoding): format
// version, flags, counts; for an original Open3DGC stream, its header (info->format says which).
Status ReadStreamInfo(const uint8_t* data, size_t size, StreamInfo* info);

}  // namespace o3dgc

#endif  // O3DGC_O3DGC_H_
