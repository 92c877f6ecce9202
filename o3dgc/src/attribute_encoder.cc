// Attribute encoder (see attribute_coder.h; attribute_decoder.cc is its mirror).
#include <algorithm>
#include <cmath>

#include "attribute_coder.h"

namespace o3dgc {

void SurfaceNormal(const MeshAdjacency& adj, uint32_t c, const int32_t* positions,
                   const double scale[3], const uint32_t* position_of, double n[3]) {
  double s[3] = {0, 0, 0};
  for (const uint32_t* it = adj.begin(c); it != adj.end(c); ++it) {
    const uint32_t* v = adj.corners(*it);
    const int32_t* p0 = positions + 3 * size_t(position_of[v[0]]);
    const int32_t* p1 = positions + 3 * size_t(position_of[v[1]]);
    const int32_t* p2 = positions + 3 * size_t(position_of[v[2]]);
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
      e1[k] = double(p1[k] - p0[k]) * scale[k];
      e2[k] = double(p2[k] - p0[k]) * scale[k];
    }
    s[0] += e1[1] * e2[2] - e1[2] * e2[1];
    s[1] += e1[2] * e2[0] - e1[0] * e2[2];
    s[2] += e1[0] * e2[1] - e1[1] * e2[0];
  }
  const double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  if (!(len > 1e-300) || !std::isfinite(len)) {
    n[0] = 0;
    n[1] = 0;
    n[2] = 1;
    return;
  }
  for (int k = 0; k < 3; ++k) n[k] = s[k] / len;
}

std::vector<double> AttributeGeometry(const NormalGeometry& geo, uint32_t n) {
  std::vector<double> g(size_t(n) * 3);
  for (uint32_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      g[3 * size_t(v) + k] =
          double(geo.positions[3 * size_t(geo.position_of[v]) + k]) * geo.scale[k];
    }
  }
  return g;
}

ClassShifts ChooseClassShifts(const ClassHistograms& histograms) {
  ClassShifts shifts;
  uint64_t total = 0, saved = 0;
  for (int kind = 0; kind < kPredictionKinds; ++kind) {
    for (int m = 0; m < kMagContexts; ++m) {
      const uint64_t* h = histograms.counts[kind][m];
      // Residuals needing a second decision under shift s: the classes 0..s (when s > 0) and
      // those above s + kDirectClasses.
      uint64_t cost[kMaxClassShift + 1] = {};
      for (int c = 0; c < kShiftHistogram; ++c) {
        total += h[c];
        for (int s = 0; s <= kMaxClassShift; ++s) {
          if ((s > 0 && c <= s) || c > s + kDirectClasses) cost[s] += h[c];
        }
      }
      int best = 0;
      for (int s = 1; s <= kMaxClassShift; ++s) {
        if (cost[s] < cost[best]) best = s;
      }
      shifts.shift[kind][m] = uint8_t(best);
      saved += cost[0] - cost[best];
    }
  }
  // The decoder's loop with shifts costs a few instructions per residual more than the one
  // without (about 1 %); a second decision about 40 and often a mispredicted branch. Shifts pay
  // when they spare a few percent of the residuals their second decision (corpus, 14 bits:
  // rocker_arm 19 %, fandisk 6 %, bunny 0.8 %, igea 0 %).
  if (saved * kMinShiftGain < total) shifts = ClassShifts();
  return shifts;
}

void EncodeClassShifts(ArithmeticEncoder* enc, const ClassShifts& shifts) {
  for (const auto& row : shifts.shift) {
    for (const uint8_t s : row) enc->EncodeBits(s, 2);
  }
}

