// Binarizations of integers on top of the adaptive arithmetic coder (encoder and decoder side by
// side so that the two stay mirror images).
//
// Unsigned values use an adaptive Exp-Golomb code: the prefix (bit length) is coded bit by bit
// with one model per position, the two most significant suffix bits with models conditioned on
// the length, the remaining suffix bits as equiprobable bits. Signed values add a zero flag and
// a sign (SignedModel); attribute residuals, the bulk of a stream, code their magnitude class in
// one multi-symbol decision instead (ResidualModel). Callers pick the model set (the context) per
// value.
#ifndef O3DGC_SRC_ENTROPY_H_
#define O3DGC_SRC_ENTROPY_H_

#include <cstdint>

#include "arithmetic_coder.h"

namespace o3dgc {

constexpr int kMaxEGPrefix = 40;  // values up to 2^40 - 2

struct EGModel {
  BitModel prefix[kMaxEGPrefix + 1];
  BitModel suffix[kMaxEGPrefix + 1][3];
};

inline int FloorLog2(uint64_t v) { return 63 - __builtin_clzll(v); }

// The k bits of v below its leading one (v >= 1, k = FloorLog2(v)): the top two through adaptive
// models (the second conditioned on the first), the rest raw. Shared by EG and signed residuals.
// (Templates on the coder: an ArithmeticEncoder, or a DecisionLog that records for it.)
template <typename Coder>
inline void EncodeMantissa(Coder& e, BitModel (&suffix)[3], uint64_t v, int k) {
  if (k == 0) return;
  const int top = int((v >> (k - 1)) & 1);
  e.Encode(top, suffix[0]);
  if (k == 1) return;
  e.Encode(int((v >> (k - 2)) & 1), suffix[1 + top]);
  int rest = k - 2;
  while (rest > 0) {
    const int n = rest > 24 ? 24 : rest;
    rest -= n;
    e.EncodeBits(uint32_t((v >> rest) & ((1u << n) - 1)), n);
  }
}

// Inverse of EncodeMantissa: returns v (leading one included).
inline uint64_t DecodeMantissa(ArithmeticDecoder& d, BitModel (&suffix)[3], int k) {
  uint64_t v = 1;
  if (k == 0) return v;
  const int top = d.Decode(suffix[0]);
  v = (v << 1) | uint64_t(top);
  if (k == 1) return v;
  v = (v << 1) | uint64_t(d.Decode(suffix[1 + top]));
  int rest = k - 2;
  while (rest > 0) {
    const int n = rest > 24 ? 24 : rest;
    rest -= n;
    v = (v << n) | d.DecodeBits(n);
  }
  return v;
}

template <typename Coder>
inline void EncodeEG(Coder& e, EGModel& m, uint64_t u) {
  const uint64_t v = u + 1;
  const int k = FloorLog2(v);
  for (int i = 0; i < k; ++i) e.Encode(1, m.prefix[i]);
  if (k < kMaxEGPrefix) e.Encode(0, m.prefix[k]);
  EncodeMantissa(e, m.suffix[k], v, k);
}

// Values of 2 and more (a prefix of at least two ones), out of line.
O3DGC_NOINLINE inline uint64_t DecodeEGTail(ArithmeticDecoder& d, EGModel& m) {
  int k = 2;
  while (k < kMaxEGPrefix && d.Decode(m.prefix[k])) ++k;
  return DecodeMantissa(d, m.suffix[k], k) - 1;
}

// The common small values (0: one decision; 1 and 2: three) inline, so that a caller's decoder
// state can stay in registers.
O3DGC_INLINE uint64_t DecodeEG(ArithmeticDecoder& d, EGModel& m) {
  if (!d.Decode(m.prefix[0])) return 0;
  if (!d.Decode(m.prefix[1])) return 1 + uint64_t(d.Decode(m.suffix[1][0]));
  return DecodeEGTail(d, m);
}

// Signed residuals: zero flag, sign, then the bit length k of the magnitude coded relative to a
// running estimate k0 of it (one "k >= k0" decision, then unary steps up or down), then the
// suffix as in EncodeEG. Starting from k0 saves most of the unary decisions.
struct SignedModel {
  BitModel zero;
  BitModel sign;
  BitModel at_least;
  BitModel up[kMaxEGPrefix + 1];
  BitModel down[kMaxEGPrefix + 1];
  BitModel suffix[kMaxEGPrefix + 1][3];
  uint16_t k_avg = 0;  // running mean of k, 4 fractional bits

