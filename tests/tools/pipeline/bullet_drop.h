// Drops a compound of convex hulls on a plane in Bullet (Debian's libbullet-dev): the native
// physics reference of physics_test.cc, robot_physics_test.cc and of the engine drop tests in
// tests/web/ (web_bullet_drop). Header-only test helper.
#ifndef HULLPACK_TESTS_TOOLS_PIPELINE_BULLET_DROP_H_
#define HULLPACK_TESTS_TOOLS_PIPELINE_BULLET_DROP_H_

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "scene/scene.h"

namespace hullpack {
namespace testing {

struct Drop {
  double rest_z = 0;         // the body origin's height at the end
  double lowest_mesh_z = 0;  // of the input mesh, moved by the body's final transform
  double speed = 0;          // linear speed at the end
  double tilt = 0;           // angle (radians) between the body's z axis and the world's
};

// A Bullet world with gravity along -z and the static ground plane z = 0.
struct PlaneWorld {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
  btRigidBody ground{btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &plane)};

  PlaneWorld() {
    world.setGravity(btVector3(0, 0, -9.81));
    world.addRigidBody(&ground);
  }
  ~PlaneWorld() { world.removeRigidBody(&ground); }
  PlaneWorld(const PlaneWorld&) = delete;
  PlaneWorld& operator=(const PlaneWorld&) = delete;
};

// Convex hulls as one compound shape, each point moved by -offset (e.g. into a centre-of-mass
// frame).
struct HullCompound {
  btCompoundShape compound;
  std::vector<std::unique_ptr<btConvexHullShape>> parts;

  explicit HullCompound(const std::vector<Mesh>& hulls, const double offset[3] = nullptr) {
    const double zero[3] = {0, 0, 0};
    const double* o = offset != nullptr ? offset : zero;
    for (const Mesh& hull : hulls) {
      auto shape = std::make_unique<btConvexHullShape>();
      for (size_t v = 0; v < hull.vertex_count(); ++v) {
        shape->addPoint(btVector3(hull.positions[v * 3] - o[0], hull.positions[v * 3 + 1] - o[1],
                                  hull.positions[v * 3 + 2] - o[2]),
                        false);
      }
      shape->recalcLocalAabb();
      shape->setMargin(0.001f);
      btTransform identity;
      identity.setIdentity();
      compound.addChildShape(identity, shape.get());
      parts.push_back(std::move(shape));
    }
  }
};

// Drops the hull compound of `mesh` from `height` onto the plane z = 0 and simulates `seconds`.
inline Drop DropOnPlane(const Mesh& mesh, const std::vector<Mesh>& hulls, double height,
                        double seconds) {
  PlaneWorld pw;
  btDiscreteDynamicsWorld& world = pw.world;
  HullCompound hull_compound(hulls);
  btCompoundShape& compound = hull_compound.compound;
  const btScalar mass = 1;
  btVector3 inertia;
  compound.calculateLocalInertia(mass, inertia);
  btTransform start;
  start.setIdentity();
  start.setOrigin(btVector3(0, 0, height));
  btDefaultMotionState motion(start);
  btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(mass, &motion, &compound, inertia));
  world.addRigidBody(&body);
  for (int step = 0; step < static_cast<int>(seconds * 240); ++step)
    world.stepSimulation(1.0 / 240, 1, 1.0 / 240);

  Drop d;
  btTransform end;
  motion.getWorldTransform(end);
  d.lowest_mesh_z = 1e300;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const btVector3 p = end * btVector3(mesh.positions[v * 3], mesh.positions[v * 3 + 1],
                                        mesh.positions[v * 3 + 2]);
    d.lowest_mesh_z = std::min<double>(d.lowest_mesh_z, p.z());
  }
  d.rest_z = end.getOrigin().z();
  d.speed = body.getLinearVelocity().length();
  const btVector3 up = end.getBasis() * btVector3(0, 0, 1);
  d.tilt = std::acos(std::min<btScalar>(1, std::max<btScalar>(-1, up.z())));
  world.removeRigidBody(&body);
  return d;
}

}  // namespace testing
}  // namespace hullpack

#endif  // HULLPACK_TESTS_TOOLS_PIPELINE_BULLET_DROP_H_