namespace {

// The multi-parallelogram loop for kDim components (mirror of DecodeParallelogram). The residuals
// are found first, in coding order, then coded: on large meshes the class shifts they select are
// sent before them. With `estimate`, nothing is coded: *estimate receives the estimated bits and
// *selects (if not null) whether the selection would be used. `expect_selection`: see
// EncodeQuantized.
template <int kDim, bool kRawLow>
void EncodeParallelogram(ArithmeticEncoder* enc, const WedgeTable& wedges, CodingOrder::Kind kind,
                         int64_t maxq, int coarse, ResidualModels& models, const int32_t* q,
                         uint32_t* mags, bool expect_selection, double* estimate = nullptr,
                         bool* selects = nullptr) {
  // One per vertex of the mesh, kept until coded: small. Values and clamped predictions lie in
  // [0, maxq] with maxq < 2^30, so a residual fits 32 bits.
  struct Vertex {
    uint8_t kind, mctx;
    int8_t choices;    // parallelograms offered to the selection (0: no symbol)
    uint8_t selected;  // selection symbol (0: combined prediction)
    int32_t r[kDim];   // residual that will be coded: the selected prediction's when `select`
  };
  // Estimated bits of a residual: its class and the bits below it.
  auto cost = [](const int64_t* r) {
    int bits = 0;
    for (int k = 0; k < kDim; ++k) {
      const int b = BitLength(uint64_t(r[k] < 0 ? -r[k] : r[k]));
      bits += b + (b > 0) + 1;
    }
    return bits;
  };
  auto clamp = [maxq](int64_t p) { return p < 0 ? 0 : (p > maxq ? maxq : p); };
  std::vector<Vertex> coded;
  // One pass in coding order: residuals, selections and their estimated bits. The neighbour
  // magnitudes (contexts) follow the residuals that will be coded: the selected ones when
  // `select`.
  auto analyse = [&](bool select, double* combined_bits, double* selected_bits) {
    coded.clear();
    coded.reserve(wedges.num_vertices());
    std::fill(mags, mags + wedges.num_vertices(), 0u);
    uint64_t symbol_counts[kSelectionContexts][kMaxSelected + 1] = {};
    *combined_bits = *selected_bits = 0;
    CodingOrder order(wedges, kind);
    for (uint32_t c; (c = order.Next()) != kNoVertex;) {
      int64_t pred[kDim];
      const uint32_t previous = order.previous();
      const int n_par = order.Visit(c);
      const PredictionContext pc = PredictFromParallelograms<kDim>(
          order.parallelograms(), n_par, wedges, order.done(), c, previous, q, mags, pred);
      Vertex v;
      v.kind = uint8_t(pc.kind);
      v.mctx = uint8_t(MagContext(pc.neighbour_magnitude) >> coarse);
      int64_t combined[kDim], selected[kDim];
      for (int k = 0; k < kDim; ++k)
        combined[k] = int64_t(q[size_t(c) * kDim + k]) - clamp(pred[k]);
      v.choices = int8_t(n_par >= 2 ? (n_par < kMaxSelected ? n_par : kMaxSelected) : 0);
      v.selected = 0;
      std::copy(combined, combined + kDim, selected);
      const int base = cost(combined);
      int best = base;
      for (int i = 0; i < v.choices; ++i) {
        const Wedge* w = order.parallelograms()[i];
        int64_t r[kDim];
        for (int k = 0; k < kDim; ++k) {
          r[k] = int64_t(q[size_t(c) * kDim + k]) -
                 clamp(int64_t(q[size_t(w->u) * kDim + k]) + q[size_t(w->w) * kDim + k] -
                       q[size_t(w->x) * kDim + k]);
        }
        const int b = cost(r);
        if (b < best) {
          best = b;
          v.selected = uint8_t(1 + i);
          std::copy(r, r + kDim, selected);
        }
      }
      *combined_bits += base;
      *selected_bits += best;
      if (v.choices) ++symbol_counts[SelectionModels::Context(v.choices)][v.selected];
      const int64_t* const r = select ? selected : combined;
      for (int k = 0; k < kDim; ++k) v.r[k] = int32_t(r[k]);
      mags[c] = SaturatingMagnitude(r, kDim);
      coded.push_back(v);
    }
    // The selection symbols' cost: their empirical entropy per context.
    for (const auto& counts : symbol_counts) {
      uint64_t total = 0;
      for (const uint64_t n : counts) total += n;
      for (const uint64_t n : counts) {
        if (n) *selected_bits -= double(n) * std::log2(double(n) / double(total));
      }
    }
  };
  // Whether the selection pays does not depend on the contexts (the bits are estimated from the
  // residuals' lengths and the symbols' counts), so the first pass may assume either; a wrong
  // assumption costs a second pass, never other bytes.
  double combined_bits, selected_bits;
  const bool assumed = kDim == 3 && expect_selection;
  analyse(assumed, &combined_bits, &selected_bits);
  // Selection costs decoding time (a symbol per vertex: 5-8 % on bunny): on large meshes, where
  // decoding time matters (see RawLowBits), it is used only when it spares a tenth of the
  // estimated bits (CAD parts: 25-70 %; smooth scans: 1-9 %), on smaller ones from 2 %.
  const bool select = kDim == 3 && selected_bits < (kRawLow ? 0.90 : 0.98) * combined_bits;
  if (estimate) {
    *estimate = select ? selected_bits : combined_bits;
    if (selects) *selects = select;
    return;
  }
  if (select != assumed) analyse(select, &combined_bits, &selected_bits);
  enc->EncodeBits(select ? 1 : 0, 1);
  ClassShifts shifts;
  if (kRawLow) {
    ClassHistograms histograms;
    for (const Vertex& v : coded) {
      if (select && v.selected) continue;
      for (int k = 0; k < kDim; ++k) histograms.Add(v.kind, v.mctx, v.r[k]);
    }
    shifts = ChooseClassShifts(histograms);
    EncodeClassShifts(enc, shifts);
  }
  std::unique_ptr<SelectionModels> selection(new SelectionModels);
  const size_t stride = coarse == 2 ? 0 : models.component_stride();
  for (const Vertex& v : coded) {
    if (select && v.choices) {
      enc->Encode(v.selected, selection->symbol[SelectionModels::Context(v.choices)]);
    }
    const bool own = select && v.selected;
    ResidualModel* const row = &models.at(0, own ? kSelectedKind : v.kind, v.mctx, 0);
    const int shift = kRawLow && !own ? shifts.shift[v.kind][v.mctx] : 0;
    int intra = 0;
    for (int k = 0; k < kDim; ++k) {
      EncodeResidual<kRawLow>(*enc, row[stride * k + intra], models.escape, v.r[k], shift,
                              kRawLow || kDim != 3 ? nullptr : models.tree_of(k));
      intra = coarse ? 0 : IntraContext(v.r[k]);
    }
  }
}

// The residual coding (RawLowBits) as a template argument, so that the loop has no test for it.
template <int kDim>
void EncodeParallelogramFor(bool raw, ArithmeticEncoder* enc, const WedgeTable& wedges,
                            CodingOrder::Kind kind, int64_t maxq, int coarse,
                            ResidualModels& models, const int32_t* q, uint32_t* mags,
                            bool expect_selection) {
  if (raw) {
    EncodeParallelogram<kDim, true>(enc, wedges, kind, maxq, coarse, models, q, mags,
                                    expect_selection);
  } else {
    EncodeParallelogram<kDim, false>(enc, wedges, kind, maxq, coarse, models, q, mags,
                                     expect_selection);
  }
}

}  // namespace

