// Adaptive arithmetic (range) coding: the entropy coder of every part of an o3dgc stream.
//
// A carry-propagating range coder over 32-bit ranges with two kinds of adaptive models:
//  - BitModel, binary: 16-bit probabilities mixing two estimates, a slow one that adapts quickly at
//    first (count-based rate) and then settles to a 1/128 rate, and a fast one (rate 1/8) that
//    follows local runs; probabilities are clamped to [kMinProb, 65536 - kMinProb] so no decision
//    costs less than ~0.001 bits;
//  - SymbolModelN, 8 (16, 32) symbols in one decision (magnitude classes of residuals, gate
//    outcomes): the same two-rate idea on cumulative frequencies. One multi-symbol decision
//    replaces the 3-6 dependent binary decisions of a unary or tree binarization, which is what
//    bounds decoding speed.
// Raw (equiprobable) bits of the residuals go to a separate bit stream stored after the range code
// and read backwards from the end of the payload, so reading them costs a shift instead of a coder
// step. The range code is terminated so that whatever follows it decodes the same. The decoder
// treats bytes past the end of its buffer as zeros and counts them; more than kMaxOverrun such
// bytes, on either stream, marks it as failed (the caller checks failed()).
#ifndef O3DGC_SRC_ARITHMETIC_CODER_H_
#define O3DGC_SRC_ARITHMETIC_CODER_H_

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__SSE2__) && !defined(O3DGC_NO_SIMD)
#include <emmintrin.h>
#endif
#if defined(__SSE2__) && !defined(O3DGC_NO_SIMD) && !defined(__wasm__)
#define O3DGC_SCALED_SEARCH_SIMD 1
#else
#define O3DGC_SCALED_SEARCH_SIMD 0
#endif

// Hot coder paths must inline into the coding loops, so that the coder's state can stay in
// registers there; rare paths stay out of line so that the hot ones stay small.
#if defined(__GNUC__) || defined(__clang__)
#define O3DGC_INLINE inline __attribute__((always_inline))
#define O3DGC_NOINLINE __attribute__((noinline))
#define O3DGC_LIKELY(x) __builtin_expect(!!(x), 1)
#define O3DGC_UNLIKELY(x) __builtin_expect(!!(x), 0)
#define O3DGC_PREFETCH(p) __builtin_prefetch(p)
#else
#define O3DGC_INLINE inline
#define O3DGC_NOINLINE
#define O3DGC_LIKELY(x) (x)
#define O3DGC_UNLIKELY(x) (x)
#define O3DGC_PREFETCH(p) ((void)(p))
#endif

// Decoder code that runs once per stream or only for rare stream features (keep_order, groups) is
// compiled for size in the WebAssembly decoder, whose download is bounded, as the sources of other
// stream kinds are (web/CMakeLists.txt); native builds and the hot paths are unaffected.
#if defined(__wasm__) && defined(__clang__)
#define O3DGC_WASM_MINSIZE __attribute__((minsize, noinline))
#else
#define O3DGC_WASM_MINSIZE
#endif

namespace o3dgc {

struct BitModel {
  uint16_t fast = 32768;  // probabilities of a 0, in 1/65536, within [kMinProb, 65536 - kMinProb]
  uint16_t slow = 32768;
  uint8_t n = 0;  // observations so far (saturating at kWarmUp)

  static constexpr int32_t kMinProb = 48;  // no decision costs less than ~0.001 bits
  static constexpr int kSlowShift = 7;
  static constexpr int kFastShift = 3;

