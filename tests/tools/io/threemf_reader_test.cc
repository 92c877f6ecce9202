#include "io/threemf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/scene_io.h"
#include "zip_test_util.h"

namespace hullpack {
namespace {

using testing::MakeThreeMf;
using testing::TestZipEntry;

constexpr const char* kModelOpen =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<model unit=\"millimeter\" xml:lang=\"en-US\" "
    "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\" "
    "xmlns:m=\"http://schemas.microsoft.com/3dmanufacturing/material/2015/02\" "
    "xmlns:p=\"http://schemas.microsoft.com/3dmanufacturing/production/2015/06\"";

// A tetrahedron's <mesh>, its triangles carrying `triangle_attributes` (one string per triangle).
std::string TetrahedronMesh(const std::vector<std::string>& triangle_attributes = {"", "", "",
                                                                                   ""}) {
  const char* corners[4] = {"v1=\"0\" v2=\"2\" v3=\"1\"", "v1=\"0\" v2=\"1\" v3=\"3\"",
                            "v1=\"0\" v2=\"3\" v3=\"2\"", "v1=\"1\" v2=\"2\" v3=\"3\""};
  std::string xml =
      "<mesh><vertices><vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"10\" y=\"0\" z=\"0\"/>"
      "<vertex x=\"0\" y=\"10\" z=\"0\"/><vertex x=\"0\" y=\"0\" z=\"10\"/></vertices><triangles>";
  for (int t = 0; t < 4; ++t) {
    xml += std::string("<triangle ") + corners[t] + " " + triangle_attributes[t] + "/>";
  }
  return xml + "</triangles></mesh>";
}

std::string WithUnit(const std::string& unit) {
  std::string xml = kModelOpen;
  xml.replace(xml.find("millimeter"), 10, unit);
  return xml;
}

Result<Scene> Read(const std::vector<uint8_t>& package) {
  return Parse3mf(package.data(), package.size(), "part.3mf");
}

// The world matrix of node `n`, column-major.
Matrix4 WorldOf(const Scene& scene, int n) {
  Matrix4 m = scene.nodes[static_cast<size_t>(n)].local_transform;
  for (int p = scene.nodes[static_cast<size_t>(n)].parent; p >= 0;
       p = scene.nodes[static_cast<size_t>(p)].parent) {
    const Matrix4& a = scene.nodes[static_cast<size_t>(p)].local_transform;
    Matrix4 r{};
    for (int c = 0; c < 4; ++c) {
      for (int row = 0; row < 4; ++row) {
        for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * m[c * 4 + k];
      }
    }
    m = r;
  }
  return m;
}

std::array<double, 3> Apply(const Matrix4& m, double x, double y, double z) {
  return {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
          m[2] * x + m[6] * y + m[10] * z + m[14]};
}

TEST(ThreeMfReader, ReadsAMeshWithABaseMaterialInMetresWithYUp) {
  const std::string xml = std::string(kModelOpen) +
                          "><resources><basematerials id=\"1\"><base name=\"orange\" "
                          "displaycolor=\"#FF800080\"/></basematerials>"
                          "<object id=\"2\" name=\"tet\" type=\"model\" pid=\"1\" pindex=\"0\">" +
                          TetrahedronMesh() +
                          "</object></resources><build><item objectid=\"2\"/></build></model>";
  Result<Scene> scene = Read(MakeThreeMf(xml));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->meshes.size(), 1u);
  const Mesh& mesh = scene->meshes[0];
  EXPECT_EQ(mesh.name, "tet");
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_EQ(mesh.positions[3], 10.0f);  // the file's millimetres stay in the mesh arrays
  EXPECT_EQ(mesh.material_ids, (std::vector<uint32_t>{0, 0, 0, 0}));
  ASSERT_EQ(scene->materials.size(), 1u);
  const Material& orange = scene->materials[0];
  EXPECT_EQ(orange.name, "orange");
  EXPECT_FLOAT_EQ(orange.base_color[0], 1.0f);
  EXPECT_NEAR(orange.base_color[1], 0.2158605f, 1e-5);  // sRGB 128/255, linear
  EXPECT_NEAR(orange.base_color[3], 128.0f / 255.0f, 1e-6);
  EXPECT_EQ(orange.alpha_mode, AlphaMode::kBlend);
  EXPECT_EQ(scene->source_vertex_records, 4u);

