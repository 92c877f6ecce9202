// Coding of per-vertex attribute values (encoder in attribute_encoder.cc, decoder in
// attribute_decoder.cc; both share the context models defined here).
//
// Quantized values are predicted (none / differential / multi-parallelogram), and each residual
// component is coded as a magnitude class in one adaptive multi-symbol decision, whose model is
// selected by the component, the kind of prediction that was possible and the magnitude of the
// residuals of the already decoded neighbours (on large meshes, the classes that decision covers
// are shifted per context: ClassShifts), then its sign and low bits (adaptive on small meshes, raw
// on large ones: RawLowBits; see entropy.h). Normals in surface-normal mode are coded
// in octahedral coordinates against the normal of the decoded surface. Int attributes are coded
// exactly.
#ifndef O3DGC_SRC_ATTRIBUTE_CODER_H_
#define O3DGC_SRC_ATTRIBUTE_CODER_H_

#include <cstdint>
#include <memory>
#include <vector>

#include "arithmetic_coder.h"
#include "entropy.h"
#include "o3dgc/o3dgc.h"
#include "predictors.h"

namespace o3dgc {

constexpr int kMagContexts = 14;
constexpr int kIntraContexts = 5;
// Below this many vertices fewer contexts are used (less to learn).
constexpr uint32_t kSmallMesh = 1500;
constexpr uint32_t kTinyMesh = 300;
// From this many vertices on, residuals code their sign and low bits raw (see DecodeResidual): on
// large meshes decoding time matters, and there those adaptive models save 0-3 % of the stream
// (corpus, 14-bit positions: rocker_arm 0.0 %, bunny 1.3 %, igea 2.0 %, fandisk 3.1 %) for 13-20 %
// of the decoding time; smaller meshes decode in a millisecond or less and keep the smaller stream.
// Streams with the header's all_adaptive flag (format 1.3, EncodeParams::max_compression) code
// them adaptively in sections of every size.
constexpr uint32_t kRawLowBitsMesh = 4096;
inline bool RawLowBits(uint32_t num_vertices, bool all_adaptive = false) {
  return !all_adaptive && num_vertices >= kRawLowBitsMesh;
}

// Context from the residual of the previous component of the same vertex.
// Bit length of a (0 for 0), without a branch.
inline int BitLength(uint64_t a) { return 64 - __builtin_clzll(a | 1) - (a == 0); }

inline int IntraContext(int64_t r) {
  const int b = BitLength(uint64_t(r < 0 ? -r : r));
  return b < kIntraContexts ? b : kIntraContexts - 1;
}

// Class shifts of the residual coding (see DecodeResidual) by prediction kind and magnitude
// context, for the multi-parallelogram coder of large meshes (RawLowBits). The encoder counts the
// residual classes per context (ClassHistograms), picks per context the shift that leaves the
// fewest residuals needing a second decision (ChooseClassShifts), and sends the table before the
// residuals, 2 bits per entry (11 bytes); a table of zeros is the coding without shifts.
constexpr int kPredictionKinds = 3;
struct ClassShifts {
  uint8_t shift[kPredictionKinds][kMagContexts] = {};
  bool any() const {
    for (const auto& row : shift) {
      for (const uint8_t s : row) {
        if (s != 0) return true;
      }
    }
    return false;
  }
};
// Classes 0 (zero) and 1 + k by context, the last entry counting every class from there on.
constexpr int kShiftHistogram = kDirectClasses + kMaxClassShift + 2;
struct ClassHistograms {
  uint64_t counts[kPredictionKinds][kMagContexts][kShiftHistogram] = {};
  void Add(int kind, int mctx, int64_t r) {
    const int cls = BitLength(uint64_t(r < 0 ? -r : r));
    ++counts[kind][mctx][cls < kShiftHistogram - 1 ? cls : kShiftHistogram - 1];
  }
};
// Shifts are used only when they spare at least 1 / kMinShiftGain of the residuals a decision.
constexpr uint64_t kMinShiftGain = 32;
ClassShifts ChooseClassShifts(const ClassHistograms& histograms);
void EncodeClassShifts(ArithmeticEncoder* enc, const ClassShifts& shifts);
void DecodeClassShifts(ArithmeticDecoder* dec, ClassShifts* shifts);

// Parallelogram selection (a bit at the start of every multi-parallelogram section; in format 1.0
// it may be set for 3-component values only: positions and normals coded as values): when set,
// every vertex with two or more parallelograms first codes which prediction it uses: symbol 0 the
// combination of all of them (as without selection), symbol 1 + i the i-th parallelogram alone
// (i < kMaxSelected, in wedge order). On CAD meshes one parallelogram (across a flat wall, along a
// strip of slivers) is often exact while the others span a crease, and their median is not.
// The symbol's model is chosen by the number of parallelograms (2, 3, 4 or more).
constexpr int kMaxSelected = 7;
// Residuals against a selected parallelogram have models of their own (often exactly zero).
constexpr int kSelectedKind = 3;
constexpr int kResidualKinds = 4;
constexpr int kSelectionContexts = 3;
struct SelectionModels {
  SymbolModelN<8> symbol[kSelectionContexts];
  static int Context(int n_par) { return n_par >= 4 ? 2 : n_par - 2; }
};

// Residual models indexed by (component, prediction kind, magnitude context, intra context);
// only the components and kinds a coder uses are allocated. Quantized attributes use
// ResidualModel (one multi-symbol decision per magnitude: fast to decode), surface-normal residuals
// SignedModel (binary decisions, which learn the few normals of small meshes faster).
template <typename Model>
class ContextModels {
 public:
  ContextModels(int components, int kinds)
      : kinds_(kinds), models_(size_t(components) * kinds * kMagContexts * kIntraContexts) {}
  Model& at(int component, int kind, int mag, int intra) {
    return models_[((size_t(component) * kinds_ + kind) * kMagContexts + mag) * kIntraContexts +
                   intra];
  }
  // Distance between the same context of consecutive components.
  size_t component_stride() const { return size_t(kinds_) * kMagContexts * kIntraContexts; }
  BitModel side;
  ResidualEscape escape;  // shared by all contexts (ResidualModel only)
  // Modelled low bits (format 1.2; ResidualModel only): kTreeModels per component, or empty.
  std::vector<BitModel> tree;
  BitModel* tree_of(int component) {
    return tree.empty() ? nullptr : tree.data() + size_t(component) * kTreeModels;
  }

