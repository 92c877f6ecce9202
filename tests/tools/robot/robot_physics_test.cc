// The URDF as a simulator would load it: its collision meshes (read back from the STL files it
// names, relative to it), its mass and inertia, into Bullet; a dropped body comes to rest where the
// exact mesh rests, within 1 % of the mesh's height: where the mesh itself (a GImpact triangle mesh
// body) comes to rest, and lying flat on its lowest point.
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "../pipeline/bullet_drop.h"
#include "common/file_util.h"
#include "common/test_shapes.h"
#include "io/scene_io.h"
#include "robot/collision_export.h"

namespace hullpack {
namespace {

struct LoadedUrdf {
  double mass = 0, com[3] = {0, 0, 0}, inertia[3] = {0, 0, 0};
  std::vector<Mesh> hulls;
};

std::string Attribute(const std::string& xml, size_t from, const std::string& name) {
  const size_t at = xml.find(name + "=\"", from);
  if (at == std::string::npos) return "";
  const size_t start = at + name.size() + 2;
  return xml.substr(start, xml.find('"', start) - start);
}

// Reads what a simulator takes from our URDF: the inertial and each <collision>'s mesh file.
LoadedUrdf LoadUrdf(const std::string& dir, const std::string& file) {
  LoadedUrdf u;
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(dir + "/" + file);
  if (!bytes.ok()) return u;
  const std::string xml(bytes->begin(), bytes->end());
  const size_t inertial = xml.find("<inertial>");
  u.mass = std::atof(Attribute(xml, inertial, "value").c_str());
  std::sscanf(Attribute(xml, inertial, "xyz").c_str(), "%lf %lf %lf", &u.com[0], &u.com[1],
              &u.com[2]);
  u.inertia[0] = std::atof(Attribute(xml, inertial, "ixx").c_str());
  u.inertia[1] = std::atof(Attribute(xml, inertial, "iyy").c_str());
  u.inertia[2] = std::atof(Attribute(xml, inertial, "izz").c_str());
  for (size_t at = xml.find("<collision"); at != std::string::npos;
       at = xml.find("<collision", at + 1)) {
    Result<Scene> mesh = ReadScene(dir + "/" + Attribute(xml, at, "filename"));
    if (mesh.ok() && !mesh->meshes.empty()) u.hulls.push_back(mesh->meshes[0]);
  }
  return u;
}

// Drops a body of the URDF's mass and inertia with `shape` (in the centre-of-mass frame) from
// `drop` above the plane z = 0; returns the lowest point of `mesh` moved by the body's final pose,
// and its tilt.
double DropOnPlane(const Mesh& mesh, const LoadedUrdf& u, btCollisionShape* shape, double drop,
                   double* tilt) {
  testing::PlaneWorld pw;
  btGImpactCollisionAlgorithm::registerAlgorithm(&pw.dispatcher);
  btDiscreteDynamicsWorld& world = pw.world;

  double min_z = 1e300;
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    min_z = std::min<double>(min_z, mesh.positions[v * 3 + 2]);
  btTransform start;
  start.setIdentity();
  start.setOrigin(btVector3(0, 0, u.com[2] - min_z + drop));
  btDefaultMotionState motion(start);
  btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(
      u.mass, &motion, shape, btVector3(u.inertia[0], u.inertia[1], u.inertia[2])));
  world.addRigidBody(&body);
  for (int step = 0; step < 3 * 240; ++step) world.stepSimulation(1.0 / 240, 1, 1.0 / 240);

  btTransform end;
  motion.getWorldTransform(end);
  double lowest = 1e300;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const btVector3 p =
        end * btVector3(mesh.positions[v * 3] - u.com[0], mesh.positions[v * 3 + 1] - u.com[1],
                        mesh.positions[v * 3 + 2] - u.com[2]);
    lowest = std::min<double>(lowest, p.z());
  }
  const btVector3 up = end.getBasis() * btVector3(0, 0, 1);
  *tilt = std::acos(std::min<btScalar>(1, std::max<btScalar>(-1, up.z())));
  world.removeRigidBody(&body);
  return lowest;
}

