// Range encoder: carry propagation and termination (see arithmetic_coder.h).
#include "arithmetic_coder.h"

namespace o3dgc {

void ArithmeticEncoder::ShiftLow() {
  if (uint32_t(low_) < 0xFF000000u || (low_ >> 32) != 0) {
    const uint8_t carry = uint8_t(low_ >> 32);
    uint8_t temp = cache_;
    do {
      // The very first byte of a range code is always 0 (low + range <= 2^32 at the start), so it
      // is not written; the decoder starts with 4 bytes instead of 5.
      if (first_) {
        first_ = false;
      } else {
        out_->push_back(uint8_t(temp + carry));
      }
      temp = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = uint8_t(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void ArithmeticEncoder::Finish() {
  // Pick the value in [low, low + range) with the most trailing zero bits, emit it, then drop the
  // trailing zero bytes of the flush: the decoder reads zeros past the end of its buffer.
  for (int bits = 32; bits >= 0; --bits) {
    const uint64_t mask = (bits == 0) ? 0 : ((uint64_t(1) << bits) - 1);
    const uint64_t v = (low_ + mask) & ~mask;
    if (v >= low_ && v < low_ + range_) {
      low_ = v;
      break;
    }
  }
  const size_t before = out_->size();
  for (int i = 0; i < 5; ++i) ShiftLow();
  size_t keep_min = before > start_ ? before : start_;
  while (out_->size() > keep_min && out_->back() == 0) out_->pop_back();
}

}  // namespace o3dgc
