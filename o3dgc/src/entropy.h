// Binarizations of integers on top of the adaptive binary arithmetic coder (encoder and decoder
// side by side so that the two stay mirror images).
//
// Unsigned values use an adaptive Exp-Golomb code: the prefix (bit length) is coded bit by bit
// with one model per position, the two most significant suffix bits with models conditioned on
// the length, the remaining suffix bits as equiprobable bits. Signed residuals add a zero flag and
// a sign. Callers pick the model set (the context) per value.
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

inline void EncodeEG(ArithmeticEncoder& e, EGModel& m, uint64_t u) {
  const uint64_t v = u + 1;
  const int k = FloorLog2(v);
  for (int i = 0; i < k; ++i) e.Encode(1, m.prefix[i]);
  if (k < kMaxEGPrefix) e.Encode(0, m.prefix[k]);
  if (k == 0) return;
  int top = int((v >> (k - 1)) & 1);
  e.Encode(top, m.suffix[k][0]);
  if (k == 1) return;
  e.Encode(int((v >> (k - 2)) & 1), m.suffix[k][1 + top]);
  int rest = k - 2;
  while (rest > 0) {
    const int n = rest > 24 ? 24 : rest;
    rest -= n;
    e.EncodeBits(uint32_t((v >> rest) & ((1u << n) - 1)), n);
  }
}

inline uint64_t DecodeEG(ArithmeticDecoder& d, EGModel& m) {
  int k = 0;
  while (k < kMaxEGPrefix && d.Decode(m.prefix[k])) ++k;
  if (k == 0) return 0;
  uint64_t v = 1;
  const int top = d.Decode(m.suffix[k][0]);
  v = (v << 1) | uint64_t(top);
  if (k > 1) {
    v = (v << 1) | uint64_t(d.Decode(m.suffix[k][1 + top]));
    int rest = k - 2;
    while (rest > 0) {
      const int n = rest > 24 ? 24 : rest;
      rest -= n;
      v = (v << n) | d.DecodeBits(n);
    }
  }
  return v - 1;
}

struct SignedModel {
  BitModel zero;
  BitModel sign;
  EGModel magnitude;
};

inline void EncodeSigned(ArithmeticEncoder& e, SignedModel& m, int64_t r) {
  e.Encode(r != 0, m.zero);
  if (r == 0) return;
  e.Encode(r < 0, m.sign);
  EncodeEG(e, m.magnitude, uint64_t(r < 0 ? -r : r) - 1);
}

inline int64_t DecodeSigned(ArithmeticDecoder& d, SignedModel& m) {
  if (!d.Decode(m.zero)) return 0;
  const int neg = d.Decode(m.sign);
  const int64_t mag = int64_t(DecodeEG(d, m.magnitude)) + 1;
  return neg ? -mag : mag;
}

// Values known to lie in [0, n): fixed-length equiprobable code.
inline int BitsFor(uint64_t n) { return n <= 1 ? 0 : FloorLog2(n - 1) + 1; }

}  // namespace o3dgc

#endif  // O3DGC_SRC_ENTROPY_H_
