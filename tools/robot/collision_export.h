// `hullpack collision`'s job, shared by the command line and the Python module: decompose a scene
// into convex hulls and write a robot description (URDF, MJCF or SDF) with one mesh file per hull,
// the visual mesh and the mass properties of the hull union.
//
// Layout written into the output folder:
//   NAME.urdf | NAME.xml | NAME.sdf
//   meshes/NAME_visual.(stl|obj)
//   meshes/NAME_hull_<i>.(stl|obj)
// Every path in the description is relative to it, so the folder can be moved as a whole.
#ifndef HULLPACK_TOOLS_ROBOT_COLLISION_EXPORT_H_
#define HULLPACK_TOOLS_ROBOT_COLLISION_EXPORT_H_

#include <string>
#include <vector>

#include "common/status.h"
#include "pipeline/collision.h"
#include "robot/robot_model.h"
#include "scene/scene.h"
#include "vhacd/vhacd.h"

namespace hullpack {

struct CollisionExportOptions {
  RobotFormat format = RobotFormat::kUrdf;
  std::string name;           // "" = the input file's stem; sanitized either way
  double density = 1000;      // kg/m^3 (water), in the mesh's units cubed
  int max_hull_vertices = 0;  // 0 = DefaultMaxHullVertices(format)
  // Decomposition; max_vertices_per_hull is replaced by the cap above.
  vhacd::Parameters parameters = PackCollisionParameters();
  bool force = false;  // replace existing files
};

struct CollisionExportReport {
  std::string name;
  std::string description;         // path of the description file
  std::vector<std::string> files;  // every file written (the description last)
  size_t hull_count = 0;
  size_t largest_hull_vertices = 0;
  MassProperties mass;
  vhacd::Report decomposition;
};

// Every mesh of `scene`, merged in world space (FlattenScene), is one rigid body. The scene is
// taken by value: moved in, its only mesh becomes the body without a copy. `input_path` names the
// input in errors and gives the default name; `output_dir` is created when missing (its parent
// must exist). Nothing is written unless the decomposition succeeds; each file is written
// atomically; an existing file is an error unless `force`.
Result<CollisionExportReport> ExportCollision(Scene scene, const std::string& input_path,
                                              const std::string& output_dir,
                                              const CollisionExportOptions& options,
                                              vhacd::Observer* observer = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_ROBOT_COLLISION_EXPORT_H_
