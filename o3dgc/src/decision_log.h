// A record of coding decisions, replayed later into an ArithmeticEncoder.
//
// Why: an encoder that tries several position grids codes the same connectivity and seams for
// each; only the payload header in front of them differs. The range coder's output for a decision
// depends only on the coder's state and on the probability the model gave, so recording each
// decision with that probability (instead of the model) and replaying the record after each
// grid's header gives, byte for byte, the stream that coding the decisions there would have given,
// without running the connectivity coder (and holding its working arrays) once per grid.
//
// DecisionLog offers the encoding calls of ArithmeticEncoder that the connectivity and seam coders
// use (adaptive bits, multi-symbol decisions, equiprobable bits in the range code), so the same
// coder code can write to either (EncodeEG and friends are templates on the coder).
#ifndef O3DGC_SRC_DECISION_LOG_H_
#define O3DGC_SRC_DECISION_LOG_H_

#include <cstdint>
#include <vector>

#include "arithmetic_coder.h"

namespace o3dgc {

class DecisionLog {
 public:
  // As ArithmeticEncoder::Encode: records the bit with the model's current probability, then
  // updates the model.
  void Encode(int bit, BitModel& m) {
    words_.push_back(kBit | (uint32_t(bit != 0) << 16) | m.p0());
    m.Update(bit);
  }
  // Records the symbol's interval (cumulative frequencies below and up to it, in 1/2^16).
  template <int N>
  void Encode(int symbol, SymbolModelN<N>& m) {
    words_.push_back(kSymbol | (symbol ? m.cumulative(symbol - 1) : 0));
    words_.push_back(m.cumulative(symbol));
    m.Update(symbol);
  }
  // As ArithmeticEncoder::EncodeBits; count <= 32.
  void EncodeBits(uint32_t value, int count) {
    words_.push_back(kBits | uint32_t(count));
    words_.push_back(value);
  }

  // Codes every recorded decision into `enc`, in order.
  void ReplayInto(ArithmeticEncoder* enc) const {
    for (size_t i = 0; i < words_.size(); ++i) {
      const uint32_t w = words_[i];
      switch (w & kTagMask) {
        case kBit: {
          // A model whose mixed estimate is the recorded probability.
          BitModel m;
          m.slow = m.fast = uint16_t(w & 0xFFFFu);
          enc->Encode(int((w >> 16) & 1), m);
          break;
        }
        case kSymbol: {
          // A model whose symbol 1 has the recorded interval (symbol 0 codes [0, hi) the same).
          const uint32_t lo = w & ~kTagMask, hi = words_[++i];
          SymbolModelN<8> m;
          m.slow[0] = uint16_t(lo / 2);
          m.fast[0] = uint16_t(lo - lo / 2);
          m.slow[1] = uint16_t(hi / 2);
          m.fast[1] = uint16_t(hi - hi / 2);
          enc->Encode(1, m);
          break;
        }
        default:
          enc->EncodeBits(words_[i + 1], int(w & ~kTagMask));
          ++i;
          break;
      }
    }
  }

  // Once every decision is recorded: frees the spare capacity growth left (up to half).
  void ShrinkToFit() { words_.shrink_to_fit(); }
  size_t bytes() const { return words_.capacity() * sizeof(uint32_t); }

 private:
  // The top two bits of a record's first word say what it is.
  static constexpr uint32_t kTagMask = 0xC0000000u;
  static constexpr uint32_t kBit = 0;
  static constexpr uint32_t kSymbol = 0x40000000u;
  static constexpr uint32_t kBits = 0x80000000u;
  std::vector<uint32_t> words_;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_DECISION_LOG_H_