double EstimatePositionBits(const WedgeTable& wedges, const std::vector<int32_t>& q, int bits,
                            CodingOrder::Kind order, bool* selects) {
  const uint32_t n = uint32_t(q.size() / 3);
  std::unique_ptr<ResidualModels> models(new ResidualModels(3, kResidualKinds));
  std::vector<uint32_t> mags(n, 0);
  const int64_t maxq = (int64_t(1) << bits) - 1;
  const int coarse = n < kTinyMesh ? 2 : (n < kSmallMesh ? 1 : 0);
  double estimate = 0;
  if (RawLowBits(n)) {
    EncodeParallelogram<3, true>(nullptr, wedges, order, maxq, coarse, *models, q.data(),
                                 mags.data(), true, &estimate, selects);
  } else {
    EncodeParallelogram<3, false>(nullptr, wedges, order, maxq, coarse, *models, q.data(),
                                  mags.data(), true, &estimate, selects);
  }
  return estimate;
}

void EncodeQuantized(ArithmeticEncoder* enc, const WedgeTable* wedges,
                     const std::vector<int32_t>& q, int dim, int bits, Prediction mode,
                     CodingOrder::Kind order_kind, const std::vector<double>* geometry,
                     LowBits low_bits, bool expect_selection, bool all_adaptive) {
  const uint32_t n = uint32_t(q.size() / size_t(dim));
  if (mode == Prediction::kNone) {
    for (int32_t v : q) enc->EncodeBits(uint32_t(v), bits);
    return;
  }
  std::unique_ptr<ResidualModels> models(new ResidualModels(dim, kResidualKinds));
  const double* geo = (geometry && dim == 2) ? geometry->data() : nullptr;
  if (low_bits != LowBits::kNoFlag &&
      HasLowBitsChoice(mode, n, dim, geo != nullptr, all_adaptive)) {
    enc->EncodeBits(low_bits == LowBits::kModelled ? 1 : 0, 1);
    if (low_bits == LowBits::kModelled) models->tree.assign(size_t(dim) * kTreeModels, BitModel());
  }
  std::vector<uint32_t> mags(n, 0);
  const int64_t maxq = (int64_t(1) << bits) - 1;
  const int coarse = n < kTinyMesh ? 2 : (n < kSmallMesh ? 1 : 0);
  const bool raw = RawLowBits(n, all_adaptive);
  auto encode_vertex = [&](uint32_t c, const PredictionContext& pc, const int64_t* pred) {
    const int mctx = MagContext(pc.neighbour_magnitude) >> coarse;
    int64_t r[4];
    for (int k = 0; k < dim; ++k) {
      r[k] = int64_t(q[size_t(c) * dim + k]) - pred[k];
      ResidualModel& m = models->at(coarse == 2 ? 0 : k, pc.kind, mctx,
                                    (k && !coarse) ? IntraContext(r[k - 1]) : 0);
      if (raw) {
        EncodeResidual<true>(*enc, m, models->escape, r[k]);
      } else {
        EncodeResidual<false>(*enc, m, models->escape, r[k], 0, models->tree_of(k));
      }
    }
    mags[c] = SaturatingMagnitude(r, dim);
  };
  if (mode != Prediction::kParallelogram) {
    // Differential: against the previous vertex in id order.
    for (uint32_t c = 0; c < n; ++c) {
      int64_t pred[4];
      PredictionContext pc;
      for (int k = 0; k < dim; ++k) pred[k] = c > 0 ? q[size_t(c - 1) * dim + k] : 0;
      pc.neighbour_magnitude = c > 0 ? mags[c - 1] : 0;
      encode_vertex(c, pc, pred);
    }
    return;
  }
  if (!geo) {
    switch (dim) {
      case 1:
        return EncodeParallelogramFor<1>(raw, enc, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data(), expect_selection);
      case 2:
        return EncodeParallelogramFor<2>(raw, enc, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data(), expect_selection);
      case 3:
        return EncodeParallelogramFor<3>(raw, enc, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data(), expect_selection);
      default:
        return EncodeParallelogramFor<4>(raw, enc, *wedges, order_kind, maxq, coarse, *models,
                                         q.data(), mags.data(), expect_selection);
    }
  }
  CodingOrder order(*wedges, order_kind);
  for (uint32_t c; (c = order.Next()) != kNoVertex;) {
    int64_t pred[4];
    int64_t alt[2];
    bool ambiguous;
    const PredictionContext pc =
        PredictAttributeVertex(*wedges, order.done(), c, order.previous(), q.data(), dim, geo,
                               mags.data(), maxq, pred, alt, &ambiguous);
    if (ambiguous) {
      int64_t da = 0, db = 0;
      for (int k = 0; k < 2; ++k) {
        const int64_t x = q[size_t(c) * 2 + k];
        da += x > pred[k] ? x - pred[k] : pred[k] - x;
        db += x > alt[k] ? x - alt[k] : alt[k] - x;
      }
      enc->Encode(db < da, models->side);
      if (db < da) {
        pred[0] = alt[0];
        pred[1] = alt[1];
      }
    }
    encode_vertex(c, pc, pred);
    order.Visit(c);
  }
}