 private:
  int kinds_;
  std::vector<Model> models_;
};
using ResidualModels = ContextModels<ResidualModel>;
using NormalModels = ContextModels<SignedModel>;

inline int MagContext(uint64_t mag) {
  const int b = BitLength(mag);
  return b < kMagContexts ? b : kMagContexts - 1;
}

inline uint32_t SaturatingMagnitude(const int64_t* r, int dim) {
  uint64_t s = 0;
  for (int k = 0; k < dim; ++k) s += uint64_t(r[k] < 0 ? -r[k] : r[k]);
  return s > 0xFFFFFFFFu ? 0xFFFFFFFFu : uint32_t(s);
}

// Surface normal of vertex c from the triangles around it; positions are quantized values per
// position vertex, `scale` the step per axis, `position_of` maps attribute vertices to position
// vertices. Returns a unit vector ((0,0,1) when the surface gives none).
void SurfaceNormal(const MeshAdjacency& adj, uint32_t c, const int32_t* positions,
                   const double scale[3], const uint32_t* position_of, double n[3]);

// Octahedral quantization of a unit normal with `bits` per coordinate.
inline int32_t OctQuantize(double u, uint32_t maxq) {
  double q = (u + 1) * 0.5 * maxq + 0.5;
  if (q < 0) q = 0;
  if (q > maxq) q = maxq;
  return int32_t(q);
}
inline double OctDequantize(int32_t q, uint32_t maxq) { return double(q) / maxq * 2 - 1; }

struct NormalGeometry {
  const int32_t* positions;     // quantized, 3 per position vertex
  double scale[3];              // position step per axis
  const uint32_t* position_of;  // attribute vertex -> position vertex
};

// Modelled low bits (format 1.2) for a section of quantized values: kNoFlag in streams without
// the header's flag (formats 1.0, 1.1: no section bit); with the flag, every section that codes
// predicted values adaptively (fewer than kRawLowBitsMesh values) starts with a bit, 1 for
// kModelled (trees, see kTreeMaxK) and 0 for kPlain, except multi-parallelogram sections of 1, 2
// or 4 components other than texture coordinates (generic attributes, colours): each decoding
// loop that can read trees adds to the WebAssembly decoder's download, and grid-built models need
// them for positions and texture coordinates.
enum class LowBits : uint8_t { kNoFlag, kPlain, kModelled };
inline bool HasLowBitsChoice(Prediction mode, uint32_t n, int dim, bool texcoord,
                             bool all_adaptive = false) {
  return mode != Prediction::kNone && !RawLowBits(n, all_adaptive) &&
         (mode != Prediction::kParallelogram || dim == 3 || texcoord);
}

// `wedges` (needed for kParallelogram) gives the predictions and, with `order`, the coding order;
// other modes code the vertices in id order. `geometry` (optional, 3 doubles per vertex): with
// dim == 2 and kParallelogram, texture coordinates are predicted from the shape (PredictTexCoord)
// instead of parallelograms. `expect_selection`: whether 3-component parallelogram-predicted
// values will most likely use the parallelogram selection (EstimatePositionBits tells); right, the
// encoder takes one pass over the mesh to find the residuals instead of two. The bytes are the
// same either way. `all_adaptive`: the stream's flag (see RawLowBits).
void EncodeQuantized(ArithmeticEncoder* enc, const WedgeTable* wedges,
                     const std::vector<int32_t>& q, int dim, int bits, Prediction mode,
                     CodingOrder::Kind order, const std::vector<double>* geometry = nullptr,
                     LowBits low_bits = LowBits::kNoFlag, bool expect_selection = true,
                     bool all_adaptive = false);
// Estimated bits of 3-component parallelogram-predicted values coded in `order` (nothing coded):
// the encoder's choice between the two orders (EncodeParams::auto_fast_decode). `selects` (if
// not null) receives whether they would use the parallelogram selection.
double EstimatePositionBits(const WedgeTable& wedges, const std::vector<int32_t>& q, int bits,
                            CodingOrder::Kind order, bool* selects = nullptr);
Status DecodeQuantized(ArithmeticDecoder* dec, const WedgeTable* wedges, uint32_t n, int dim,
                       int bits, Prediction mode, CodingOrder::Kind order, std::vector<int32_t>* q,
                       const std::vector<double>* geometry = nullptr, bool low_bits_flag = false,
                       bool all_adaptive = false);

// Positions of attribute vertices as doubles (quantized value * step), for PredictTexCoord.
std::vector<double> AttributeGeometry(const NormalGeometry& geo, uint32_t n);

// normals: 3 floats per vertex (any length; zero-length codes as (0,0,1)).
void EncodeOctNormals(ArithmeticEncoder* enc, const MeshAdjacency& adj, const NormalGeometry& geo,
                      const std::vector<float>& normals, int bits);
Status DecodeOctNormals(ArithmeticDecoder* dec, const MeshAdjacency& adj, const NormalGeometry& geo,
                        uint32_t n, int bits, std::vector<float>* normals);

void EncodeInts(ArithmeticEncoder* enc, const std::vector<int32_t>& values, int dim,
                Prediction mode);
Status DecodeInts(ArithmeticDecoder* dec, uint32_t n, int dim, Prediction mode,
                  std::vector<int32_t>* values);

}  // namespace o3dgc

#endif  // O3DGC_SRC_ATTRIBUTE_CODER_H_
