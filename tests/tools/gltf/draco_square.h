// A Draco-compressed square for the tests of the readers of KHR_draco_mesh_compression: its
// stream (libdraco's encoder) and a GLB document that references it as glTF-Transform writes one.
#ifndef HULLPACK_TESTS_TOOLS_GLTF_DRACO_SQUARE_H_
#define HULLPACK_TESTS_TOOLS_GLTF_DRACO_SQUARE_H_

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "gltf/draco_inflate.h"
#include "gltf/gltf_document.h"

namespace hullpack {

// A square of two triangles with UVs and a normalized byte colour, as Draco streams it.
struct DracoSquare {
  std::vector<uint8_t> stream;
  int position_id = -1, uv_id = -1, color_id = -1;
};

inline DracoSquare EncodeSquare() {
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const uint8_t color[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {9, 9, 9, 9}};
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2);
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int tex = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const int col = builder.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_UINT8);
  for (int f = 0; f < 2; ++f) {
    const int* c = faces[f];
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), p[c[0]], p[c[1]], p[c[2]]);
    builder.SetAttributeValuesForFace(tex, draco::FaceIndex(f), uv[c[0]], uv[c[1]], uv[c[2]]);
    builder.SetAttributeValuesForFace(col, draco::FaceIndex(f), color[c[0]], color[c[1]],
                                      color[c[2]]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  mesh->attribute(col)->set_normalized(true);
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  DracoSquare out;
  out.stream.assign(buffer.data(), buffer.data() + buffer.size());
  out.position_id = mesh->attribute(pos)->unique_id();
  out.uv_id = mesh->attribute(tex)->unique_id();
  out.color_id = mesh->attribute(col)->unique_id();
  return out;
}

// A GLB document whose one primitive is the Draco square, as glTF-Transform writes it: accessors
// without bufferViews, the stream in a bufferView of the binary chunk.
inline GltfDocument DracoDocument(const DracoSquare& square, size_t points, bool required = true) {
  GltfDocument doc;
  const int view = doc.AddBufferView(square.stream, 4);
  auto accessor = [&](int ctype, size_t count, const char* type, bool normalized) {
    AccessorDesc d;
    d.component_type = ctype;
    d.count = count;
    d.type = type;
    d.normalized = normalized;
    return doc.AddAccessor(d);
  };
  const int position = accessor(gltf::kFloat, points, "VEC3", false);
  const int uv = accessor(gltf::kFloat, points, "VEC2", false);
  const int color = accessor(gltf::kUnsignedByte, points, "VEC4", true);
  const int indices = accessor(gltf::kUnsignedShort, 6, "SCALAR", false);
  nlohmann::json prim = {
      {"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}, {"COLOR_0", color}}},
      {"indices", indices},
      {"extensions",
       {{kDracoExtension,
         {{"bufferView", view},
          {"attributes",
           {{"POSITION", square.position_id},
            {"TEXCOORD_0", square.uv_id},
            {"COLOR_0", square.color_id}}}}}}}};
  doc.Append("meshes", {{"primitives", nlohmann::json::array({prim})}});
  doc.Append("nodes", {{"mesh", 0}});
  doc.json()["scenes"] = nlohmann::json::array({{{"nodes", {0}}}});
  doc.UseExtension(kDracoExtension, required);
  doc.json()["buffers"] = nlohmann::json::array({{{"byteLength", doc.binary().size()}}});
  return doc;
}

}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_GLTF_DRACO_SQUARE_H_