  // The mixed estimate; within [kMinProb, 65536 - kMinProb] since both estimates are.
  uint32_t p0() const { return (uint32_t(slow) + fast + 1) >> 1; }
  // Moves p by 1/2^shift of the way to 65536 - kMinProb after a 0 (`zero` all ones) or to
  // kMinProb after a 1, rounded away from p (an arithmetic shift floors; adding 2^shift - 1 first
  // makes the upward step round up), so p never leaves [kMinProb, 65536 - kMinProb]. Branch-free.
  static uint32_t Step(uint32_t p, int32_t zero, int shift) {
    const int32_t d = kMinProb + ((65536 - 2 * kMinProb + (1 << shift) - 1) & zero) - int32_t(p);
    return uint32_t(int32_t(p) + (d >> shift));
  }
  // Adaptation: the slow estimate starts fast (count-based rate, kWarmUp observations) and settles
  // at 1/2^kSlowShift; the fast one uses min(rate, 1/2^kFastShift). Settled models (the hot ones)
  // take the constant-shift path.
  static constexpr int kWarmUp = 40;
  O3DGC_INLINE void Update(int bit) {
    if (O3DGC_UNLIKELY(n < kWarmUp)) {
      WarmUpdate(bit);
      return;
    }
    const int32_t zero = bit - 1;
    slow = uint16_t(Step(slow, zero, kSlowShift));
    fast = uint16_t(Step(fast, zero, kFastShift));
  }
  // The first kWarmUp updates, out of line so that the settled path stays small.
  O3DGC_NOINLINE void WarmUpdate(int bit) {
    static constexpr uint8_t kSlow[kWarmUp] = {2, 2, 3, 3, 3, 4, 4, 4, 4, 4, 5, 5, 5, 5,
                                               5, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 6,
                                               6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6};
    const int32_t zero = bit - 1;
    const int s = kSlow[n++];
    slow = uint16_t(Step(slow, zero, s));
    fast = uint16_t(Step(fast, zero, s < kFastShift ? s : kFastShift));
  }
};

// An adaptive distribution over kSymbols symbols (8, 16 or 32). Two cumulative frequency tables
// (total 2^15 each; entry i is the frequency of the symbols <= i) move towards the observed symbol,
// the slow one at a count-based rate settling at 1/2^kSlowShift, the fast one at min(that,
// 1/2^kFastShift); the coder uses their sum (total 2^16). Every symbol keeps at least kMinFreq in
// each table (the targets keep it and rounding cannot lose it), so every symbol stays codable. The
// tables are updated 8 lanes at a time (SSE2 where available; the scalar code computes the same
// values).
template <int N>
struct alignas(16) SymbolModelN {
  static_assert(N == 8 || N == 16 || N == 32, "alphabet of 8, 16 or 32 symbols");
  static constexpr int kSymbols = N;
  static constexpr int kMinFreq = 4;
  static constexpr int kSlowShift = 8;
  static constexpr int kFastShift = 3;
  static constexpr int kTotal = 1 << 15;

  uint16_t slow[kSymbols];  // entry kSymbols - 1 is the total and never changes
  uint16_t fast[kSymbols];
  // Observations so far (saturating at kRates - 1). Not a char type: a char store may alias
  // anything, which would make the compiler reload every pointer after each decision.
  uint16_t n = 0;

  SymbolModelN() {
    for (int i = 0; i < kSymbols; ++i) slow[i] = fast[i] = uint16_t((i + 1) * (kTotal / kSymbols));
  }
  // A model of which only the first `used` symbols are expected: they share the range evenly, the
  // others start at the minimum frequency.
  explicit SymbolModelN(int used) {
    const int rest = (kSymbols - used) * kMinFreq;
    for (int i = 0; i < kSymbols; ++i) {
      slow[i] = fast[i] = uint16_t(i < used ? (i + 1) * ((kTotal - rest) / used)
                                            : kTotal - (kSymbols - 1 - i) * kMinFreq);
    }
  }
  // Frequency of the symbols <= i (i < kSymbols) in 1/2^16.
  uint32_t cumulative(int i) const { return uint32_t(slow[i]) + fast[i]; }
  // Settled models (n == kRates - 1, the hot ones) move at the constant rates kSlowShift and
  // kFastShift, with immediate shifts and no table lookup; the first kRates - 1 observations take
  // the out-of-line count-based path (the same values: Rate(kRates - 1) == kSlowShift).
  O3DGC_INLINE void Update(int symbol) {
    if (O3DGC_LIKELY(n == kRates - 1)) {
      Move(symbol, kSlowShift, kFastShift);  // inlined: the constant rates become immediate shifts
    } else {
      WarmUpdate(symbol);
    }
  }
  O3DGC_NOINLINE void WarmUpdate(int symbol);
  // Moves both tables towards the targets of `symbol` at 1/2^rate and 1/2^fast_rate.
  O3DGC_INLINE void Move(int symbol, int rate, int fast_rate);
  // The symbol whose interval holds `code` (< range) for a range r * 2^16: the number of entries
  // i < kSymbols - 1 with r * cumulative(i) <= code, i.e. with cumulative(i) <= code / r. Its
  // interval is [*lo, *hi) (in 1/2^16).
  int Find(uint32_t r, uint32_t code, uint32_t* lo, uint32_t* hi) const;
  // The same symbol, with its interval scaled by r: [*lo, *hi) = r * [cumulative(s - 1),
  // cumulative(s)) (r * 2^16 for the last symbol's end). No division: the decoder's symbol search
  // is on the dependency chain from one decision to the next, and r * cumulative(i) <= code is
  // cumulative(i) <= code / r without the divider's latency.
  O3DGC_INLINE int FindScaled(uint32_t r, uint32_t code, uint32_t* lo, uint32_t* hi) const;
  int Find(uint32_t r, uint32_t code) const {
    uint32_t lo, hi;
    return Find(r, code, &lo, &hi);
  }