  // The root turns millimetres into metres and +Z up into +Y up.
  ASSERT_EQ(scene->nodes.size(), 2u);
  EXPECT_EQ(scene->nodes[0].name, "part.3mf");
  ASSERT_EQ(scene->nodes[1].meshes, (std::vector<int>{0}));
  const std::array<double, 3> top = Apply(WorldOf(scene.value(), 1), 0, 0, 10);
  EXPECT_NEAR(top[0], 0, 1e-12);
  EXPECT_NEAR(top[1], 0.01, 1e-12);
  EXPECT_NEAR(top[2], 0, 1e-12);
  const std::array<double, 3> side = Apply(WorldOf(scene.value(), 1), 0, 10, 0);
  EXPECT_NEAR(side[2], -0.01, 1e-12);
}

TEST(ThreeMfReader, ComponentsAndBuildItemsPlaceOneMeshManyTimes) {
  const std::string xml =
      WithUnit("meter") + "><resources><object id=\"1\">" + TetrahedronMesh() +
      "</object><object id=\"5\" name=\"pair\"><components>"
      "<component objectid=\"1\"/>"
      "<component objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 100 0 0\"/>"
      "</components></object></resources><build>"
      "<item objectid=\"5\" transform=\"0 1 0 -1 0 0 0 0 1 0 0 7\"/><item objectid=\"1\"/>"
      "</build></model>";
  Result<Scene> scene = Read(MakeThreeMf(xml));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->meshes.size(), 1u);
  int placements = 0;
  for (const Node& node : scene->nodes) placements += static_cast<int>(node.meshes.size());
  EXPECT_EQ(placements, 3);
  // nodes: root, pair, two components, the second item.
  ASSERT_EQ(scene->nodes.size(), 5u);
  EXPECT_EQ(scene->nodes[1].name, "pair");
  EXPECT_EQ(scene->nodes[3].parent, 1);
  // The second component: moved 100 along x, then the item turns x into y and lifts z by 7;
  // the root turns z into y (the unit is metres).
  const std::array<double, 3> p = Apply(WorldOf(scene.value(), 3), 0, 0, 0);
  EXPECT_NEAR(p[0], 0, 1e-9);
  EXPECT_NEAR(p[1], 7, 1e-9);
  EXPECT_NEAR(p[2], -100, 1e-9) << p[0] << " " << p[1] << " " << p[2];
}

TEST(ThreeMfReader, ColourGroupsBecomeVertexColoursAndTexturesUvs) {
  const std::string colours =
      std::string(kModelOpen) +
      "><resources><m:colorgroup id=\"3\"><m:color color=\"#FF0000\"/><m:color "
      "color=\"#0000FF\"/></m:colorgroup><object id=\"1\">" +
      TetrahedronMesh({"pid=\"3\" p1=\"0\"", "pid=\"3\" p1=\"1\"", "pid=\"3\" p1=\"0\" p2=\"1\"",
                       "pid=\"3\" p1=\"0\""}) +
      "</object></resources><build><item objectid=\"1\"/></build></model>";
  Result<Scene> scene = Read(MakeThreeMf(colours));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const Mesh& mesh = scene->meshes[0];
  ASSERT_EQ(mesh.colors.size(), mesh.vertex_count() * 4);
  // Vertices 0, 1 and 3 are red in some triangles and blue in others: each is split.
  EXPECT_EQ(mesh.vertex_count(), 7u);
  for (size_t t = 0; t < 4; ++t) {
    const float blue_expected = t == 1 ? 1.0f : 0.0f;
    EXPECT_EQ(mesh.colors[4 * mesh.indices[3 * t] + 2], blue_expected) << t;
  }

  const std::string textured =
      std::string(kModelOpen) +
      "><resources><m:texture2d id=\"7\" path=\"/3D/Textures/wood.png\" contenttype=\"image/png\" "
      "tilestyleu=\"clamp\" filter=\"nearest\"/><m:texture2dgroup id=\"8\" texid=\"7\">"
      "<m:tex2coord u=\"0\" v=\"0\"/><m:tex2coord u=\"1\" v=\"0.25\"/></m:texture2dgroup>"
      "<object id=\"1\" pid=\"8\" pindex=\"0\">" +
      TetrahedronMesh({"p1=\"0\" p2=\"1\" p3=\"1\"", "", "", ""}) +
      "</object></resources><build><item objectid=\"1\"/></build></model>";
  scene = Read(MakeThreeMf(textured, {{"3D/Textures/wood.png", "PNG bytes", false}}));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const Mesh& uv_mesh = scene->meshes[0];
  ASSERT_EQ(uv_mesh.uv_sets.size(), 1u);
  // Corner 2 of the first triangle: (1, 0.25) with v = 0 at the bottom, (1, 0.75) in glTF's.
  const uint32_t v = uv_mesh.indices[1];
  EXPECT_EQ(uv_mesh.uv_sets[0][2 * v], 1.0f);
  EXPECT_EQ(uv_mesh.uv_sets[0][2 * v + 1], 0.75f);
  ASSERT_EQ(scene->images.size(), 1u);
  EXPECT_EQ(scene->images[0].mime_type, "image/png");
  EXPECT_EQ(std::string(scene->images[0].bytes.begin(), scene->images[0].bytes.end()), "PNG bytes");
  ASSERT_EQ(scene->materials.size(), 1u);
  EXPECT_EQ(scene->materials[0].base_color_texture.image, 0);
  EXPECT_EQ(scene->materials[0].base_color_texture.sampler.wrap_s, 33071);
  EXPECT_EQ(scene->materials[0].base_color_texture.sampler.mag_filter, 9728);
}