void EncodeOctNormals(ArithmeticEncoder* enc, const MeshAdjacency& adj, const NormalGeometry& geo,
                      const std::vector<float>& normals, int bits) {
  const uint32_t n = uint32_t(normals.size() / 3);
  const uint32_t maxq = uint32_t((uint64_t(1) << bits) - 1);
  std::unique_ptr<NormalModels> models(new NormalModels(2, 1));
  std::vector<uint32_t> mags(n, 0);
  for (uint32_t c = 0; c < n; ++c) {
    double p[3];
    SurfaceNormal(adj, c, geo.positions, geo.scale, geo.position_of, p);
    const bool flip = p[2] < 0;
    double a[3] = {normals[3 * size_t(c)], normals[3 * size_t(c) + 1], normals[3 * size_t(c) + 2]};
    const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(len > 0) || !std::isfinite(len)) {
      a[0] = 0;
      a[1] = 0;
      a[2] = 1;
    }
    if (flip) {
      p[2] = -p[2];
      a[2] = -a[2];
    }
    double pu, pv, au, av;
    OctEncode(p, &pu, &pv);
    OctEncode(a, &au, &av);
    const int32_t qp[2] = {OctQuantize(pu, maxq), OctQuantize(pv, maxq)};
    const int32_t qa[2] = {OctQuantize(au, maxq), OctQuantize(av, maxq)};
    const int mctx = MagContext(NeighbourMagnitude(adj, c, mags.data()));
    int64_t r[2];
    for (int k = 0; k < 2; ++k) {
      r[k] = int64_t(qa[k]) - qp[k];
      const int intra = (k && n >= kSmallMesh) ? IntraContext(r[0]) : 0;
      EncodeSigned(*enc, models->at(k, 0, mctx, intra), r[k]);
    }
    mags[c] = SaturatingMagnitude(r, 2);
  }
}

void EncodeInts(ArithmeticEncoder* enc, const std::vector<int32_t>& values, int dim,
                Prediction mode) {
  std::vector<SignedModel> models(static_cast<size_t>(dim));  // one per component
  const size_t n = values.size() / size_t(dim);
  for (size_t c = 0; c < n; ++c) {
    for (int k = 0; k < dim; ++k) {
      const int64_t pred =
          (mode == Prediction::kDifferential && c > 0) ? values[(c - 1) * dim + k] : 0;
      EncodeSigned(*enc, models[size_t(k)], int64_t(values[c * dim + k]) - pred);
    }
  }
}

}  // namespace o3dgc