  // Slow rate by observation count: 1/4 at first, then 1/8, 1/16, ... down to 1/2^kSlowShift
  // after 126 observations.
  static constexpr int kRates = 128;
  static constexpr uint8_t Rate(int n) {
    return uint8_t(2 + (n > 2) + (n > 6) + (n > 14) + (n > 30) + (n > 62) + (n > 126));
  }
  static_assert(Rate(kRates - 1) == kSlowShift, "a settled model moves at the slow rate");
  // Targets after observing s: entry i moves to (i + 1) * kMinFreq below s and to
  // kTotal - (kSymbols - 1 - i) * kMinFreq from s on (the last entry, the total, stays).
  static constexpr uint16_t Target(int s, int i) {
    return uint16_t(i < s ? (i + 1) * kMinFreq : kTotal - (kSymbols - 1 - i) * kMinFreq);
  }
};
using SymbolModel = SymbolModelN<16>;

namespace symbol_tables {
template <int N>
struct Tables {
  uint8_t rate[SymbolModelN<N>::kRates];
  alignas(16) uint16_t target[N][N];
  constexpr Tables() : rate(), target() {
    for (int n = 0; n < SymbolModelN<N>::kRates; ++n) rate[n] = SymbolModelN<N>::Rate(n);
    for (int s = 0; s < N; ++s) {
      for (int i = 0; i < N; ++i) target[s][i] = SymbolModelN<N>::Target(s, i);
    }
  }
};
template <int N>
inline constexpr Tables<N> kTables{};
}  // namespace symbol_tables

#if defined(__SSE2__) && !defined(O3DGC_NO_SIMD)
template <int N>
O3DGC_INLINE void SymbolModelN<N>::Move(int symbol, int rate, int fast_rate) {
  // 16-bit lanes: differences to the targets stay within +-2^15.
  const __m128i* t = reinterpret_cast<const __m128i*>(symbol_tables::kTables<N>.target[symbol]);
  const __m128i rs = _mm_cvtsi32_si128(rate), rf = _mm_cvtsi32_si128(fast_rate);
  __m128i* sp = reinterpret_cast<__m128i*>(slow);
  __m128i* fp = reinterpret_cast<__m128i*>(fast);
  for (int v = 0; v < N / 8; ++v) {
    const __m128i tv = _mm_load_si128(t + v), sv = _mm_load_si128(sp + v),
                  fv = _mm_load_si128(fp + v);
    _mm_store_si128(sp + v, _mm_add_epi16(sv, _mm_sra_epi16(_mm_sub_epi16(tv, sv), rs)));
    _mm_store_si128(fp + v, _mm_add_epi16(fv, _mm_sra_epi16(_mm_sub_epi16(tv, fv), rf)));
  }
}

template <int N>
O3DGC_INLINE int SymbolModelN<N>::Find(uint32_t r, uint32_t code, uint32_t* lo,
                                       uint32_t* hi) const {
  // Compare the 16-bit cumulative sums (the last lane wraps to 0 and is masked off) with code / r:
  // the lanes at or below it form a prefix, whose length is the symbol. The sums are kept, after a
  // zero, for the interval's ends.
  uint32_t q = code / r;
  q = q < 0xFFFFu ? q : 0xFFFFu;  // larger only in a corrupt stream
  const __m128i* sp = reinterpret_cast<const __m128i*>(slow);
  const __m128i* fp = reinterpret_cast<const __m128i*>(fast);
  const __m128i qv = _mm_set1_epi16(short(q)), zero = _mm_setzero_si128();
  __m128i le[N / 8];
  uint16_t cum[N + 8];
  cum[7] = 0;
  for (int v = 0; v < N / 8; ++v) {
    const __m128i c = _mm_add_epi16(_mm_load_si128(sp + v), _mm_load_si128(fp + v));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(cum + 8 + 8 * v), c);
    le[v] = _mm_cmpeq_epi16(_mm_subs_epu16(c, qv), zero);
  }
  uint32_t at_or_below;
  if (N == 8) {
    at_or_below = uint32_t(_mm_movemask_epi8(_mm_packs_epi16(le[0], zero)));
  } else {
    at_or_below = uint32_t(_mm_movemask_epi8(_mm_packs_epi16(le[0], le[N / 8 > 1 ? 1 : 0])));
    if (N == 32) {
      at_or_below |=
          uint32_t(_mm_movemask_epi8(_mm_packs_epi16(le[N / 8 > 2 ? 2 : 0], le[N / 8 > 3 ? 3 : 0])))
          << 16;
    }
  }
  at_or_below &= uint32_t((uint64_t(1) << (N - 1)) - 1);
  const int symbol = __builtin_ctz(~at_or_below);
  *lo = cum[7 + symbol];
  *hi = ((uint32_t(cum[8 + symbol]) - 1) & 0xFFFFu) + 1;  // the total, 2^16, wrapped to 0
  return symbol;
}
#if O3DGC_SCALED_SEARCH_SIMD
template <int N>
O3DGC_INLINE int SymbolModelN<N>::FindScaled(uint32_t r, uint32_t code, uint32_t* lo,
                                             uint32_t* hi) const {
  // 32-bit products r * cumulative(i) from the 16-bit halves (entries below the last are below
  // 2^16, so each product is below 2^32), compared with code as signed numbers after flipping the
  // top bits. The products are kept, after a zero, for the interval's ends.
  const __m128i* sp = reinterpret_cast<const __m128i*>(slow);
  const __m128i* fp = reinterpret_cast<const __m128i*>(fast);
  const __m128i rv = _mm_set1_epi16(short(r));
  const __m128i flip = _mm_set1_epi32(int(0x80000000u));
  const __m128i cv = _mm_set1_epi32(int(code ^ 0x80000000u));
  alignas(16) uint32_t prod[N + 4];
  prod[3] = 0;
  __m128i gt[N / 4];
  for (int v = 0; v < N / 8; ++v) {
    const __m128i c = _mm_add_epi16(_mm_load_si128(sp + v), _mm_load_si128(fp + v));
    const __m128i pl = _mm_mullo_epi16(c, rv), ph = _mm_mulhi_epu16(c, rv);
    const __m128i p0 = _mm_unpacklo_epi16(pl, ph), p1 = _mm_unpackhi_epi16(pl, ph);
    _mm_store_si128(reinterpret_cast<__m128i*>(prod + 4 + 8 * v), p0);
    _mm_store_si128(reinterpret_cast<__m128i*>(prod + 8 + 8 * v), p1);
    gt[2 * v] = _mm_cmpgt_epi32(_mm_xor_si128(p0, flip), cv);
    gt[2 * v + 1] = _mm_cmpgt_epi32(_mm_xor_si128(p1, flip), cv);
  }
  prod[N + 3] = r << 16;  // the total, 2^16, wrapped to 0 in its lane
  uint32_t above = 0;
  for (int v = 0; v < N / 8; ++v) {
    above |= uint32_t(_mm_movemask_epi8(
                 _mm_packs_epi16(_mm_packs_epi32(gt[2 * v], gt[2 * v + 1]), _mm_setzero_si128())))
             << (8 * v);
  }
  // Entries i < N - 1 with r * cumulative(i) <= code form a prefix; the last entry counts as above.
  above |= uint32_t(1) << (N - 1);
  const int symbol = __builtin_ctz(above);
  *lo = prod[3 + symbol];
  *hi = prod[4 + symbol];
  return symbol;
}
#endif  // O3DGC_SCALED_SEARCH_SIMD
#else
template <int N>
O3DGC_INLINE void SymbolModelN<N>::Move(int symbol, int rate, int fast_rate) {
  const uint16_t* t = symbol_tables::kTables<N>.target[symbol];
  for (int i = 0; i < kSymbols - 1; ++i) {
    slow[i] = uint16_t(slow[i] + ((int32_t(t[i]) - slow[i]) >> rate));
    fast[i] = uint16_t(fast[i] + ((int32_t(t[i]) - fast[i]) >> fast_rate));
  }
}

