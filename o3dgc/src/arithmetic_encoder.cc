// Range encoder: carry propagation and termination (see arithmetic_coder.h).
#include "arithmetic_coder.h"

#include <algorithm>

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

void ArithmeticEncoder::Finish(size_t min_size) {
  // Emit the value v in [low, low + range) whose low `bits` bits are free: every value from v to
  // v + 2^bits - 1 lies in the interval, so the bytes below `bits` can be dropped and whatever the
  // decoder reads in their place (the raw stream, padding, zeros) decodes the same.
  int bits = 32;
  for (; bits > 0; --bits) {
    const uint64_t mask = (uint64_t(1) << bits) - 1;
    const uint64_t v = (low_ + mask) & ~mask;
    if (v + mask < low_ + range_) {
      low_ = v;
      break;
    }
  }
  for (int i = 0; i < 5; ++i) ShiftLow();  // the cached byte and the four bytes of v
  const size_t drop = std::min(size_t(bits / 8), out_->size() - start_);
  out_->resize(out_->size() - drop);
  if (raw_bits_ > 0) {
    raw_.push_back(uint8_t(raw_acc_ << (8 - raw_bits_)));
    raw_bits_ = 0;
  }
  const size_t size = out_->size() - start_ + raw_.size();
  if (size < min_size) out_->resize(out_->size() + (min_size - size), 0);
  // The raw stream is read from the end backwards: its first byte goes last.
  out_->insert(out_->end(), raw_.rbegin(), raw_.rend());
  raw_.clear();
}

}  // namespace o3dgc