TEST(ThreeMfReader, ReadsObjectsFromOtherModelParts) {
  const std::string root = std::string(kModelOpen) +
                           "><resources/><build><item objectid=\"4\" "
                           "p:path=\"/3D/Objects/wheel.model\"/></build></model>";
  const std::string wheel = std::string(kModelOpen) +
                            "><resources><object id=\"4\" name=\"wheel\">" + TetrahedronMesh() +
                            "</object></resources><build/></model>";
  Result<Scene> scene = Read(MakeThreeMf(root, {{"3D/Objects/wheel.model", wheel}}));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->meshes.size(), 1u);
  EXPECT_EQ(scene->meshes[0].name, "wheel");

  Result<Scene> missing = Read(MakeThreeMf(root));
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().message(),
            "part.3mf: the package has no model part '/3D/Objects/wheel.model'");
}

TEST(ThreeMfReader, SupportObjectsAreLeftOutAndListed) {
  const std::string xml = std::string(kModelOpen) + "><resources><object id=\"1\">" +
                          TetrahedronMesh() + "</object><object id=\"2\" type=\"support\">" +
                          TetrahedronMesh() +
                          "</object></resources><build><item objectid=\"1\"/><item "
                          "objectid=\"2\"/></build></model>";
  Result<Scene> scene = Read(MakeThreeMf(xml));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->meshes.size(), 1u);
  ASSERT_EQ(scene->dropped.size(), 1u);
  EXPECT_NE(scene->dropped[0].find("1 support object"), std::string::npos);
}