  int Expected() const { return (k_avg + 8) >> 4; }
  void Observe(int k) { k_avg = uint16_t(k_avg + ((k * 16 - int(k_avg)) >> 3)); }
};

inline void EncodeSigned(ArithmeticEncoder& e, SignedModel& m, int64_t r) {
  e.Encode(r != 0, m.zero);
  if (r == 0) return;
  e.Encode(r < 0, m.sign);
  const uint64_t v = uint64_t(r < 0 ? -r : r);
  const int k = FloorLog2(v);
  const int k0 = m.Expected();
  if (k0 > 0) e.Encode(k >= k0, m.at_least);
  if (k >= k0) {
    for (int i = k0; i < k; ++i) e.Encode(1, m.up[i]);
    if (k < kMaxEGPrefix) e.Encode(0, m.up[k]);
  } else {
    for (int i = k0 - 1; i > k; --i) e.Encode(1, m.down[i]);
    if (k > 0) e.Encode(0, m.down[k]);
  }
  m.Observe(k);
  EncodeMantissa(e, m.suffix[k], v, k);
}

inline int64_t DecodeSigned(ArithmeticDecoder& d, SignedModel& m) {
  if (!d.Decode(m.zero)) return 0;
  const int neg = d.Decode(m.sign);
  const int k0 = m.Expected();
  int k;
  if (k0 == 0 || d.Decode(m.at_least)) {
    k = k0;
    while (k < kMaxEGPrefix && d.Decode(m.up[k])) ++k;
  } else {
    k = k0 - 1;
    while (k > 0 && d.Decode(m.down[k])) --k;
  }
  m.Observe(k);
  const uint64_t v = DecodeMantissa(d, m.suffix[k], k);
  return neg ? -int64_t(v) : int64_t(v);
}

// Residuals of the attribute coders: the magnitude class (0: zero; 1 + k: |r| in [2^k, 2^(k+1)))
// in one multi-symbol decision, then the sign and the k bits below the leading one. The decision
// covers the classes shift + 1 .. shift + kDirectClasses directly (symbols 1..kDirectClasses); the
// first symbol stands for the classes 0..shift (when shift > 0, a second decision says which), the
// last one for the classes above (a second decision for the next kEscapeSymbol classes, then a
// unary code). The shift (0..kMaxClassShift) comes from the caller, the same in the encoder and
// the decoder: with 0 the first symbol is zero itself. Meshes with large residuals (rocker_arm at
// 14 bits: 27 % of them k >= kDirectClasses) take a shift where they are common, so that most
// residuals need one decision. Two codings of the sign and the low bits (the caller picks one per
// attribute, the same in the encoder and the decoder):
//  - adaptive (kRawLow false): the sign and the bit below the leading one through adaptive models,
//    the remaining bits raw;
//  - raw (kRawLow true): the sign and all k bits in one read of the raw bit stream. Two adaptive
//    decisions fewer per residual: 13-20 % less decoding time on meshes of 10k to 270k triangles,
//    for 0-3 % more bytes (attribute_coder.h says where it is used).
// Eight symbols: one SSE2 vector per table, and a smaller alphabet learns faster than 16 classes
// did (most residuals are below 2^6; the escape costs a second decision for the others).
constexpr int kResidualSymbols = 8;
constexpr int kDirectClasses = kResidualSymbols - 2;
constexpr int kEscapeSymbol = kResidualSymbols - 1;
constexpr int kHighClasses = kDirectClasses + kEscapeSymbol;  // below: the two decisions
constexpr int kMaxClassShift = 3;

// One context's models: those every residual uses first (two cache lines), then the second class
// decisions. The unary part of the rare classes past both decisions (|r| >= 2^(kHighClasses +
// shift)) has its models in ResidualEscape, shared by all contexts, so that the context models
// stay small.
struct ResidualModel {
  SymbolModelN<kResidualSymbols> magnitude;
  BitModel sign;                          // adaptive coding only
  BitModel mantissa[kDirectClasses + 1];  // the bit below the leading one, by k (larger: the last)
  SymbolModelN<kResidualSymbols> high;    // the class above the direct ones after an escape
  // The class 0..shift after the first symbol (shift > 0).
  SymbolModelN<kResidualSymbols> low{kMaxClassShift + 1};
};
struct ResidualEscape {
  BitModel more[kMaxEGPrefix - kHighClasses + 1];
};

// Modelled low bits (format 1.2, adaptive coding only): the k bits below the leading one of a
// residual of class 1 + k <= kTreeMaxK + 1 are coded one by one, each with the bit model of its
// place in a binary tree over the magnitudes of that class (model (1 << k) - 1 + p, where p is the
// magnitude's bits read so far, leading one included), instead of one adaptive bit and k - 1 raw
// ones. On meshes built on a design grid the same few residual values recur in every class, and
// the tree learns them; raw bits cannot. One tree per component (kTreeModels models each).
constexpr int kTreeMaxK = 12;
constexpr size_t kTreeModels = (size_t(2) << kTreeMaxK) - 1;

// The low `count` bits of v (count <= 64) to the raw stream, most significant first.
inline void EncodeRawWide(ArithmeticEncoder& e, uint64_t v, int count) {
  while (count > 0) {
    const int n = count > 24 ? 24 : count;
    count -= n;
    e.EncodeRaw(uint32_t((v >> count) & ((1u << n) - 1)), n);
  }
}

// Inverse of EncodeRawWide: v followed by `count` bits of the raw stream.
O3DGC_INLINE uint64_t DecodeRawWide(ArithmeticDecoder& d, uint64_t v, int count) {
  while (count > 0) {
    const int n = count > 24 ? 24 : count;
    count -= n;
    v = (v << n) | d.DecodeRaw(n);
  }
  return v;
}

// `shift` in 0..kMaxClassShift; `tree` (adaptive coding only): the component's tree of modelled
// low bits, or null.
template <bool kRawLow>
O3DGC_INLINE void EncodeResidual(ArithmeticEncoder& e, ResidualModel& m, ResidualEscape& x,
                                 int64_t r, int shift = 0, BitModel* tree = nullptr) {
  const uint64_t v = uint64_t(r < 0 ? -r : r);
  const int k = r == 0 ? -1 : FloorLog2(v);
  const int cls = k + 1;
  if (cls <= shift) {
    e.Encode(0, m.magnitude);
    if (shift > 0) e.Encode(cls, m.low);
    if (r == 0) return;
  } else if (cls <= shift + kDirectClasses) {
    e.Encode(cls - shift, m.magnitude);
  } else {
    e.Encode(kEscapeSymbol, m.magnitude);
    const int h = cls - shift - kDirectClasses - 1;
    if (h < kEscapeSymbol) {
      e.Encode(h, m.high);
    } else {
      e.Encode(kEscapeSymbol, m.high);
      const int first = kHighClasses + shift;  // the k of the first unary step
      for (int i = first; i < k; ++i) e.Encode(1, x.more[i - first]);
      if (k < kMaxEGPrefix) e.Encode(0, x.more[k - first]);
    }
  }
  if (kRawLow) {
    // The sign, then the k bits below the leading one: one read for the decoder when k < 24.
    if (k < 24) {
      e.EncodeRaw((uint32_t(r < 0) << k) | uint32_t(v & ((1u << k) - 1)), k + 1);
    } else {
      e.EncodeRaw(uint32_t(r < 0), 1);
      EncodeRawWide(e, v, k);
    }
    return;
  }
  e.Encode(r < 0, m.sign);
  if (k == 0) return;
  if (tree && k <= kTreeMaxK) {
    BitModel* const level = tree + (size_t(1) << k) - 1;
    uint32_t p = 1;
    for (int j = k - 1; j >= 0; --j) {
      const int bit = int((v >> j) & 1);
      e.Encode(bit, level[p]);
      p = 2 * p + uint32_t(bit);
    }
    return;
  }
  e.Encode(int((v >> (k - 1)) & 1), m.mantissa[k < kDirectClasses ? k : kDirectClasses]);
  EncodeRawWide(e, v, k - 1);
}

// The class k after an escape: the high decision `h` counts from k = `base`; its last symbol
// continues in a unary code.
O3DGC_INLINE int DecodeHighClass(ArithmeticDecoder& d, ResidualEscape& x, int h, int base) {
  int k = base + h;
  if (h == kEscapeSymbol) {
    const int first = k;
    while (k < kMaxEGPrefix && d.Decode(x.more[k - first])) ++k;
  }
  return k;
}

// The magnitude of class 1 + k (1 <= k <= kTreeMaxK) from its tree of modelled low bits; out of
// line: used on small meshes only, where it costs no time that matters, and the loops stay small.
O3DGC_INLINE uint64_t DecodeTreeBits(ArithmeticDecoder& d, BitModel* tree, int k) {
  BitModel* const level = tree + (size_t(1) << k) - 1;
  uint32_t p = 1;
  for (int j = 0; j < k; ++j) p = 2 * p + uint32_t(d.Decode(level[p]));
  return p;
}

// The sign and the k bits below the leading one of a residual of class 1 + k (`tree`: see
// EncodeResidual).
template <bool kRawLow>
O3DGC_INLINE int64_t DecodeSignAndLowBits(ArithmeticDecoder& d, ResidualModel& m, int k,
                                          BitModel* tree = nullptr) {
  int neg;
  uint64_t v = 1;
  if (kRawLow) {
    if (O3DGC_LIKELY(k < 24)) {
      const uint32_t bits = d.DecodeRaw(k + 1);
      neg = int(bits >> k);
      v = (uint64_t(1) << k) | (bits & ((1u << k) - 1));
    } else {
      neg = int(d.DecodeRaw(1));
      v = DecodeRawWide(d, v, k);
    }
  } else {
    neg = d.Decode(m.sign);
    if (tree && k > 0 && k <= kTreeMaxK) {
      v = DecodeTreeBits(d, tree, k);
    } else if (k > 0) {
      v = 2 | uint64_t(d.Decode(m.mantissa[k < kDirectClasses ? k : kDirectClasses]));
      v = DecodeRawWide(d, v, k - 1);
    }
  }
  const int64_t sign = -int64_t(neg);  // all ones for a negative value
  return (int64_t(v) ^ sign) - sign;
}

// Inverse of EncodeResidual with shift 0. `symbol` (optional) receives the first decision's
// symbol: min(symbol, kDirectClasses + 1) is min(bit length of |r|, kDirectClasses + 1), known
// before the sign and the low bits are read.
template <bool kRawLow>
O3DGC_INLINE int64_t DecodeResidual(ArithmeticDecoder& d, ResidualModel& m, ResidualEscape& x,
                                    int* first_symbol = nullptr, BitModel* tree = nullptr) {
  const int symbol = d.Decode(m.magnitude);
  if (first_symbol) *first_symbol = symbol;
  if (symbol == 0) return 0;
  int k = symbol - 1;
  if (O3DGC_UNLIKELY(symbol == kEscapeSymbol)) {
    k = DecodeHighClass(d, x, d.Decode(m.high), kDirectClasses);
  }
  return DecodeSignAndLowBits<kRawLow>(d, m, k, tree);
}

// Inverse of EncodeResidual with any shift (0..kMaxClassShift). A separate function: the loops
// without shifts keep DecodeResidual's shorter code. `*bit_length` (optional) receives the bit
// length of |r| (its class), known before the sign and the low bits are read.
template <bool kRawLow>
O3DGC_INLINE int64_t DecodeShiftedResidual(ArithmeticDecoder& d, ResidualModel& m,
                                           ResidualEscape& x, int shift,
                                           int* bit_length = nullptr) {
  int unused;
  if (!bit_length) bit_length = &unused;
  const int symbol = d.Decode(m.magnitude);
  int k = symbol - 1 + shift;
  *bit_length = k + 1;
  if (O3DGC_UNLIKELY(symbol == 0 || symbol == kEscapeSymbol)) {
    *bit_length = 0;
    if (symbol == 0 && shift == 0) return 0;
    // One decoding step for both second decisions: each inlined step adds to the loops' code
    // (and to the WebAssembly decoder's download).
    const int h = d.Decode(symbol == 0 ? m.low : m.high);
    if (symbol == 0) {
      // A corrupt stream may name a class above the shift: it decodes as some value all the same.
      k = h - 1;
      if (k < 0) return 0;
    } else {
      k = DecodeHighClass(d, x, h, kDirectClasses + shift);
    }
    *bit_length = k + 1;
  }
  return DecodeSignAndLowBits<kRawLow>(d, m, k);
}

// Values known to lie in [0, n): fixed-length equiprobable code.
inline int BitsFor(uint64_t n) { return n <= 1 ? 0 : FloorLog2(n - 1) + 1; }

}  // namespace o3dgc

#endif  // O3DGC_SRC_ENTROPY_H_
