// The arithmetic decoder of original Open3DGC binary streams: a 32-bit range coder with
// multiplicative adaptive models in the style of A. Said's FastAC (the coder the original
// encoder used). Decoded values depend on every detail of the model adaptation (counts, update
// periods, rescaling), so these classes reproduce that arithmetic exactly:
//  - bit models: a probability of 0 in 1/8192, re-estimated from counts every `update_cycle`
//    bits; the cycle starts at 4 and grows by 5/4 up to 64; counts halve above 8192;
//  - data models (2..2048 symbols): a cumulative distribution in 1/32768, re-estimated every
//    cycle (starting at (n + 6) / 2 symbols, growing by 5/4 up to 8 (n + 6)); counts halve above
//    32768;
//  - interval: 32 bits, renormalised a byte at a time when it falls below 2^24; the code value
//    starts with the first 4 bytes of the section.
// The decoder reads its section [begin, end) of the stream; like the original it then goes on
// reading the stream's following bytes (a valid section needs at most 3 of them), and zeros past
// the end of the stream. More than kMaxOverrun bytes read past `end` mark it failed.
#ifndef O3DGC_SRC_LEGACY_ARITHMETIC_DECODER_H_
#define O3DGC_SRC_LEGACY_ARITHMETIC_DECODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace o3dgc {

struct LegacyStaticBitModel {
  uint32_t bit_0_prob = 1u << 12;  // p(0) = 1/2 in 1/8192
};

struct LegacyAdaptiveBitModel {
  uint32_t update_cycle = 4;
  uint32_t bits_until_update = 4;
  uint32_t bit_0_prob = 1u << 12;
  uint32_t bit_0_count = 1;
  uint32_t bit_count = 2;
  void Update();
};

class LegacyAdaptiveDataModel {
 public:
  static constexpr uint32_t kMaxSymbols = 2048;
  // false (and no model) outside 2..kMaxSymbols; the original aborts there.
  bool Init(uint32_t symbols);
  uint32_t symbols() const { return symbols_; }
  // Cumulative probability of the symbols below `s`, in 1/32768 (distribution[0] = 0).
  uint32_t Low(uint32_t s) const { return distribution_[s]; }
  // Counts an occurrence of `s`; re-estimates the distribution when due.
  void Count(uint32_t s) {
    ++count_[s];
    if (--symbols_until_update_ == 0) Update();
  }

 private:
  void Update();

  uint32_t symbols_ = 0;
  std::vector<uint32_t> distribution_;  // cumulative, in 1/32768
  std::vector<uint32_t> count_;
  uint32_t total_count_ = 0;
  uint32_t update_cycle_ = 0;
  uint32_t symbols_until_update_ = 0;
};

class LegacyArithmeticDecoder {
 public:
  static constexpr size_t kMaxOverrun = 8;

  // Decodes the section [begin, end) of data[0, stream_end); begin <= end <= stream_end.
  LegacyArithmeticDecoder(const uint8_t* data, size_t begin, size_t end, size_t stream_end);

  uint32_t Decode(LegacyStaticBitModel& m);
  uint32_t Decode(LegacyAdaptiveBitModel& m);
  uint32_t Decode(LegacyAdaptiveDataModel& m);
  // Exp-Golomb code of order k: a unary prefix of adaptive bits, then static bits. false (value
  // unchanged) if the prefix would carry the order past 31.
  bool DecodeExpGolomb(uint32_t k, LegacyStaticBitModel& bits, LegacyAdaptiveBitModel& prefix,
                       uint32_t* value);

  bool failed() const { return pos_ > end_ + kMaxOverrun; }

 private:
  uint8_t NextByte() {
    const size_t p = pos_++;
    return p < stream_end_ ? data_[p] : 0;
  }
  void Renormalize() {
    do {
      value_ = (value_ << 8) | NextByte();
    } while ((length_ <<= 8) < (1u << 24));
  }

  const uint8_t* data_;
  size_t pos_;
  size_t end_;
  size_t stream_end_;
  uint32_t value_ = 0;
  uint32_t length_ = 0xFFFFFFFFu;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_LEGACY_ARITHMETIC_DECODER_H_
