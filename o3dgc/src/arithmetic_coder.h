// Adaptive binary arithmetic (range) coding: the entropy coder of every part of an o3dgc stream.
//
// A carry-propagating range coder over 32-bit ranges with 16-bit adaptive probabilities. Each
// BitModel mixes two estimates: a slow one that adapts quickly at first (count-based rate) and
// then settles to a 1/128 rate, and a fast one (rate 1/8) that follows local runs; probabilities
// are clamped to [kMinProb, 65536 - kMinProb] so no decision costs less than ~0.001 bits. The decoder treats bytes past the end of its buffer as zeros and counts them; more than
// kMaxOverrun such bytes marks the decoder as failed (the caller checks failed()).
#ifndef O3DGC_SRC_ARITHMETIC_CODER_H_
#define O3DGC_SRC_ARITHMETIC_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace o3dgc {

struct BitModel {
  uint16_t fast = 32768;  // probabilities of a 0, in 1/65536
  uint16_t slow = 32768;
  uint8_t n = 0;          // observations so far (saturating at sizeof(kShift))

  static constexpr int32_t kMinProb = 48;
  static constexpr int kSlowShift = 7;
  static constexpr int kFastShift = 3;

  // The mixed estimate, clamped so that no decision costs less than ~0.001 bits.
  uint32_t p0() const {
    const uint32_t p = (uint32_t(slow) + fast + 1) >> 1;
    return p < uint32_t(kMinProb) ? uint32_t(kMinProb)
                                  : (p > uint32_t(65536 - kMinProb) ? uint32_t(65536 - kMinProb) : p);
  }
  // Moves p by (target - p) / 2^shift rounded towards the target; stays within [0, 65535].
  static uint32_t Step(uint32_t p, int bit, int shift) {
    return bit ? p - ((p + (1u << shift) - 1) >> shift) : p + ((65535 - p + (1u << shift) - 1) >> shift);
  }
  void Update(int bit) {
    static constexpr uint8_t kShift[] = {2, 2, 3, 3, 3, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5,
                                         6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6};
    if (n < sizeof(kShift)) {
      const int shift = kShift[n++];
      slow = uint16_t(Step(slow, bit, shift));
      fast = uint16_t(Step(fast, bit, shift < kFastShift ? shift : kFastShift));
    } else {
      slow = uint16_t(Step(slow, bit, kSlowShift));
      fast = uint16_t(Step(fast, bit, kFastShift));
    }
  }
};

class ArithmeticEncoder {
 public:
  explicit ArithmeticEncoder(std::vector<uint8_t>* out) : out_(out) {}

  void Encode(int bit, BitModel& m) {
    const uint32_t bound = uint32_t((uint64_t(range_) * m.p0()) >> 16);
    if (bit) {
      low_ += bound;
      range_ -= bound;
    } else {
      range_ = bound;
    }
    m.Update(bit);
    Normalize();
  }
  // Equiprobable bits, most significant first; count <= 32.
  void EncodeBits(uint32_t value, int count) {
    for (int i = count - 1; i >= 0; --i) {
      range_ >>= 1;
      if ((value >> i) & 1) low_ += range_;
      Normalize();
    }
  }
  // Terminates the code: after this the output holds every byte needed by the decoder.
  void Finish();
  // Bytes produced so far, counting the pending ones (an estimate of the position while coding).
  size_t BytesSoFar() const { return out_->size() - start_ + cache_size_; }

 private:
  void Normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  void ShiftLow();

  std::vector<uint8_t>* out_;
  size_t start_ = out_->size();
  uint64_t low_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;
  uint64_t cache_size_ = 1;
  bool first_ = true;
};

class ArithmeticDecoder {
 public:
  static constexpr size_t kMaxOverrun = 8;

  ArithmeticDecoder(const uint8_t* data, size_t size) : data_(data), size_(size) {
    for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | NextByte();
  }

  int Decode(BitModel& m) {
    const uint32_t bound = uint32_t((uint64_t(range_) * m.p0()) >> 16);
    int bit;
    if (code_ < bound) {
      range_ = bound;
      bit = 0;
    } else {
      code_ -= bound;
      range_ -= bound;
      bit = 1;
    }
    m.Update(bit);
    Normalize();
    return bit;
  }
  uint32_t DecodeBits(int count) {
    uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
      range_ >>= 1;
      int bit = 0;
      if (code_ >= range_) {
        code_ -= range_;
        bit = 1;
      }
      v = (v << 1) | uint32_t(bit);
      Normalize();
    }
    return v;
  }
  bool failed() const { return pos_ > size_ + kMaxOverrun; }
  size_t BytesConsumed() const { return pos_ < size_ ? pos_ : size_; }
  size_t size() const { return size_; }

 private:
  uint8_t NextByte() { return pos_ < size_ ? data_[pos_++] : (++pos_, uint8_t(0)); }
  void Normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      code_ = (code_ << 8) | NextByte();
    }
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  uint32_t code_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_ARITHMETIC_CODER_H_