template <int N>
O3DGC_INLINE int SymbolModelN<N>::Find(uint32_t r, uint32_t code, uint32_t* lo,
                                       uint32_t* hi) const {
  uint32_t q = code / r;
  q = q < 0xFFFFu ? q : 0xFFFFu;
  int symbol = 0;
  for (int i = 0; i < kSymbols - 1; ++i) symbol += cumulative(i) <= q;
  *lo = symbol ? cumulative(symbol - 1) : 0;
  *hi = cumulative(symbol);
  return symbol;
}
#endif

// Without SSE2, and in WebAssembly (where the SIMD search's code weighs more in the download than
// it saves in time), the scaled search is the search with the division.
#if !O3DGC_SCALED_SEARCH_SIMD
template <int N>
O3DGC_INLINE int SymbolModelN<N>::FindScaled(uint32_t r, uint32_t code, uint32_t* lo,
                                             uint32_t* hi) const {
  uint32_t l, h;
  const int symbol = Find(r, code, &l, &h);
  *lo = r * l;
  *hi = r * h;
  return symbol;
}
#endif

// The first kRates - 1 observations: the slow rate from the observation count.
template <int N>
O3DGC_NOINLINE void SymbolModelN<N>::WarmUpdate(int symbol) {
  const int rate = symbol_tables::kTables<N>.rate[n];
  ++n;
  Move(symbol, rate, rate < kFastShift ? rate : kFastShift);
}

