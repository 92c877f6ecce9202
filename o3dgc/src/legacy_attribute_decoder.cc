// Per-vertex arrays of original Open3DGC streams (see legacy_attribute_decoder.h). Float
// arithmetic follows the original step by step (float products and sums, the same casts), so
// decoded values match its output bit for bit on IEEE machines; this file is compiled without
// floating-point contraction for that reason.
#include "legacy_attribute_decoder.h"

#include <cmath>
#include <cstdint>
#include <memory>

#include "legacy_arithmetic_decoder.h"

namespace o3dgc {
namespace {

constexpr uint8_t kNoPrediction = 0;
constexpr uint8_t kDifferential = 1;
constexpr uint8_t kParallelogram = 5;
constexpr uint8_t kSurfaceNormal = 6;
constexpr uint8_t kArithmeticCoding = 4;  // "arithmetic coding + Exp-Golomb" (binary streams)
constexpr uint8_t kAsciiCoding = 5;
constexpr uint32_t kMaxCandidates = 2;

// Wrapping integer arithmetic: hostile residuals may overflow int64; valid ones never do.
int64_t Add(int64_t a, int64_t b) { return int64_t(uint64_t(a) + uint64_t(b)); }
int64_t Sub(int64_t a, int64_t b) { return int64_t(uint64_t(a) - uint64_t(b)); }
int64_t Mul(int64_t a, int64_t b) { return int64_t(uint64_t(a) * uint64_t(b)); }
uint64_t Magnitude(int64_t a) { return a < 0 ? 0 - uint64_t(a) : uint64_t(a); }

// A predictor candidate's identity: (min(a, b), max(a, b), -c - 1) for a parallelogram,
// (-1, -1, w) for a neighbour. Ordered by c, then b, then a, so parallelograms come first.
struct Id {
  int64_t a, b, c;
  bool operator==(const Id& o) const { return a == o.a && b == o.b && c == o.c; }
  bool operator<(const Id& o) const {
    if (c != o.c) return c < o.c;
    if (b != o.b) return b < o.b;
    return a < o.a;
  }
};

struct Candidate {
  Id id;
  int64_t value[kLegacyMaxDimension];
};

// The two smallest distinct ids seen so far, with their predictions. Returns the slot to fill
// for a new id, or -1 when `e` is already present or larger than both kept ones.
int Insert(const Id& e, uint32_t* n, Candidate* list) {
  for (uint32_t j = 0; j < *n; ++j) {
    if (e == list[j].id) return -1;
    if (e < list[j].id) {
      if (*n < kMaxCandidates) ++*n;
      for (uint32_t h = *n - 1; h > j; --h) list[h] = list[h - 1];
      list[j].id = e;
      return int(j);
    }
  }
  if (*n < kMaxCandidates) {
    list[*n].id = e;
    return int((*n)++);
  }
  return -1;
}

// The cube face of direction (x, y, z) and the two coordinates in it.
void SphereToCube(int64_t x, int64_t y, int64_t z, int64_t* a, int64_t* b, int8_t* face) {
  const uint64_t ax = Magnitude(x), ay = Magnitude(y), az = Magnitude(z);
  if (az >= ax && az >= ay) {
    *face = z >= 0 ? 0 : 1;
    *a = z >= 0 ? x : Sub(0, x);
    *b = z >= 0 ? y : Sub(0, y);
  } else if (ay >= ax && ay >= az) {
    *face = y >= 0 ? 2 : 3;
    *a = y >= 0 ? z : Sub(0, z);
    *b = y >= 0 ? x : Sub(0, x);
  } else {
    *face = x >= 0 ? 4 : 5;
    *a = x >= 0 ? y : Sub(0, y);
    *b = x >= 0 ? z : Sub(0, z);
  }
}

// sqrt(max(0, 1 - u^2 - w^2)) with the squares rounded to float and the rest in double, as the
// original computed it.
float Height(float u, float w) {
  const float uu = u * u, ww = w * w;
  const double h = (1.0 - double(uu)) - double(ww);
  return float(std::sqrt(h > 0.0 ? h : 0.0));
}

// Inverse of SphereToCube for a unit-length normal; false for a face outside 0..5.
bool CubeToSphere(float a, float b, int8_t face, float* n) {
  switch (face) {
    case 0:
      n[0] = a;
      n[1] = b;
      n[2] = Height(n[0], n[1]);
      return true;
    case 1:
      n[0] = -a;
      n[1] = -b;
      n[2] = -Height(n[0], n[1]);
      return true;
    case 2:
      n[2] = a;
      n[0] = b;
      n[1] = Height(n[0], n[2]);
      return true;
    case 3:
      n[2] = -a;
      n[0] = -b;
      n[1] = -Height(n[0], n[2]);
      return true;
    case 4:
      n[1] = a;
      n[2] = b;
      n[0] = Height(n[1], n[2]);
      return true;
    case 5:
      n[1] = -a;
      n[2] = -b;
      n[0] = -Height(n[1], n[2]);
      return true;
    default:
      return false;
  }
}

// Cell size of `bits`-bit quantization over [min, max], in float as the original.
float Step(float min, float max, int bits) {
  const float r = max - min;
  return r > 0.0f ? r / float((1 << bits) - 1) : 1.0f;
}

// Reads residuals: from the arithmetic decoder (binary) or as variable-length numbers (ASCII).
class ResidualSource {
 public:
  // The Exp-Golomb models are those that decoded the section's first two numbers (the original
  // shares them).
  ResidualSource(LegacyReader* r, LegacyArithmeticDecoder* dec, LegacyAdaptiveDataModel* values,
                 LegacyStaticBitModel* bits, LegacyAdaptiveBitModel* prefix, uint32_t exp_k,
                 uint32_t m)
      : r_(r), dec_(dec), values_(values), bits_(bits), prefix_(prefix), exp_k_(exp_k), m_(m) {}
  bool Unsigned(uint64_t* out) {
    if (!dec_) {
      *out = r_->ReadAsciiUInt();
      return !r_->failed();
    }
    uint64_t s = dec_->Decode(*values_);
    if (s == m_) {
      uint32_t extra;
      if (!dec_->DecodeExpGolomb(exp_k_, *bits_, *prefix_, &extra)) return false;
      s += extra;
    }
    *out = s;
    return true;
  }
  bool Signed(int64_t* out) {
    uint64_t u;
    if (!Unsigned(&u)) return false;
    *out = LegacyUnsignedToSigned(u);
    return true;
  }

