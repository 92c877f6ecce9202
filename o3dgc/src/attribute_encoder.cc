// Attribute encoder (see attribute_coder.h; attribute_decoder.cc is its mirror).
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
      g[3 * size_t(v) + k] = double(geo.positions[3 * size_t(geo.position_of[v]) + k]) * geo.scale[k];
    }
  }
  return g;
}

void EncodeQuantized(ArithmeticEncoder* enc, const MeshAdjacency& adj_in,
                     const std::vector<int32_t>& q_in, int dim, int bits, Prediction mode,
                     const std::vector<double>* geometry) {
  const bool texcoord = geometry && dim == 2 && mode == Prediction::kParallelogram;
  const uint32_t n = uint32_t(q_in.size() / size_t(dim));
  if (mode == Prediction::kNone) {
    for (int32_t v : q_in) enc->EncodeBits(uint32_t(v), bits);
    return;
  }
  // Parallelogram prediction codes the vertices in max-prediction-degree order.
  const MeshAdjacency* adj_ptr = &adj_in;
  const std::vector<int32_t>* q_ptr = &q_in;
  MeshAdjacency renamed;
  std::vector<uint32_t> renamed_tris;
  std::vector<int32_t> q_renamed;
  std::vector<double> geo_renamed;
  if (mode == Prediction::kParallelogram) {
    const std::vector<uint32_t> order = MaxDegreeOrder(adj_in);
    renamed_tris = RenameByOrder(adj_in, order);
    renamed.BuildPermuted(adj_in, order, renamed_tris);
    renamed.SetOpposite(adj_in.opposite());
    q_renamed.resize(q_in.size());
    for (uint32_t i = 0; i < n; ++i) {
      for (int k = 0; k < dim; ++k) q_renamed[size_t(i) * dim + k] = q_in[size_t(order[i]) * dim + k];
    }
    adj_ptr = &renamed;
    q_ptr = &q_renamed;
    if (texcoord) {
      geo_renamed.resize(size_t(n) * 3);
      for (uint32_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) geo_renamed[3 * size_t(i) + k] = (*geometry)[3 * size_t(order[i]) + k];
      }
    }
  }
  const MeshAdjacency& adj = *adj_ptr;
  const std::vector<int32_t>& q = *q_ptr;
  std::unique_ptr<ResidualModels> models(new ResidualModels(dim, 3));
  std::vector<uint32_t> mags(n, 0);
  const int64_t maxq = (int64_t(1) << bits) - 1;
  const int coarse = n < kTinyMesh ? 2 : (n < kSmallMesh ? 1 : 0);
  for (uint32_t c = 0; c < n; ++c) {
    int64_t pred[4];
    int64_t alt[2];
    bool ambiguous;
    const PredictionContext pc =
        PredictAttributeVertex(adj, c, q.data(), dim, texcoord ? geo_renamed.data() : nullptr,
                               mode == Prediction::kParallelogram, mags.data(), maxq, pred, alt, &ambiguous);
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
    const int mctx = MagContext(pc.neighbour_magnitude) >> coarse;
    int64_t r[4];
    for (int k = 0; k < dim; ++k) {
      r[k] = int64_t(q[size_t(c) * dim + k]) - pred[k];
      EncodeSigned(*enc, models->at(coarse == 2 ? 0 : k, pc.kind, mctx, (k && !coarse) ? IntraContext(r[k - 1]) : 0), r[k]);
    }
    mags[c] = SaturatingMagnitude(r, dim);
  }
}

void EncodeOctNormals(ArithmeticEncoder* enc, const MeshAdjacency& adj, const NormalGeometry& geo,
                      const std::vector<float>& normals, int bits) {
  const uint32_t n = uint32_t(normals.size() / 3);
  const uint32_t maxq = uint32_t((uint64_t(1) << bits) - 1);
  std::unique_ptr<ResidualModels> models(new ResidualModels(2, 1));
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