class ArithmeticEncoder {
 public:
  explicit ArithmeticEncoder(std::vector<uint8_t>* out) : out_(out) {}

  O3DGC_INLINE void Encode(int bit, BitModel& m) {
    const uint32_t bound = uint32_t((uint64_t(range_) * m.p0()) >> 16);
    const uint32_t one = 0u - uint32_t(bit != 0);  // masks: the bits are unpredictable
    low_ += bound & one;
    range_ = bound ^ ((bound ^ (range_ - bound)) & one);
    m.Update(bit);
    Normalize();
  }
  template <int N>
  O3DGC_INLINE void Encode(int symbol, SymbolModelN<N>& m) {
    const uint32_t r = range_ >> 16;
    const uint32_t lo = symbol ? r * m.cumulative(symbol - 1) : 0;
    const uint32_t hi = r * m.cumulative(symbol);
    low_ += lo;
    range_ = hi - lo;
    m.Update(symbol);
    Normalize();
  }
  // Equiprobable bits in the range code, most significant first; count <= 32.
  void EncodeBits(uint32_t value, int count) {
    for (int i = count - 1; i >= 0; --i) {
      range_ >>= 1;
      if ((value >> i) & 1) low_ += range_;
      Normalize();
    }
  }
  // Equiprobable bits in the raw bit stream, most significant first; 0 <= count <= 32.
  O3DGC_INLINE void EncodeRaw(uint32_t value, int count) {
    if (count == 0) return;
    raw_acc_ = (raw_acc_ << count) | (value & (0xFFFFFFFFu >> (32 - count)));
    raw_bits_ += count;
    while (raw_bits_ >= 8) {
      raw_bits_ -= 8;
      raw_.push_back(uint8_t(raw_acc_ >> raw_bits_));
    }
  }
  // Terminates the code and appends the raw bit stream; zero bytes are inserted between the two so
  // that the payload (the bytes written since construction) is at least `min_size` bytes long.
  // After this the output holds every byte needed by the decoder.
  void Finish(size_t min_size = 0);
  // Bytes produced so far, counting the pending ones (an estimate of the position while coding).
  size_t BytesSoFar() const {
    return out_->size() - start_ + cache_size_ + raw_.size() + (raw_bits_ + 7) / 8;
  }

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
  std::vector<uint8_t> raw_;
  uint64_t raw_acc_ = 0;
  int raw_bits_ = 0;
};

class ArithmeticDecoder {
 public:
  static constexpr size_t kMaxOverrun = 8;

  ArithmeticDecoder(const uint8_t* data, size_t size)
      : data_(data), size_(size), raw_next_(data + size) {
    for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | NextByte();
  }