 private:
  LegacyReader* r_;
  LegacyArithmeticDecoder* dec_;
  LegacyAdaptiveDataModel* values_;
  LegacyStaticBitModel* bits_;
  LegacyAdaptiveBitModel* prefix_;
  uint32_t exp_k_, m_;
};

}  // namespace

LegacyAttributeDecoder::LegacyAttributeDecoder(LegacyReader* reader,
                                               const std::vector<uint32_t>& triangles,
                                               uint32_t num_coords)
    : r_(reader), triangles_(triangles), num_coords_(num_coords) {
  // Triangle ids per vertex, one entry per corner (a triangle naming a vertex twice is listed
  // twice, as in the original; candidates are deduplicated anyway).
  offsets_.assign(size_t(num_coords) + 1, 0);
  for (uint32_t v : triangles_) ++offsets_[size_t(v) + 1];
  for (size_t i = 0; i < num_coords; ++i) offsets_[i + 1] += offsets_[i];
  incident_.resize(triangles_.size());
  std::vector<uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (size_t i = 0; i < triangles_.size(); ++i) incident_[fill[triangles_[i]]++] = uint32_t(i / 3);
}

Status LegacyAttributeDecoder::DecodeArray(const LegacyArrayDesc& d, Kind kind,
                                           std::vector<int64_t>* q, uint32_t* dim_out,
                                           uint8_t* mode_out) {
  const bool ascii = r_->encoding() == LegacyEncoding::kAscii;
  const size_t start = r_->pos();
  const uint64_t section = r_->ReadUInt32();
  const uint8_t mask = r_->ReadUChar();
  if (r_->failed()) return Status::kTruncated;
  const uint8_t coding = (mask >> 4) & 7;
  const uint8_t mode = mask & 7;
  const size_t fields = r_->pos() - start;
  if (section < fields) return Status::kCorrupt;
  if (section - fields > r_->remaining()) return Status::kTruncated;
  const size_t end = start + size_t(section);
  if (coding != (ascii ? kAsciiCoding : kArithmeticCoding)) return Status::kCorrupt;
  if (mode == kSurfaceNormal && (kind == Kind::kPositions || kind == Kind::kFloats)) {
    return Status::kUnsupported;  // the original only defines it for normals
  }

  const uint32_t n = uint32_t(d.count);
  const uint32_t stride = d.dimension;
  const bool surface = mode == kSurfaceNormal && kind == Kind::kNormals;
  const uint32_t dim = surface ? 2 : d.dimension;
  *dim_out = dim;
  *mode_out = mode;

  // Binary: one arithmetic-coded section starting with the Exp-Golomb order and the escape
  // symbol M. ASCII: residuals here, predictor choices in the section that follows.
  std::unique_ptr<LegacyArithmeticDecoder> dec;
  LegacyStaticBitModel eg_bits;
  LegacyAdaptiveBitModel eg_prefix;
  LegacyAdaptiveDataModel values, choices;
  uint32_t exp_k = 0, m = 0;
  LegacyReader choice_reader(r_->data(), r_->size(), r_->encoding());
  if (!ascii) {
    dec.reset(new LegacyArithmeticDecoder(r_->data(), r_->pos(), end, r_->size()));
    if (!dec->DecodeExpGolomb(0, eg_bits, eg_prefix, &exp_k) ||
        !dec->DecodeExpGolomb(0, eg_bits, eg_prefix, &m)) {
      return Status::kCorrupt;
    }
    if (exp_k > 30 || m > LegacyAdaptiveDataModel::kMaxSymbols - 2 || !values.Init(m + 2) ||
        !choices.Init(kMaxCandidates + 1)) {
      return Status::kCorrupt;
    }
  } else {
    choice_reader.Seek(end);
    choice_reader.ReadUInt32();  // size of the choice section: read as needed
    if (choice_reader.failed()) return Status::kTruncated;
  }
  ResidualSource residuals(r_, dec.get(), &values, &eg_bits, &eg_prefix, exp_k, m);

  if (surface) {
    if (coords_.empty()) return Status::kCorrupt;
    // Orientation of each normal relative to the cube face of the predicted one.
    orientation_.resize(n);
    if (ascii) {
      for (uint32_t i = 0; i < n; ++i) orientation_[i] = int8_t(uint8_t(r_->ReadAsciiInt()));
      if (r_->failed()) return Status::kTruncated;
    } else {
      LegacyAdaptiveDataModel faces;
      faces.Init(12);
      for (uint32_t i = 0; i < n; ++i) {
        orientation_[i] = int8_t(LegacyUnsignedToSigned(dec->Decode(faces)));
      }
    }
    // Predicted normal: the sum of the (unnormalised) triangle normals, in cube-face coordinates.
    normal_prediction_.assign(2 * size_t(n), 0.0f);
    for (uint32_t v = 0; v < n; ++v) {
      int64_t s[3] = {0, 0, 0};
      if (v < num_coords_) {
        for (uint32_t e = offsets_[v]; e < offsets_[v + 1]; ++e) {
          const uint32_t* t = &triangles_[3 * size_t(incident_[e])];
          const int64_t* p1 = &coords_[3 * size_t(t[0])];
          const int64_t* p2 = &coords_[3 * size_t(t[1])];
          const int64_t* p3 = &coords_[3 * size_t(t[2])];
          int64_t u[3], w[3];
          for (int k = 0; k < 3; ++k) {
            u[k] = Sub(p2[k], p1[k]);
            w[k] = Sub(p3[k], p1[k]);
          }
          s[0] = Add(s[0], Sub(Mul(u[1], w[2]), Mul(u[2], w[1])));
          s[1] = Add(s[1], Sub(Mul(u[2], w[0]), Mul(u[0], w[2])));
          s[2] = Add(s[2], Sub(Mul(u[0], w[1]), Mul(u[1], w[0])));
        }
      }
      const double x = double(s[0]), y = double(s[1]), z = double(s[2]);
      float norm = float(std::sqrt(x * x + y * y + z * z));
      if (norm == 0.0f) norm = 1.0f;
      int64_t a, b;
      int8_t face;
      SphereToCube(s[0], s[1], s[2], &a, &b, &face);
      float pa = float(a) / norm, pb = float(b) / norm;
      const int8_t actual = int8_t(face + orientation_[v]);
      orientation_[v] = actual;
      if ((actual >> 1) != (face >> 1)) pa = pb = 0.0f;  // another axis: no usable prediction
      normal_prediction_[2 * size_t(v)] = pa;
      normal_prediction_[2 * size_t(v) + 1] = pb;
    }
  }

  // The parallelogram search is bounded: a valid mesh needs a few steps per corner, a hostile
  // one (thousands of triangles on one edge) could need quadratic time.
  const uint64_t max_work = work_ + 64 * uint64_t(triangles_.size()) + (uint64_t(1) << 24);
  q->assign(size_t(n) * stride, 0);
  int64_t* qv = q->data();
  Candidate list[kMaxCandidates];
  for (uint32_t v = 0; v < n; ++v) {
    uint32_t count = 0;
    if (mode != kNoPrediction && v < num_coords_) {
      for (uint32_t e = offsets_[v]; e < offsets_[v + 1]; ++e) {
        const uint32_t* t = &triangles_[3 * size_t(incident_[e])];
        if (mode == kParallelogram && kind != Kind::kInts) {
          const uint32_t a = t[0] == v ? t[1] : t[0];
          const uint32_t b = t[0] == v || t[1] == v ? t[2] : t[1];
          if (a < v && b < v) {
            // Triangles holding both a and b: scan the shorter of the two lists.
            const bool by_a = offsets_[a + 1] - offsets_[a] <= offsets_[b + 1] - offsets_[b];
            const uint32_t other = by_a ? b : a, list_of = by_a ? a : b;
            work_ += offsets_[list_of + 1] - offsets_[list_of];
            if (work_ > max_work) return Status::kLimitExceeded;
            for (uint32_t f = offsets_[list_of]; f < offsets_[list_of + 1]; ++f) {
              const uint32_t* u = &triangles_[3 * size_t(incident_[f])];
              if (u[0] != other && u[1] != other && u[2] != other) continue;
              int64_t c = -1;
              for (int k = 0; k < 3; ++k) {
                if (u[k] < v && u[k] != a && u[k] != b) c = u[k];
              }
              if (c < 0) continue;
              const int p = Insert({a < b ? a : b, a < b ? b : a, -c - 1}, &count, list);
              if (p < 0) continue;
              for (uint32_t i = 0; i < dim; ++i) {
                list[p].value[i] = Sub(Add(qv[a * size_t(stride) + i], qv[b * size_t(stride) + i]),
                                       qv[size_t(c) * stride + i]);
              }
            }
          }
        }
        if (mode == kDifferential || mode == kParallelogram || mode == kSurfaceNormal ||
            (kind == Kind::kInts && mode != kNoPrediction)) {
          for (int k = 0; k < 3; ++k) {
            const uint32_t w = t[k];
            if (w >= v) continue;
            const int p = Insert({-1, -1, int64_t(w)}, &count, list);
            if (p < 0) continue;
            for (uint32_t i = 0; i < dim; ++i) list[p].value[i] = qv[w * size_t(stride) + i];
          }
        }
      }
    }
    int64_t* out = qv + size_t(v) * stride;
    if (count > 1) {
      const uint32_t pick = ascii ? choice_reader.ReadByte() : dec->Decode(choices);
      if (pick >= count) return Status::kCorrupt;
      for (uint32_t i = 0; i < dim; ++i) {
        int64_t r;
        if (!residuals.Signed(&r)) return Status::kCorrupt;
        out[i] = Add(r, list[pick].value[i]);
      }
    } else if (v > 0 && mode != kNoPrediction) {
      for (uint32_t i = 0; i < dim; ++i) {
        int64_t r;
        if (!residuals.Signed(&r)) return Status::kCorrupt;
        out[i] = Add(r, (out - stride)[i]);
      }
    } else {
      for (uint32_t i = 0; i < dim; ++i) {
        uint64_t r;
        if (!residuals.Unsigned(&r)) return Status::kCorrupt;
        out[i] = int64_t(r);
      }
    }
    if ((v & 1023) == 0 && (ascii ? r_->failed() || choice_reader.failed() : dec->failed())) {
      return Status::kCorrupt;
    }
  }
  if (ascii) {
    if (r_->failed() || choice_reader.failed()) return Status::kTruncated;
    r_->Seek(choice_reader.pos());
  } else {
    if (dec->failed()) return Status::kCorrupt;
    r_->Seek(end);
  }
  return Status::kOk;
}

Status LegacyAttributeDecoder::DecodePositions(const LegacyArrayDesc& d, std::vector<float>* out) {
  uint32_t dim;
  uint8_t mode;
  if (d.bits < 1 || d.bits > 30) return Status::kCorrupt;
  Status s = DecodeArray(d, Kind::kPositions, &coords_, &dim, &mode);
  if (s != Status::kOk) return s;
  out->resize(coords_.size());
  for (size_t i = 0; i < coords_.size(); ++i) {
    const uint32_t k = uint32_t(i % 3);
    (*out)[i] = float(coords_[i]) * Step(d.min[k], d.max[k], d.bits) + d.min[k];
  }
  return Status::kOk;
}

Status LegacyAttributeDecoder::DecodeNormals(const LegacyArrayDesc& d, std::vector<float>* out) {
  uint32_t dim;
  uint8_t mode;
  std::vector<int64_t> q;
  if (d.bits < 1 || d.bits > 29) return Status::kCorrupt;
  Status s = DecodeArray(d, Kind::kNormals, &q, &dim, &mode);
  if (s != Status::kOk) return s;
  out->resize(q.size());
  if (mode != kSurfaceNormal) {
    for (size_t i = 0; i < q.size(); ++i) {
      const uint32_t k = uint32_t(i % 3);
      (*out)[i] = float(q[i]) * Step(d.min[k], d.max[k], d.bits) + d.min[k];
    }
    return Status::kOk;
  }
  // Two cube-face coordinates quantized over [-2, 2] with one more bit, added to the prediction.
  const float step = Step(-2.0f, 2.0f, d.bits + 1);
  for (size_t v = 0; v < q.size() / 3; ++v) {
    const float a = float(q[3 * v]) * step + -2.0f;
    const float b = float(q[3 * v + 1]) * step + -2.0f;
    if (!CubeToSphere(a + normal_prediction_[2 * v], b + normal_prediction_[2 * v + 1],
                      orientation_[v], &(*out)[3 * v])) {
      return Status::kCorrupt;
    }
  }
  return Status::kOk;
}

Status LegacyAttributeDecoder::DecodeFloats(const LegacyArrayDesc& d, std::vector<float>* out) {
  uint32_t dim;
  uint8_t mode;
  std::vector<int64_t> q;
  if (d.count > 0 && (d.bits < 1 || d.bits > 30)) return Status::kCorrupt;
  Status s = DecodeArray(d, Kind::kFloats, &q, &dim, &mode);
  if (s != Status::kOk) return s;
  out->resize(q.size());
  for (size_t i = 0; i < q.size(); ++i) {
    const uint32_t k = uint32_t(i % d.dimension);
    (*out)[i] = float(q[i]) * Step(d.min[k], d.max[k], d.bits) + d.min[k];
  }
  return Status::kOk;
}

Status LegacyAttributeDecoder::DecodeInts(const LegacyArrayDesc& d, std::vector<int32_t>* out) {
  uint32_t dim;
  uint8_t mode;
  std::vector<int64_t> q;
  Status s = DecodeArray(d, Kind::kInts, &q, &dim, &mode);
  if (s != Status::kOk) return s;
  out->resize(q.size());
  for (size_t i = 0; i < q.size(); ++i) {
    if (q[i] < INT32_MIN || q[i] > INT32_MAX) return Status::kCorrupt;
    (*out)[i] = int32_t(q[i]);
  }
  return Status::kOk;
}

}  // namespace o3dgc
