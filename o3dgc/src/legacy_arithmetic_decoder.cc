// FastAC-compatible arithmetic decoding (see legacy_arithmetic_decoder.h).
#include "legacy_arithmetic_decoder.h"

namespace o3dgc {
namespace {

constexpr uint32_t kMinLength = 1u << 24;
constexpr uint32_t kBitShift = 13;  // bit probabilities in 1/8192
constexpr uint32_t kBitMaxCount = 1u << kBitShift;
constexpr uint32_t kDataShift = 15;  // distributions in 1/32768
constexpr uint32_t kDataMaxCount = 1u << kDataShift;

}  // namespace

void LegacyAdaptiveBitModel::Update() {
  if ((bit_count += update_cycle) > kBitMaxCount) {
    bit_count = (bit_count + 1) >> 1;
    bit_0_count = (bit_0_count + 1) >> 1;
    if (bit_0_count == bit_count) ++bit_count;
  }
  const uint32_t scale = 0x80000000u / bit_count;
  bit_0_prob = (bit_0_count * scale) >> (31 - kBitShift);
  update_cycle = (5 * update_cycle) >> 2;
  if (update_cycle > 64) update_cycle = 64;
  bits_until_update = update_cycle;
}

bool LegacyAdaptiveDataModel::Init(uint32_t symbols) {
  if (symbols < 2 || symbols > kMaxSymbols) return false;
  symbols_ = symbols;
  distribution_.assign(symbols, 0);
  count_.assign(symbols, 1);
  total_count_ = 0;
  update_cycle_ = symbols;
  Update();
  symbols_until_update_ = update_cycle_ = (symbols + 6) >> 1;
  return true;
}

void LegacyAdaptiveDataModel::Update() {
  if ((total_count_ += update_cycle_) > kDataMaxCount) {
    total_count_ = 0;
    for (uint32_t& c : count_) total_count_ += (c = (c + 1) >> 1);
  }
  const uint32_t scale = 0x80000000u / total_count_;
  uint32_t sum = 0;
  for (uint32_t k = 0; k < symbols_; ++k) {
    distribution_[k] = (scale * sum) >> (31 - kDataShift);
    sum += count_[k];
  }
  update_cycle_ = (5 * update_cycle_) >> 2;
  const uint32_t max_cycle = (symbols_ + 6) << 3;
  if (update_cycle_ > max_cycle) update_cycle_ = max_cycle;
  symbols_until_update_ = update_cycle_;
}

LegacyArithmeticDecoder::LegacyArithmeticDecoder(const uint8_t* data, size_t begin, size_t end,
                                                 size_t stream_end)
    : data_(data), pos_(begin), end_(end), stream_end_(stream_end) {
  for (int i = 0; i < 4; ++i) value_ = (value_ << 8) | NextByte();
}

uint32_t LegacyArithmeticDecoder::Decode(LegacyStaticBitModel& m) {
  const uint32_t x = m.bit_0_prob * (length_ >> kBitShift);
  const uint32_t bit = value_ >= x;
  if (bit == 0) {
    length_ = x;
  } else {
    value_ -= x;
    length_ -= x;
  }
  if (length_ < kMinLength) Renormalize();
  return bit;
}

uint32_t LegacyArithmeticDecoder::Decode(LegacyAdaptiveBitModel& m) {
  const uint32_t x = m.bit_0_prob * (length_ >> kBitShift);
  const uint32_t bit = value_ >= x;
  if (bit == 0) {
    length_ = x;
    ++m.bit_0_count;
  } else {
    value_ -= x;
    length_ -= x;
  }
  if (length_ < kMinLength) Renormalize();
  if (--m.bits_until_update == 0) m.Update();
  return bit;
}

uint32_t LegacyArithmeticDecoder::Decode(LegacyAdaptiveDataModel& m) {
  // The symbol s with distribution[s] <= value / (length / 2^15) < distribution[s + 1]; the last
  // symbol takes the rest of the interval (the rounding slack).
  const uint32_t full = length_;
  length_ >>= kDataShift;
  const uint32_t dv = value_ / length_;
  uint32_t lo = 0, hi = m.symbols();  // Low(lo) <= dv < Low(hi) (Low(symbols) virtual)
  while (hi - lo > 1) {
    const uint32_t mid = (lo + hi) >> 1;
    if (m.Low(mid) > dv) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  const uint32_t x = m.Low(lo) * length_;
  const uint32_t y = lo + 1 < m.symbols() ? m.Low(lo + 1) * length_ : full;
  value_ -= x;
  length_ = y - x;
  if (length_ < kMinLength) Renormalize();
  m.Count(lo);
  return lo;
}

bool LegacyArithmeticDecoder::DecodeExpGolomb(uint32_t k, LegacyStaticBitModel& bits,
                                              LegacyAdaptiveBitModel& prefix, uint32_t* value) {
  uint64_t v = 0;
  while (Decode(prefix)) {
    if (k >= 31) return false;  // the original shifts 1 << k in an int
    v += uint64_t(1) << k;
    ++k;
  }
  uint64_t low = 0;
  while (k--) {
    if (Decode(bits)) low |= uint64_t(1) << k;
  }
  v += low;
  if (v > 0xFFFFFFFFu) return false;
  *value = uint32_t(v);
  return true;
}

}  // namespace o3dgc
