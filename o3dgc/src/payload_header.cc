// Counts and attribute descriptors at the start of the payload (see payload_header.h).
#include "payload_header.h"

#include <cstring>

namespace o3dgc {
namespace {

uint32_t FloatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
float BitsFloat(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

bool HasQuantizer(const AttributeDesc& d, bool is_int) {
  return !is_int && d.prediction != Prediction::kSurfaceNormal;
}

void EncodeDesc(ArithmeticEncoder* enc, const AttributeDesc& d, bool is_int) {
  enc->EncodeBits(uint32_t(d.semantic), 3);
  enc->EncodeBits(d.dimension - 1, 2);
  enc->EncodeBits(uint32_t(d.prediction), 2);
  if (is_int) return;
  enc->EncodeBits(uint32_t(d.bits - 1), 5);
  if (!HasQuantizer(d, is_int)) return;
  enc->EncodeBits(uint32_t(d.range), 2);
  for (uint32_t c = 0; c < d.dimension; ++c) enc->EncodeBits(FloatBits(d.quant.min[c]), 32);
  const uint32_t nr = d.range == RangeMode::kPerAxis ? d.dimension : 1;
  for (uint32_t c = 0; c < nr; ++c) enc->EncodeBits(FloatBits(d.quant.range[c]), 32);
}

Status DecodeDesc(ArithmeticDecoder* dec, AttributeDesc* d, bool is_int) {
  const uint32_t sem = dec->DecodeBits(3);
  if (sem > uint32_t(Semantic::kJointId)) return Status::kCorrupt;
  d->semantic = Semantic(sem);
  d->dimension = dec->DecodeBits(2) + 1;
  const uint32_t pred = dec->DecodeBits(2);
  d->prediction = Prediction(pred);
  if (is_int) {
    if (d->prediction != Prediction::kNone && d->prediction != Prediction::kDifferential) {
      return Status::kCorrupt;
    }
    return Status::kOk;
  }
  d->bits = int(dec->DecodeBits(5)) + 1;
  if (d->bits > 30) return Status::kCorrupt;
  if (d->prediction == Prediction::kSurfaceNormal &&
      (d->semantic != Semantic::kNormal || d->dimension != 3)) {
    return Status::kCorrupt;
  }
  if (!HasQuantizer(*d, is_int)) return Status::kOk;
  const uint32_t range_mode = dec->DecodeBits(2);
  if (range_mode > uint32_t(RangeMode::kDiagonal)) return Status::kCorrupt;
  d->range = RangeMode(range_mode);
  d->quant.dimension = d->dimension;
  d->quant.bits = d->bits;
  d->quant.mode = d->range;
  for (uint32_t c = 0; c < d->dimension; ++c) d->quant.min[c] = BitsFloat(dec->DecodeBits(32));
  if (d->range != RangeMode::kPerAxis) {
    const float r = BitsFloat(dec->DecodeBits(32));
    for (uint32_t c = 0; c < d->dimension; ++c) d->quant.range[c] = r;
  } else {
    for (uint32_t c = 0; c < d->dimension; ++c) d->quant.range[c] = BitsFloat(dec->DecodeBits(32));
  }
  if (!d->quant.Valid()) return Status::kCorrupt;
  return Status::kOk;
}

}  // namespace

uint64_t PayloadHeader::Budget() const {
  uint64_t comps = 3;
  if (has_normals) comps += 3;
  for (const auto& a : floats) comps += a.dimension;
  for (const auto& a : ints) comps += a.dimension;
  return num_triangles + num_vertices * (1 + comps);
}

void EncodePayloadHeader(ArithmeticEncoder* enc, const PayloadHeader& h) {
  EGModel m;
  EncodeEG(*enc, m, h.num_vertices);
  EncodeEG(*enc, m, h.num_triangles);
  enc->EncodeBits(h.has_normals, 1);
  enc->EncodeBits(h.has_groups, 1);
  EncodeEG(*enc, m, h.floats.size());
  EncodeEG(*enc, m, h.ints.size());
  EncodeDesc(enc, h.position, false);
  if (h.has_normals) EncodeDesc(enc, h.normal, false);
  for (const auto& a : h.floats) EncodeDesc(enc, a, false);
  for (const auto& a : h.ints) EncodeDesc(enc, a, true);
}

Status DecodePayloadHeader(ArithmeticDecoder* dec, PayloadHeader* h) {
  EGModel m;
  h->num_vertices = DecodeEG(*dec, m);
  h->num_triangles = DecodeEG(*dec, m);
  h->has_normals = dec->DecodeBits(1) != 0;
  h->has_groups = dec->DecodeBits(1) != 0;
  const uint64_t nf = DecodeEG(*dec, m);
  const uint64_t ni = DecodeEG(*dec, m);
  if (nf > 64 || ni > 64) return Status::kCorrupt;
  Status s;
  if ((s = DecodeDesc(dec, &h->position, false)) != Status::kOk) return s;
  if (h->position.dimension != 3 || h->position.prediction == Prediction::kSurfaceNormal) {
    return Status::kCorrupt;
  }
  if (h->has_normals) {
    if ((s = DecodeDesc(dec, &h->normal, false)) != Status::kOk) return s;
    if (h->normal.dimension != 3) return Status::kCorrupt;
  }
  h->floats.resize(size_t(nf));
  for (auto& a : h->floats) {
    if ((s = DecodeDesc(dec, &a, false)) != Status::kOk) return s;
    if (a.prediction == Prediction::kSurfaceNormal) return Status::kCorrupt;
  }
  h->ints.resize(size_t(ni));
  for (auto& a : h->ints) {
    if ((s = DecodeDesc(dec, &a, true)) != Status::kOk) return s;
  }
  if (dec->failed()) return Status::kTruncated;
  return Status::kOk;
}

void AddTailBytes(const PayloadHeader& h, size_t tail, StreamInfo* si) {
  if (h.has_groups) {
    si->groups = tail;
  } else if (!si->int_attributes.empty()) {
    si->int_attributes.back() += tail;
  } else if (!si->float_attributes.empty()) {
    si->float_attributes.back() += tail;
  } else if (h.has_normals) {
    si->normals += tail;
  } else {
    si->positions += tail;
  }
}

}  // namespace o3dgc
