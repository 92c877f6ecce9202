// Test-side encoder for original Open3DGC streams: the encoding half of the FastAC-style range
// coder (as the original encoder ran it) and writers for the binary and ASCII sections, so tests
// can build small legacy streams in code.
#ifndef TESTS_O3DGC_LEGACY_TEST_ENCODER_H_
#define TESTS_O3DGC_LEGACY_TEST_ENCODER_H_

#include <cstdint>
#include <cstring>
#include <vector>

#include "legacy_arithmetic_decoder.h"
#include "legacy_stream_reader.h"

namespace legacy_test {

using namespace o3dgc;

// The encoding half of the coder, as the original encoder ran it (carry into written bytes,
// 1 or 2 final bytes).
class TestEncoder {
 public:
  void Encode(uint32_t bit, LegacyAdaptiveBitModel& m) {
    const uint32_t x = m.bit_0_prob * (length_ >> 13);
    if (bit == 0) {
      length_ = x;
      ++m.bit_0_count;
    } else {
      Move(x, length_ - x);
    }
    if (length_ < (1u << 24)) Renormalize();
    if (--m.bits_until_update == 0) m.Update();
  }
  void Encode(uint32_t bit, LegacyStaticBitModel& m) {
    const uint32_t x = m.bit_0_prob * (length_ >> 13);
    if (bit == 0) {
      length_ = x;
    } else {
      Move(x, length_ - x);
    }
    if (length_ < (1u << 24)) Renormalize();
  }
  void Encode(uint32_t s, LegacyAdaptiveDataModel& m) {
    if (s + 1 == m.symbols()) {
      const uint32_t x = m.Low(s) * (length_ >> 15);
      Move(x, length_ - x);
    } else {
      length_ >>= 15;
      const uint32_t x = m.Low(s) * length_;
      Move(x, m.Low(s + 1) * length_ - x);
    }
    if (length_ < (1u << 24)) Renormalize();
    m.Count(s);
  }
  void EncodeExpGolomb(uint32_t v, uint32_t k, LegacyStaticBitModel& bits,
                       LegacyAdaptiveBitModel& prefix) {
    while (v >= (1u << k)) {
      Encode(1, prefix);
      v -= 1u << k;
      ++k;
    }
    Encode(0, prefix);
    while (k--) Encode((v >> k) & 1, bits);
  }
  std::vector<uint8_t> Finish() {
    const uint32_t before = base_;
    if (length_ > 2 * (1u << 24)) {
      base_ += 1u << 24;
      length_ = 1u << 23;
    } else {
      base_ += 1u << 23;
      length_ = 1u << 15;
    }
    if (before > base_) Carry();
    Renormalize();
    return out_;
  }

 private:
  void Move(uint32_t x, uint32_t length) {
    const uint32_t before = base_;
    base_ += x;
    length_ = length;
    if (before > base_) Carry();
  }
  void Carry() {
    size_t p = out_.size();
    while (out_[--p] == 0xFF) out_[p] = 0;
    ++out_[p];
  }
  void Renormalize() {
    do {
      out_.push_back(uint8_t(base_ >> 24));
      base_ <<= 8;
    } while ((length_ <<= 8) < (1u << 24));
  }
  std::vector<uint8_t> out_;
  uint32_t base_ = 0, length_ = 0xFFFFFFFFu;
};

// Appends fields in the stream's encoding, as the original BinaryStream wrote them.
struct Writer {
  LegacyEncoding enc;
  std::vector<uint8_t> out;
  void U32(uint32_t v) {
    if (enc == LegacyEncoding::kBinary) {
      for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
    } else {
      for (int i = 0; i < 5; ++i) out.push_back(uint8_t((v >> (7 * i)) & 127));
    }
  }
  void PatchU32(size_t at, uint32_t v) {
    Writer w{enc, {}};
    w.U32(v);
    std::memcpy(&out[at], w.out.data(), w.out.size());
  }
  void F32(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    U32(bits);
  }
  void U8(uint8_t v) { out.push_back(v); }
  void AsciiUInt(uint64_t v) {
    if (v < 127) {
      out.push_back(uint8_t(v));
      return;
    }
    out.push_back(127);
    v -= 127;
    do {
      const uint8_t more = (v >> 6) > 0;
      out.push_back(uint8_t(((v & 63) << 1) | more));
      v >>= 6;
    } while (v);
  }
  void AsciiInt(int64_t v) { AsciiUInt(v < 0 ? uint64_t(-1 - 2 * v) : uint64_t(2 * v)); }
};

// TFAN symbol arrays as sections. Binary: [u32 bytes][u32 count][u32 offset][coded bytes].
enum class ArrayKind { kSigned, kUnsigned, kBits };

inline void WriteArray(Writer* w, ArrayKind kind, uint32_t m, const std::vector<int64_t>& v) {
  const size_t start = w->out.size();
  w->U32(0);
  w->U32(uint32_t(v.size()));
  if (w->enc == LegacyEncoding::kAscii) {
    if (kind == ArrayKind::kBits) {
      for (size_t i = 0; i < v.size(); i += 7) {
        uint8_t symbol = 0;
        for (size_t h = 0; h < 7 && i + h < v.size(); ++h) symbol |= uint8_t(v[i + h] << h);
        w->U8(symbol);
      }
    } else {
      for (int64_t x : v) kind == ArrayKind::kSigned ? w->AsciiInt(x) : w->AsciiUInt(uint64_t(x));
    }
    w->PatchU32(start, uint32_t(w->out.size() - start));
    return;
  }
  if (v.empty()) {
    w->PatchU32(start, 8);
    return;
  }
  int64_t offset = 0;
  if (kind != ArrayKind::kBits) {
    offset = kind == ArrayKind::kSigned ? 0 : v[0];
    for (int64_t x : v) offset = x < offset ? x : offset;
    w->U32(uint32_t(kind == ArrayKind::kSigned ? offset + 0x7FFFFFFF : offset));
  }
  TestEncoder enc;
  LegacyAdaptiveDataModel values;
  values.Init(kind == ArrayKind::kSigned ? m + 2 : m + 1);
  LegacyAdaptiveBitModel bit, prefix;
  LegacyStaticBitModel bits;
  for (int64_t x : v) {
    const uint32_t u = uint32_t(x - offset);
    if (kind == ArrayKind::kBits) {
      enc.Encode(u, bit);
    } else if (kind == ArrayKind::kUnsigned || u < m) {
      enc.Encode(u, values);
    } else {
      enc.Encode(m, values);
      enc.EncodeExpGolomb(u - m, 0, bits, prefix);
    }
  }
  const std::vector<uint8_t> coded = enc.Finish();
  w->out.insert(w->out.end(), coded.begin(), coded.end());
  w->PatchU32(start, uint32_t(w->out.size() - start));
}

}  // namespace legacy_test

#endif  // TESTS_O3DGC_LEGACY_TEST_ENCODER_H_
