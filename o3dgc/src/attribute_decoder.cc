// Attribute decoder (see attribute_coder.h; the mirror of attribute_encoder.cc).
#include <cmath>

#include "attribute_coder.h"

namespace o3dgc {

void DecodeClassShifts(ArithmeticDecoder* dec, ClassShifts* shifts) {
  for (auto& row : shifts->shift) {
    for (uint8_t& s : row) s = uint8_t(dec->DecodeBits(2));
  }
}

namespace {

// The multi-parallelogram loop for kDim components, in one function so that the decoder's state
// (a local copy, whose address no call may take) stays in registers. `shifts`: read before it,
// used when kShifted (a table of zeros is the same as none, and the loop without it is smaller).
template <int kDim, bool kRawLow, bool kShifted>
Status DecodeParallelogram(ArithmeticDecoder* dec_in, const WedgeTable& wedges,
                           CodingOrder::Kind kind, int64_t maxq, int coarse, ResidualModels& models,
                           const ClassShifts& shifts, bool select, int32_t* q, uint32_t* mags) {
  ArithmeticDecoder dec = *dec_in;
  Status status = Status::kOk;
  CodingOrder order(wedges, kind);
  std::unique_ptr<SelectionModels> selection(select ? new SelectionModels : nullptr);
  BitModel* trees[kDim];
  for (int k = 0; k < kDim; ++k) trees[k] = kRawLow || kDim != 3 ? nullptr : models.tree_of(k);
  // A truncated stream reads as zeros (bounded work: one pass over the vertices), found by the
  // check after the loop.
  for (uint32_t c; (c = order.Next()) != kNoVertex;) {
    int64_t pred[kDim];
    const uint32_t previous = order.previous();
    const int n_par = order.Visit(c);
    const PredictionContext pc = PredictFromParallelograms<kDim>(
        order.parallelograms(), n_par, wedges, order.done(), c, previous, q, mags, pred);
    int residual_kind = pc.kind;
    // Selection is defined for 3 components only (DecodeParallelogramFor rejects the flag for
    // others): the other loops stay without its code.
    if (kDim == 3 && select && n_par >= 2) {
      const int symbol = dec.Decode(selection->symbol[SelectionModels::Context(n_par)]);
      if (symbol > 0) {
        if (symbol > n_par || symbol > kMaxSelected) {
          status = Status::kCorrupt;
          break;
        }
        residual_kind = kSelectedKind;
        const Wedge* w = order.parallelograms()[symbol - 1];
        for (int k = 0; k < kDim; ++k) {
          pred[k] = int64_t(q[size_t(w->u) * kDim + k]) + q[size_t(w->w) * kDim + k] -
                    q[size_t(w->x) * kDim + k];
        }
      }
    }
    const int mctx = MagContext(pc.neighbour_magnitude) >> coarse;
    // Component k's context: same (kind, magnitude), its own component (all share component 0
    // for tiny meshes), the previous component's residual (not for small meshes).
    ResidualModel* const row = &models.at(0, residual_kind, mctx, 0);
    const size_t stride = coarse == 2 ? 0 : models.component_stride();
    const int shift =
        kShifted && residual_kind != kSelectedKind ? shifts.shift[residual_kind][mctx] : 0;
    int64_t r[kDim];
    bool ok = true;
    int intra = 0;
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC unroll 4
#endif
    for (int k = 0; k < kDim; ++k) {
      const int64_t p = pred[k] < 0 ? 0 : (pred[k] > maxq ? maxq : pred[k]);
      ResidualModel& m = row[stride * k + intra];
      if (kShifted) {
        int bit_length;
        r[k] = DecodeShiftedResidual<kRawLow>(dec, m, models.escape, shift, &bit_length);
        intra = coarse ? 0 : (bit_length < kIntraContexts ? bit_length : kIntraContexts - 1);
      } else {
        // The next component's context from the class, before this residual's low bits: the
        // same value as IntraContext(r[k]) (the bit length of |r[k]|, capped), one step earlier
        // on the chain from one decision to the next.
        int symbol;
        r[k] = DecodeResidual<kRawLow>(dec, m, models.escape, &symbol, trees[k]);
        static_assert(kIntraContexts <= kDirectClasses + 1, "the class names the intra context");
        intra = coarse ? 0 : (symbol < kIntraContexts ? symbol : kIntraContexts - 1);
      }
      const int64_t v = p + r[k];
      ok &= uint64_t(v) <= uint64_t(maxq);
      q[size_t(c) * kDim + k] = int32_t(v);
    }
    if (!ok) {
      status = Status::kCorrupt;
      break;
    }
    mags[c] = SaturatingMagnitude(r, kDim);
  }
  *dec_in = dec;
  if (status == Status::kOk && dec.failed()) status = Status::kTruncated;
  return status;
}

// The residual coding (RawLowBits) as a template argument, so that the loop has no test for it.
template <int kDim>
Status DecodeParallelogramFor(bool raw, ArithmeticDecoder* dec, const WedgeTable& wedges,
                              CodingOrder::Kind kind, int64_t maxq, int coarse,
                              ResidualModels& models, int32_t* q, uint32_t* mags) {
  ClassShifts shifts;
  const bool select = dec->DecodeBits(1) != 0;
  if (select && kDim != 3) return Status::kCorrupt;
  if (!raw) {
    return DecodeParallelogram<kDim, false, false>(dec, wedges, kind, maxq, coarse, models, shifts,
                                                   select, q, mags);
  }
  DecodeClassShifts(dec, &shifts);
  // Positions (and normals predicted as values) have a loop of their own for tables of zeros; other
  // attributes share the loop with shifts (each loop adds about 1.6 KB to the gzip'd wasm decoder).
  if constexpr (kDim == 3) {
    if (!shifts.any()) {
      return DecodeParallelogram<kDim, true, false>(dec, wedges, kind, maxq, coarse, models, shifts,
                                                    select, q, mags);
    }
  }
  return DecodeParallelogram<kDim, true, true>(dec, wedges, kind, maxq, coarse, models, shifts,
                                               select, q, mags);
}

}  // namespace

Status DecodeQuantized(ArithmeticDecoder* dec_in, const WedgeTable* wedges, uint32_t n, int dim,
                       int bits, Prediction mode, CodingOrder::Kind order_kind,
                       std::vector<int32_t>* out, const std::vector<double>* geometry,
                       bool low_bits_flag, bool all_adaptive) {
  ScopedDecoder dec(dec_in);
  std::vector<int32_t>& q = *out;
  q.assign(size_t(n) * dim, 0);
  const int64_t maxq = (int64_t(1) << bits) - 1;
  if (mode == Prediction::kNone) {
    for (size_t i = 0; i < q.size(); ++i) {
      q[i] = int32_t(dec->DecodeBits(bits));
      if ((i & 1023) == 0 && dec->failed()) return Status::kTruncated;
    }
    return dec->failed() ? Status::kTruncated : Status::kOk;
  }
  std::unique_ptr<ResidualModels> models(new ResidualModels(dim, kResidualKinds));
  const double* geo = (geometry && dim == 2) ? geometry->data() : nullptr;
  if (low_bits_flag && HasLowBitsChoice(mode, n, dim, geo != nullptr, all_adaptive) &&
      dec->DecodeBits(1)) {
    models->tree.assign(size_t(dim) * kTreeModels, BitModel());
  }
  std::vector<uint32_t> mags(n, 0);
  const int coarse = n < kTinyMesh ? 2 : (n < kSmallMesh ? 1 : 0);
  const bool raw = RawLowBits(n, all_adaptive);
  // Residuals against `pred` for vertex c, with the context of `pc`.
  auto decode_vertex = [&](uint32_t c, const PredictionContext& pc, const int64_t* pred) {
    const int mctx = MagContext(pc.neighbour_magnitude) >> coarse;
    int64_t r[4];
    for (int k = 0; k < dim; ++k) {
      ResidualModel& m = models->at(coarse == 2 ? 0 : k, pc.kind, mctx,
                                    (k && !coarse) ? IntraContext(r[k - 1]) : 0);
      r[k] = raw ? DecodeResidual<true>(*dec, m, models->escape)
                 : DecodeResidual<false>(*dec, m, models->escape, nullptr, models->tree_of(k));
      const int64_t v = pred[k] + r[k];
      if (v < 0 || v > maxq) return false;
      q[size_t(c) * dim + k] = int32_t(v);
    }
    mags[c] = SaturatingMagnitude(r, dim);
    return true;
  };
  if (mode != Prediction::kParallelogram) {
    // Differential: against the previous vertex in id order.
    for (uint32_t c = 0; c < n; ++c) {
      if (dec->failed()) return Status::kTruncated;
      int64_t pred[4];
      PredictionContext pc;
      for (int k = 0; k < dim; ++k) pred[k] = c > 0 ? q[size_t(c - 1) * dim + k] : 0;
      pc.neighbour_magnitude = c > 0 ? mags[c - 1] : 0;
      if (!decode_vertex(c, pc, pred)) return Status::kCorrupt;
    }
    return dec->failed() ? Status::kTruncated : Status::kOk;
  }
  if (!geo) {
    switch (dim) {
      case 1:
        return DecodeParallelogramFor<1>(raw, &*dec, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data());
      case 2:
        return DecodeParallelogramFor<2>(raw, &*dec, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data());
      case 3:
        return DecodeParallelogramFor<3>(raw, &*dec, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data());
      default:
        return DecodeParallelogramFor<4>(raw, &*dec, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data());
    }
  }
  CodingOrder order(*wedges, order_kind);
  for (uint32_t c; (c = order.Next()) != kNoVertex;) {
    if (dec->failed()) return Status::kTruncated;
    int64_t pred[4];
    int64_t alt[2];
    bool ambiguous;
    const PredictionContext pc =
        PredictAttributeVertex(*wedges, order.done(), c, order.previous(), q.data(), dim, geo,
                               mags.data(), maxq, pred, alt, &ambiguous);
    if (ambiguous && dec->Decode(models->side)) {
      pred[0] = alt[0];
      pred[1] = alt[1];
    }
    if (!decode_vertex(c, pc, pred)) return Status::kCorrupt;
    order.Visit(c);
  }
  return dec->failed() ? Status::kTruncated : Status::kOk;
}

Status DecodeOctNormals(ArithmeticDecoder* dec_in, const MeshAdjacency& adj,
                        const NormalGeometry& geo, uint32_t n, int bits,
                        std::vector<float>* normals) {
  ScopedDecoder dec(dec_in);
  const uint32_t maxq = uint32_t((uint64_t(1) << bits) - 1);
  std::unique_ptr<NormalModels> models(new NormalModels(2, 1));
  std::vector<uint32_t> mags(n, 0);
  normals->assign(size_t(n) * 3, 0.0f);
  for (uint32_t c = 0; c < n; ++c) {
    if (dec->failed()) return Status::kTruncated;
    double p[3];
    SurfaceNormal(adj, c, geo.positions, geo.scale, geo.position_of, p);
    const bool flip = p[2] < 0;
    if (flip) p[2] = -p[2];
    double pu, pv;
    OctEncode(p, &pu, &pv);
    const int32_t qp[2] = {OctQuantize(pu, maxq), OctQuantize(pv, maxq)};
    const int mctx = MagContext(NeighbourMagnitude(adj, c, mags.data()));
    int64_t r[2];
    int32_t qa[2];
    for (int k = 0; k < 2; ++k) {
      const int intra = (k && n >= kSmallMesh) ? IntraContext(r[0]) : 0;
      r[k] = DecodeSigned(*dec, models->at(k, 0, mctx, intra));
      const int64_t v = qp[k] + r[k];
      if (v < 0 || v > int64_t(maxq)) return Status::kCorrupt;
      qa[k] = int32_t(v);
    }
    mags[c] = SaturatingMagnitude(r, 2);
    double a[3];
    OctDecode(OctDequantize(qa[0], maxq), OctDequantize(qa[1], maxq), a);
    if (flip) a[2] = -a[2];
    for (int k = 0; k < 3; ++k) (*normals)[3 * size_t(c) + k] = float(a[k]);
  }
  return dec->failed() ? Status::kTruncated : Status::kOk;
}

Status DecodeInts(ArithmeticDecoder* dec_in, uint32_t n, int dim, Prediction mode,
                  std::vector<int32_t>* values) {
  ScopedDecoder dec(dec_in);
  std::vector<SignedModel> models(static_cast<size_t>(dim));  // one per component
  values->assign(size_t(n) * dim, 0);
  for (size_t c = 0; c < n; ++c) {
    if (dec->failed()) return Status::kTruncated;
    for (int k = 0; k < dim; ++k) {
      const int64_t pred =
          (mode == Prediction::kDifferential && c > 0) ? (*values)[(c - 1) * dim + k] : 0;
      const int64_t v = pred + DecodeSigned(*dec, models[size_t(k)]);
      if (v < INT32_MIN || v > INT32_MAX) return Status::kCorrupt;
      (*values)[c * dim + k] = int32_t(v);
    }
  }
  return dec->failed() ? Status::kTruncated : Status::kOk;
}

}  // namespace o3dgc
