#include "bench/draco_bridge.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

namespace hullpack {

std::unique_ptr<draco::Mesh> ToDracoMesh(const Mesh& m) {
  draco::TriangleSoupMeshBuilder b;
  b.Start(static_cast<int>(m.triangle_count()));
  const int pos = b.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int nrm = m.normals.empty()
                      ? -1
                      : b.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int tex = m.uv_sets.empty()
                      ? -1
                      : b.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const int col =
      m.colors.empty() ? -1 : b.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_FLOAT32);
  // Skins as glTF's Draco extension carries them: generic attributes.
  const int wgt = m.weights.empty()
                      ? -1
                      : b.AddAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_FLOAT32);
  const int jnt = m.joints.empty()
                      ? -1
                      : b.AddAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_UINT16);
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const uint32_t* c = &m.indices[t * 3];
    const draco::FaceIndex f(static_cast<uint32_t>(t));
    b.SetAttributeValuesForFace(pos, f, &m.positions[c[0] * 3], &m.positions[c[1] * 3],
                                &m.positions[c[2] * 3]);
    if (nrm >= 0)
      b.SetAttributeValuesForFace(nrm, f, &m.normals[c[0] * 3], &m.normals[c[1] * 3],
                                  &m.normals[c[2] * 3]);
    if (tex >= 0) {
      const std::vector<float>& uv = m.uv_sets[0];
      b.SetAttributeValuesForFace(tex, f, &uv[c[0] * 2], &uv[c[1] * 2], &uv[c[2] * 2]);
    }
    if (col >= 0)
      b.SetAttributeValuesForFace(col, f, &m.colors[c[0] * 4], &m.colors[c[1] * 4],
                                  &m.colors[c[2] * 4]);
    if (wgt >= 0)
      b.SetAttributeValuesForFace(wgt, f, &m.weights[c[0] * 4], &m.weights[c[1] * 4],
                                  &m.weights[c[2] * 4]);
    if (jnt >= 0)
      b.SetAttributeValuesForFace(jnt, f, &m.joints[c[0] * 4], &m.joints[c[1] * 4],
                                  &m.joints[c[2] * 4]);
  }
  return b.Finalize();
}

std::vector<uint8_t> DracoEncode(const draco::Mesh& mesh, int qp, int qn, int qt, int level) {
  draco::Encoder enc;
  enc.SetAttributeQuantization(draco::GeometryAttribute::POSITION, qp);
  enc.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, qn);
  enc.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, qt);
  enc.SetAttributeQuantization(draco::GeometryAttribute::COLOR, 10);    // as hullpack's colours
  enc.SetAttributeQuantization(draco::GeometryAttribute::GENERIC, 10);  // weights, as hullpack's
  enc.SetSpeedOptions(10 - level, 10 - level);
  draco::EncoderBuffer buffer;
  if (!enc.EncodeMeshToBuffer(mesh, &buffer).ok()) return {};
  return std::vector<uint8_t>(buffer.data(), buffer.data() + buffer.size());
}

Mesh DracoDecodePositions(const std::vector<uint8_t>& bytes) {
  Mesh m;
  draco::DecoderBuffer in;
  in.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  draco::Decoder dec;
  auto r = dec.DecodeMeshFromBuffer(&in);
  if (!r.ok()) return m;
  const std::unique_ptr<draco::Mesh> d = std::move(r).value();
  const draco::PointAttribute* att = d->GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (!att) return m;
  m.positions.resize(d->num_points() * 3);
  for (uint32_t i = 0; i < d->num_points(); ++i)
    att->GetMappedValue(draco::PointIndex(i), &m.positions[i * 3]);
  return m;
}

}  // namespace hullpack
