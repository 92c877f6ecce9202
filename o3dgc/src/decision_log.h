// A record of coding decisions, replayed later into an ArithmeticEncoder.
//
// Why: an encoder that tries several position grids codes the same connectivity and seams for
// each; only the payload header in front of them differs. The range coder's output for a decision
// depends only on the coder's state and on the probability the model gave, so recording each
// decision with that probability (instead of the model) and replaying the record after each
// grid's header gives, byte for byte, the stream that coding the decisions there would have given,
// without running the connectivity coder (and holding its working arrays) once per grid.
//
// The bulk of the decisions, the gate outcomes, use one array of models (the gate contexts):
// registered with UseModels, such a decision is recorded as its model's index and its symbol (2
// bytes), and the replay updates copies of the models as the coding did (a model's state depends
// only on the symbols it saw).
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
  using Model = SymbolModelN<8>;

  // The models of `models` (up to kMaxModels, in their current state, which the replay starts
  // from) are recorded by index from here on. Once per log, before their first decision.
  void UseModels(const std::vector<Model>& models) {
    if (!models_.empty() || models.size() > kMaxModels) return;
    models_ = models;
    base_ = models.data();
  }

  // As ArithmeticEncoder::Encode: records the bit with the model's current probability, then
  // updates the model.
  void Encode(int bit, BitModel& m) {
    words_.push_back(uint16_t(kBit | (bit != 0)));
    words_.push_back(uint16_t(m.p0()));
    m.Update(bit);
  }
  // A registered model: its index and the symbol; else the symbol's interval (cumulative
  // frequencies below and up to it, in 1/2^16).
  template <int N>
  void Encode(int symbol, SymbolModelN<N>& m) {
    const size_t index = Index(&m);
    if (index < models_.size()) {
      words_.push_back(uint16_t(kIndexed | (index << 3) | uint32_t(symbol)));
    } else {
      const uint32_t lo = symbol ? m.cumulative(symbol - 1) : 0, hi = m.cumulative(symbol);
      words_.push_back(uint16_t(kInterval | (lo >> 16) << 1 | hi >> 16));
      words_.push_back(uint16_t(lo));
      words_.push_back(uint16_t(hi));
    }
    m.Update(symbol);
  }
  // As ArithmeticEncoder::EncodeBits; count <= 32.
  void EncodeBits(uint32_t value, int count) {
    words_.push_back(uint16_t(kBits | uint32_t(count)));
    words_.push_back(uint16_t(value >> 16));
    words_.push_back(uint16_t(value));
  }

  // Codes every recorded decision into `enc`, in order.
  void ReplayInto(ArithmeticEncoder* enc) const {
    std::vector<Model> models = models_;  // in the state the recording started from
    for (size_t i = 0; i < words_.size(); ++i) {
      const uint32_t w = words_[i];
      switch (w & kTagMask) {
        case kIndexed:
          enc->Encode(int(w & 7), models[(w & ~kTagMask) >> 3]);
          break;
        case kBit: {
          // A model whose mixed estimate is the recorded probability.
          BitModel m;
          m.slow = m.fast = words_[++i];
          enc->Encode(int(w & 1), m);
          break;
        }
        case kInterval: {
          // A model whose symbol 1 has the recorded interval (symbol 0 codes [0, hi) the same).
          const uint32_t lo = (w >> 1 & 1) << 16 | words_[i + 1];
          const uint32_t hi = (w & 1) << 16 | words_[i + 2];
          i += 2;
          Model m;
          m.slow[0] = uint16_t(lo / 2);
          m.fast[0] = uint16_t(lo - lo / 2);
          m.slow[1] = uint16_t(hi / 2);
          m.fast[1] = uint16_t(hi - hi / 2);
          enc->Encode(1, m);
          break;
        }
        default:
          enc->EncodeBits(uint32_t(words_[i + 1]) << 16 | words_[i + 2], int(w & ~kTagMask));
          i += 2;
          break;
      }
    }
  }

  // Once every decision is recorded: frees the spare capacity growth left (up to half).
  void ShrinkToFit() { words_.shrink_to_fit(); }
  size_t bytes() const { return words_.capacity() * sizeof(uint16_t); }

 private:
  // The top two bits of a record's first word say what it is: a registered model's index and
  // symbol (one word); a bit, then its probability (two); a symbol's interval, the ends' 17th bits
  // in the first word, their low 16 bits after (three); a count of equiprobable bits, then their
  // value (three).
  static constexpr uint32_t kTagMask = 0xC000u;
  static constexpr uint32_t kIndexed = 0;
  static constexpr uint32_t kBit = 0x4000u;
  static constexpr uint32_t kInterval = 0x8000u;
  static constexpr uint32_t kBits = 0xC000u;
  static constexpr size_t kMaxModels = size_t(1) << 11;  // 11 bits of index, 3 of symbol

  template <int N>
  size_t Index(const SymbolModelN<N>*) const {
    return models_.size();  // only 8-symbol models are registered
  }
  size_t Index(const Model* m) const {
    // Compared as integers: pointers into different arrays are not ordered.
    const uintptr_t p = reinterpret_cast<uintptr_t>(m), b = reinterpret_cast<uintptr_t>(base_);
    if (p < b || p >= b + models_.size() * sizeof(Model)) return models_.size();
    return (p - b) / sizeof(Model);
  }

  std::vector<uint16_t> words_;
  std::vector<Model> models_;    // the registered models as they were when registered
  const Model* base_ = nullptr;  // where the coder's registered models are
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_DECISION_LOG_H_