TEST(ThreeMfReader, BadPackagesAreErrorsThatSayWhy) {
  auto error_of = [](const std::string& body) {
    Result<Scene> s = Read(MakeThreeMf(std::string(kModelOpen) + body));
    return s.ok() ? std::string("ok") : s.status().message();
  };
  const std::string tet = "<object id=\"1\">" + TetrahedronMesh() + "</object>";
  EXPECT_EQ(error_of(" requiredextensions=\"b\" xmlns:b=\"http://schemas.microsoft.com/"
                     "3dmanufacturing/beamlattice/2017/02\"><resources/><build/></model>"),
            "part.3mf: 3D/3dmodel.model: requires the 3MF extension "
            "http://schemas.microsoft.com/3dmanufacturing/beamlattice/2017/02, which hullpack "
            "does not read (it reads the core specification and the materials and production "
            "extensions)");
  EXPECT_EQ(
      error_of("><resources>" + tet + "</resources><build><item objectid=\"9\"/></build></model>"),
      "part.3mf: object 9 in 3D/3dmodel.model is referenced but not defined");
  EXPECT_EQ(error_of("><resources><object id=\"1\"><components><component objectid=\"1\"/>"
                     "</components></object></resources><build><item objectid=\"1\"/></build>"
                     "</model>"),
            "part.3mf: components nest deeper than 32 (a cycle?)");
  EXPECT_EQ(error_of("><resources>" + tet + tet + "</resources><build/></model>"),
            "part.3mf: 3D/3dmodel.model: line 2: resource id 1 is used twice");
  EXPECT_EQ(error_of("><resources><object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"0\" "
                     "z=\"0\"/></vertices><triangles><triangle v1=\"0\" v2=\"1\" v3=\"2\"/>"
                     "</triangles></mesh></object></resources><build><item objectid=\"1\"/>"
                     "</build></model>"),
            "part.3mf: object 1 in 3D/3dmodel.model: triangle 0 refers to vertex 1, but it has 1");
  EXPECT_EQ(error_of("><resources><object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"nan\" "
                     "z=\"0\"/></vertices></mesh></object></resources><build/></model>"),
            "part.3mf: 3D/3dmodel.model: line 2: <vertex> y 'nan' is not a finite number");
  EXPECT_EQ(error_of("><resources><object id=\"1\" pid=\"6\">" + TetrahedronMesh() +
                     "</object></resources><build><item objectid=\"1\"/></build></model>"),
            "part.3mf: object 1 in 3D/3dmodel.model refers to property group 6, which the part "
            "does not define");
  EXPECT_EQ(error_of("><resources><basematerials id=\"2\"><base displaycolor=\"#FFFFFF\"/>"
                     "</basematerials><object id=\"1\" pid=\"2\" pindex=\"3\">" +
                     TetrahedronMesh() +
                     "</object></resources><build><item objectid=\"1\"/></build></model>"),
            "part.3mf: object 1 in 3D/3dmodel.model refers to entry 3 of property group 2, which "
            "has 1");
  EXPECT_EQ(error_of("><resources><object id=\"1\"><mesh></object></resources></model>"),
            "part.3mf: 3D/3dmodel.model: line 2: malformed XML: end tag 'object' does not match "
            "'mesh'");
}

TEST(ThreeMfReader, ComponentsThatMultiplyWithoutBoundAreRefused) {
  // Each level places the one below ten times: 10^7 leaves from 8 small objects.
  std::string xml =
      std::string(kModelOpen) + "><resources><object id=\"1\">" + TetrahedronMesh() + "</object>";
  for (int level = 2; level <= 8; ++level) {
    xml += "<object id=\"" + std::to_string(level) + "\"><components>";
    for (int k = 0; k < 10; ++k)
      xml += "<component objectid=\"" + std::to_string(level - 1) + "\"/>";
    xml += "</components></object>";
  }
  xml += "</resources><build><item objectid=\"8\"/></build></model>";
  Result<Scene> scene = Read(MakeThreeMf(xml));
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().message(), "part.3mf: its components place more than 1000000 objects");
}

TEST(ThreeMfReader, DamagedPackagesNeverCrash) {
  const std::string xml = std::string(kModelOpen) +
                          "><resources><m:colorgroup id=\"3\"><m:color color=\"#FF0000\"/>"
                          "</m:colorgroup><object id=\"1\" pid=\"3\" pindex=\"0\">" +
                          TetrahedronMesh() +
                          "</object></resources><build><item objectid=\"1\"/></build></model>";
  std::vector<TestZipEntry> stored = {{"3D/3dmodel.model", xml, false}};
  const std::vector<uint8_t> package = testing::MakeZip(stored);
  ASSERT_TRUE(Read(package).ok());  // found without _rels/.rels, by its conventional name
  size_t read = 0;
  for (size_t at = 0; at < package.size(); ++at) {
    std::vector<uint8_t> damaged = package;
    damaged[at] = static_cast<uint8_t>(damaged[at] ^ (at % 2 ? 0x20 : 0x09));
    Result<Scene> scene = Read(damaged);
    if (!scene.ok()) continue;
    ++read;
    for (const Mesh& m : scene->meshes) {
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
    }
  }
  EXPECT_GT(read, 0u);
}

TEST(ThreeMfReader, ReadSceneDispatchesOnTheExtension) {
  const std::string xml = std::string(kModelOpen) + "><resources><object id=\"1\">" +
                          TetrahedronMesh() +
                          "</object></resources><build><item objectid=\"1\"/></build></model>";
  const std::vector<uint8_t> package = MakeThreeMf(xml);
  EXPECT_EQ(FormatFromExtension("x/Part.3MF"), FileFormat::kThreeMf);
  Result<Scene> scene =
      ReadSceneFromMemory(package.data(), package.size(), FileFormat::kThreeMf, "mem.3mf");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->triangle_count(), 4u);
}

}  // namespace
}  // namespace hullpack
