// Attribute decoder (see attribute_coder.h; the mirror of attribute_encoder.cc).
#include <cmath>

#include "attribute_coder.h"

namespace o3dgc {

namespace {

Status DecodeQuantizedInOrder(ArithmeticDecoder* dec, const MeshAdjacency& adj, uint32_t n, int dim,
                              int bits, Prediction mode, std::vector<int32_t>* out,
                              const double* geometry) {
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
  std::unique_ptr<ResidualModels> models(new ResidualModels(dim, 3));
  std::vector<uint32_t> mags(n, 0);
  const int coarse = n < kTinyMesh ? 2 : (n < kSmallMesh ? 1 : 0);
  for (uint32_t c = 0; c < n; ++c) {
    if (dec->failed()) return Status::kTruncated;
    int64_t pred[4];
    int64_t alt[2];
    bool ambiguous;
    const PredictionContext pc = PredictAttributeVertex(adj, c, q.data(), dim, geometry, mode == Prediction::kParallelogram,
                                                        mags.data(), maxq, pred, alt, &ambiguous);
    if (ambiguous && dec->Decode(models->side)) {
      pred[0] = alt[0];
      pred[1] = alt[1];
    }
    const int mctx = MagContext(pc.neighbour_magnitude) >> coarse;
    int64_t r[4];
    for (int k = 0; k < dim; ++k) {
      r[k] = DecodeSigned(*dec, models->at(coarse == 2 ? 0 : k, pc.kind, mctx, (k && !coarse) ? IntraContext(r[k - 1]) : 0));
      const int64_t v = pred[k] + r[k];
      if (v < 0 || v > maxq) return Status::kCorrupt;
      q[size_t(c) * dim + k] = int32_t(v);
    }
    mags[c] = SaturatingMagnitude(r, dim);
  }
  return dec->failed() ? Status::kTruncated : Status::kOk;
}

}  // namespace

Status DecodeQuantized(ArithmeticDecoder* dec, const MeshAdjacency& adj, uint32_t n, int dim,
                       int bits, Prediction mode, std::vector<int32_t>* out,
                       const std::vector<double>* geometry) {
  if (mode != Prediction::kParallelogram) {
    return DecodeQuantizedInOrder(dec, adj, n, dim, bits, mode, out, nullptr);
  }
  const bool texcoord = geometry && dim == 2;
  const std::vector<uint32_t> order = MaxDegreeOrder(adj);
  const std::vector<uint32_t> renamed_tris = RenameByOrder(adj, order);
  MeshAdjacency renamed;
  renamed.BuildPermuted(adj, order, renamed_tris);
  renamed.SetOpposite(adj.opposite());
  std::vector<double> geo_renamed;
  if (texcoord) {
    geo_renamed.resize(size_t(n) * 3);
    for (uint32_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) geo_renamed[3 * size_t(i) + k] = (*geometry)[3 * size_t(order[i]) + k];
    }
  }
  std::vector<int32_t> q;
  const Status s = DecodeQuantizedInOrder(dec, renamed, n, dim, bits, mode, &q,
                                          texcoord ? geo_renamed.data() : nullptr);
  if (s != Status::kOk) return s;
  out->assign(q.size(), 0);
  for (uint32_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) (*out)[size_t(order[i]) * dim + k] = q[size_t(i) * dim + k];
  }
  return Status::kOk;
}

Status DecodeOctNormals(ArithmeticDecoder* dec, const MeshAdjacency& adj, const NormalGeometry& geo,
                        uint32_t n, int bits, std::vector<float>* normals) {
  const uint32_t maxq = uint32_t((uint64_t(1) << bits) - 1);
  std::unique_ptr<ResidualModels> models(new ResidualModels(2, 1));
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

Status DecodeInts(ArithmeticDecoder* dec, uint32_t n, int dim, Prediction mode,
                  std::vector<int32_t>* values) {
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
