#include "mesh/validate.h"

#include <gtest/gtest.h>

#include <cmath>

#include <limits>
#include <string>

#include "test_meshes.h"

namespace hullpack {
namespace {

using testing_meshes::UnitCube;

// The status is an invalid-mesh error whose message holds every fragment.
void ExpectInvalid(const Status& status, std::initializer_list<const char*> fragments) {
  EXPECT_EQ(status.code(), StatusCode::kInvalidMesh) << status.ToString();
  for (const char* fragment : fragments) {
    EXPECT_NE(status.message().find(fragment), std::string::npos)
        << "missing '" << fragment << "' in: " << status.message();
  }
}

Mesh CubeWithAllAttributes() {
  Mesh mesh = UnitCube();
  const size_t n = mesh.vertex_count();
  mesh.normals.assign(3 * n, 0.5f);
  mesh.tangents.assign(4 * n, 1.0f);
  mesh.uv_sets.assign(2, std::vector<float>(2 * n, 0.25f));
  mesh.colors.assign(4 * n, 1.0f);
  mesh.joints.assign(4 * n, 0);
  mesh.weights.assign(4 * n, 0.25f);
  mesh.material_ids.assign(mesh.triangle_count(), 0);
  return mesh;
}

TEST(ValidateTest, AcceptsWellFormedMeshes) {
  EXPECT_TRUE(ValidateMesh(UnitCube()).ok());
  EXPECT_TRUE(ValidateMesh(CubeWithAllAttributes()).ok());
  EXPECT_TRUE(ValidateMesh(Mesh{}).ok());
}

TEST(ValidateTest, RejectsNanPositionNamingVertexAndCount) {
  Mesh mesh = UnitCube();
  mesh.name = "crate";
  mesh.positions[3 * 5 + 1] = std::numeric_limits<float>::quiet_NaN();
  mesh.positions[3 * 7 + 2] = std::numeric_limits<float>::quiet_NaN();
  ExpectInvalid(ValidateMesh(mesh), {"crate", "positions", "2 non-finite", "vertex 5", "y = nan"});
}

TEST(ValidateTest, RejectsInfinitePosition) {
  Mesh mesh = UnitCube();
  mesh.positions[0] = -std::numeric_limits<float>::infinity();
  ExpectInvalid(ValidateMesh(mesh), {"positions", "1 non-finite value", "vertex 0", "x = -inf"});
}

TEST(ValidateTest, RejectsNonFiniteAttributes) {
  const float inf = std::numeric_limits<float>::infinity();
  Mesh normals = CubeWithAllAttributes();
  normals.normals[3 * 4 + 2] = inf;
  ExpectInvalid(ValidateMesh(normals), {"normals", "vertex 4", "z = inf"});

  Mesh uvs = CubeWithAllAttributes();
  uvs.uv_sets[1][2 * 6 + 1] = std::numeric_limits<float>::quiet_NaN();
  ExpectInvalid(ValidateMesh(uvs), {"uv set 1", "vertex 6", "v = nan"});

  Mesh weights = CubeWithAllAttributes();
  weights.weights[4 * 3] = inf;
  ExpectInvalid(ValidateMesh(weights), {"weights", "vertex 3", "w0 = inf"});

  Mesh tangents = CubeWithAllAttributes();
  tangents.tangents[4 * 2 + 3] = inf;
  ExpectInvalid(ValidateMesh(tangents), {"tangents", "vertex 2", "w = inf"});

  Mesh colors = CubeWithAllAttributes();
  colors.colors[4 * 1 + 3] = inf;
  ExpectInvalid(ValidateMesh(colors), {"colors", "vertex 1", "a = inf"});
}

TEST(ValidateTest, RejectsOutOfRangeIndicesNamingTriangleAndCount) {
  Mesh mesh = UnitCube();
  mesh.indices[3 * 4 + 2] = 8;
  mesh.indices[3 * 9 + 0] = 4000000000u;
  ExpectInvalid(ValidateMesh(mesh), {"2 out of range", "vertex count 8", "triangle 4", "= 8"});
}

TEST(ValidateTest, RejectsIndexCountNotMultipleOfThree) {
  Mesh mesh = UnitCube();
  mesh.indices.push_back(0);
  ExpectInvalid(ValidateMesh(mesh), {"indices", "37", "multiple of 3"});
}

TEST(ValidateTest, RejectsPositionCountNotMultipleOfThree) {
  Mesh mesh = UnitCube();
  mesh.positions.push_back(1);
  ExpectInvalid(ValidateMesh(mesh), {"positions", "25", "multiple of 3"});
}

TEST(ValidateTest, RejectsMalformedMorphTargets) {
  Mesh base = CubeWithAllAttributes();
  MorphTarget t;
  t.positions.assign(24, 0.0f);
  base.morph_targets = {t, t};
  ASSERT_TRUE(ValidateMesh(base).ok());
  Mesh short_target = base;
  short_target.morph_targets[1].positions.resize(21);
  ExpectInvalid(ValidateMesh(short_target), {"morph target 1 positions", "21 values"});
  Mesh one_with_normals = base;
  one_with_normals.morph_targets[1].normals.assign(24, 0.0f);
  ExpectInvalid(ValidateMesh(one_with_normals), {"every target or none"});
  Mesh nan = base;
  nan.morph_targets[0].positions[5] = std::nanf("");
  ExpectInvalid(ValidateMesh(nan), {"morph target 0 positions"});
  Mesh weights = base;
  weights.morph_weights = {1};
  ExpectInvalid(ValidateMesh(weights), {"morph weights", "1 for 2 targets"});
}

TEST(ValidateTest, RejectsAttributeSizeMismatch) {
  Mesh normals = CubeWithAllAttributes();
  normals.normals.resize(21);
  ExpectInvalid(ValidateMesh(normals), {"normals", "21 values for 8 vertices", "expected 24"});

  Mesh uvs = CubeWithAllAttributes();
  uvs.uv_sets[0].pop_back();
  ExpectInvalid(ValidateMesh(uvs), {"uv set 0", "15 values"});

  Mesh joints = CubeWithAllAttributes();
  joints.joints.resize(4);
  ExpectInvalid(ValidateMesh(joints), {"joints"});

  Mesh materials = CubeWithAllAttributes();
  materials.material_ids.resize(11);
  ExpectInvalid(ValidateMesh(materials), {"material_ids", "11 ids for 12 triangles"});
}

TEST(ValidateTest, RejectsJointsWithoutWeights) {
  Mesh mesh = CubeWithAllAttributes();
  mesh.weights.clear();
  ExpectInvalid(ValidateMesh(mesh), {"joints without weights"});
}

}  // namespace
}  // namespace hullpack