  O3DGC_INLINE int Decode(BitModel& m) {
    const uint32_t slow = m.slow, fast = m.fast;
    const uint32_t bound = uint32_t((uint64_t(range_) * ((slow + fast + 1) >> 1)) >> 16);
    // Masks instead of a branch or a select (which compilers may turn into a branch): decoded bits
    // of a well-compressed stream are unpredictable.
    const uint32_t one = 0u - uint32_t(code_ >= bound);  // all ones for a 1
    code_ -= bound & one;
    range_ = bound ^ ((bound ^ (range_ - bound)) & one);  // range - bound for a 1, else bound
    if (O3DGC_LIKELY(m.n >= BitModel::kWarmUp)) {
      const int32_t zero = int32_t(~one);
      m.slow = uint16_t(BitModel::Step(slow, zero, BitModel::kSlowShift));
      m.fast = uint16_t(BitModel::Step(fast, zero, BitModel::kFastShift));
    } else {
      m.WarmUpdate(int(one & 1));
    }
    Normalize();
    return int(one & 1);
  }
  template <int N>
  O3DGC_INLINE int Decode(SymbolModelN<N>& m) {
    const uint32_t r = range_ >> 16;
    uint32_t lo, hi;
    const int symbol = m.FindScaled(r, code_, &lo, &hi);
    code_ -= lo;
    range_ = hi - lo;
    m.Update(symbol);
    Normalize();
    return symbol;
  }
  uint32_t DecodeBits(int count) {
    uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
      range_ >>= 1;
      const uint32_t bit = code_ >= range_;
      code_ -= range_ & (0u - bit);
      v = (v << 1) | bit;
      Normalize();
    }
    return v;
  }
  // Bits of the raw stream (see ArithmeticEncoder::EncodeRaw); 0 <= count <= 32.
  O3DGC_INLINE uint32_t DecodeRaw(int count) {
    if (count == 0) return 0;
    if (raw_avail_ < count) RefillRaw();
    const uint32_t v = uint32_t(raw_acc_ >> (64 - count));
    raw_acc_ <<= count;
    raw_avail_ -= count;
    return v;
  }
  bool failed() const { return pos_ > size_ + kMaxOverrun || raw_overrun_ > kMaxOverrun; }
  // Bytes of both streams read so far (an estimate of the position, for StreamInfo).
  size_t BytesConsumed() const {
    const size_t raw = size_t(data_ + size_ - raw_next_) + raw_overrun_ - size_t(raw_avail_ / 8);
    const size_t n = (pos_ < size_ ? pos_ : size_) + raw;
    return n < size_ ? n : size_;
  }
  size_t size() const { return size_; }

 private:
  uint8_t NextByte() { return pos_ < size_ ? data_[pos_++] : (++pos_, uint8_t(0)); }
  // Every coding step keeps at least 2^-13 of a range >= 2^24: at most two bytes come in.
  O3DGC_INLINE void Normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      code_ = (code_ << 8) | NextByte();
    }
  }
  // Tops the raw bit buffer up to at least 57 bits; the raw stream is read from the end of the
  // payload backwards, bytes before the payload read as zeros.
  void RefillRaw() {
    if (raw_next_ - data_ >= 8) {
      uint64_t w;
      std::memcpy(&w, raw_next_ - 8, 8);
      w = FromLittleEndian(w);  // the byte just below raw_next_ is the most significant
      const int bytes = (64 - raw_avail_) >> 3;
      const uint64_t keep = raw_avail_ ? ~(~uint64_t(0) >> raw_avail_) : 0;
      raw_acc_ = (raw_acc_ & keep) | ((w >> raw_avail_) & ~keep);
      raw_avail_ += 8 * bytes;
      raw_next_ -= bytes;
      return;
    }
    while (raw_avail_ <= 56) {
      uint8_t b = 0;
      if (raw_next_ > data_) {
        b = *--raw_next_;
      } else {
        ++raw_overrun_;
      }
      raw_acc_ |= uint64_t(b) << (56 - raw_avail_);
      raw_avail_ += 8;
    }
  }
  static uint64_t FromLittleEndian(uint64_t w) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    return __builtin_bswap64(w);
#else
    return w;
#endif
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  uint32_t code_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  const uint8_t* raw_next_;  // raw bytes below this one are not read yet
  uint64_t raw_acc_ = 0;     // next raw bits, most significant first
  int raw_avail_ = 0;        // valid bits at the top of raw_acc_
  size_t raw_overrun_ = 0;   // raw bytes read before the start of the payload
};

// A working copy of a decoder for a hot loop, written back when it goes out of scope. Through a
// pointer, the decoder's state must go to memory after every decision (stores to the decoded
// arrays might alias it); a local copy can stay in registers.
class ScopedDecoder {
 public:
  explicit ScopedDecoder(ArithmeticDecoder* target) : target_(target), local_(*target) {}
  ~ScopedDecoder() { *target_ = local_; }
  ScopedDecoder(const ScopedDecoder&) = delete;
  ScopedDecoder& operator=(const ScopedDecoder&) = delete;
  ArithmeticDecoder* operator->() { return &local_; }
  ArithmeticDecoder& operator*() { return local_; }

 private:
  ArithmeticDecoder* target_;
  ArithmeticDecoder local_;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_ARITHMETIC_CODER_H_