// The URDF's hulls as one compound (Bullet's body frame is the centre of mass: shifted by it).
double DropHulls(const Mesh& mesh, const LoadedUrdf& u, double drop, double* tilt) {
  testing::HullCompound hulls(u.hulls, u.com);
  return DropOnPlane(mesh, u, &hulls.compound, drop, tilt);
}

// The exact mesh as a moving triangle mesh (GImpact), with the same mass and inertia.
double DropExactMesh(const Mesh& mesh, const LoadedUrdf& u, double drop, double* tilt) {
  std::vector<btScalar> points(mesh.positions.size());
  for (size_t i = 0; i < points.size(); ++i) points[i] = mesh.positions[i] - u.com[i % 3];
  std::vector<int> indices(mesh.indices.begin(), mesh.indices.end());
  btTriangleIndexVertexArray array(static_cast<int>(mesh.triangle_count()), indices.data(),
                                   3 * sizeof(int), static_cast<int>(mesh.vertex_count()),
                                   points.data(), 3 * sizeof(btScalar));
  btGImpactMeshShape shape(&array);
  shape.setMargin(0.001f);
  shape.updateBound();
  return DropOnPlane(mesh, u, &shape, drop, tilt);
}

// An L-shaped block (2 x 2 x 1 with a 1 x 1 notch), lying on its flat side.
Mesh LBlock() {
  const float p[6][2] = {{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}};
  Mesh m;
  m.name = "l_block";
  for (float z : {0.0f, 1.0f})
    for (const auto& q : p) m.positions.insert(m.positions.end(), {q[0], q[1], z});
  for (uint32_t i = 1; i + 1 < 6; ++i) {
    m.indices.insert(m.indices.end(), {0, i + 1, i});
    m.indices.insert(m.indices.end(), {6, 6 + i, 6 + i + 1});
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    m.indices.insert(m.indices.end(), {i, j, 6 + j, i, 6 + j, 6 + i});
  }
  return m;
}

class RobotPhysics : public ::testing::TestWithParam<int> {};

TEST_P(RobotPhysics, UrdfHullsRestWhereTheMeshRests) {
  Mesh mesh;
  if (GetParam() == 0) {
    test_shapes::AppendTo(test_shapes::Torus(1, 0.3, 40, 16), &mesh);
    mesh.name = "torus";
  } else {
    mesh = LBlock();
  }
  char dir_template[] = "/tmp/hullpack_robot_physics_XXXXXX";
  ASSERT_NE(mkdtemp(dir_template), nullptr);
  const std::string dir = dir_template;
  Scene scene;
  scene.meshes = {mesh};
  AddRootNodeForAllMeshes(scene, mesh.name);
  CollisionExportOptions options;
  options.parameters.resolution = 50000;
  Result<CollisionExportReport> r = ExportCollision(scene, mesh.name + ".obj", dir, options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const LoadedUrdf u = LoadUrdf(dir, mesh.name + ".urdf");
  ASSERT_EQ(u.hulls.size(), r->hull_count);
  ASSERT_GT(u.mass, 0);
  double lo = 1e300, hi = -1e300;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    lo = std::min<double>(lo, mesh.positions[v * 3 + 2]);
    hi = std::max<double>(hi, mesh.positions[v * 3 + 2]);
  }
  double tilt = 0, exact_tilt = 0;
  const double lowest = DropHulls(mesh, u, 0.3, &tilt);
  const double exact = DropExactMesh(mesh, u, 0.3, &exact_tilt);
  const double tolerance = 0.01 * (hi - lo);
  std::printf("rest of the lowest mesh point: hulls %.5f, exact mesh %.5f (1 %% of height %.5f)\n",
              lowest, exact, tolerance);
  EXPECT_NEAR(lowest, exact, tolerance);
  EXPECT_NEAR(lowest, 0.0, tolerance);  // lying flat on the plane, as the mesh does
  EXPECT_LT(tilt, 0.02);
  EXPECT_LT(exact_tilt, 0.02);
  for (const std::string& f : r->files) unlink(f.c_str());
  rmdir((dir + "/meshes").c_str());
  rmdir(dir.c_str());
}

INSTANTIATE_TEST_SUITE_P(Shapes, RobotPhysics, ::testing::Values(0, 1));

}  // namespace
}  // namespace hullpack
