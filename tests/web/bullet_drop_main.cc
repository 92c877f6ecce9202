// web_bullet_drop FILE.glb: the native reference of the engine drop tests (engines_test.mjs). Reads
// a packed GLB with the C++ reader, drops the compound of its collision hulls (ReadCollisionHulls,
// body-node space) from z = 2 onto the plane z = 0 in Bullet (gravity -z, 4 s at 240 Hz, as
// physics_test.cc), and prints JSON: the body origin's resting height, the render mesh's z extent,
// and every hull's points as the C++ reader gives them.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../tools/pipeline/bullet_drop.h"
#include "packed/packed_glb_reader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: web_bullet_drop FILE.glb\n");
    return 64;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<uint8_t> glb((std::istreambuf_iterator<char>(in)), {});
  hullpack::GltfDocument doc;
  hullpack::Result<hullpack::Scene> scene =
      hullpack::ReadPackedGltf(glb.data(), glb.size(), argv[1], "", &doc);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.status().ToString().c_str());
    return 1;
  }
  hullpack::Result<std::vector<hullpack::CollisionHull>> hulls =
      hullpack::ReadCollisionHulls(doc, argv[1]);
  if (!hulls.ok() || hulls->empty() || scene->meshes.empty()) {
    std::fprintf(stderr, "%s: no collision hulls\n", argv[1]);
    return 1;
  }
  std::vector<hullpack::Mesh> meshes;
  for (const hullpack::CollisionHull& h : hulls.value()) meshes.push_back(h.hull);
  const hullpack::Mesh& render = scene->meshes[0];
  const hullpack::testing::Drop d = hullpack::testing::DropOnPlane(render, meshes, 2.0, 4.0);
  double lo = 1e300, hi = -1e300;
  for (size_t v = 0; v < render.vertex_count(); ++v) {
    lo = std::min<double>(lo, render.positions[v * 3 + 2]);
    hi = std::max<double>(hi, render.positions[v * 3 + 2]);
  }
  std::printf(
      "{\"restZ\": %.9g, \"lowestMeshZ\": %.9g, \"speed\": %.9g, \"tilt\": %.9g, "
      "\"height\": %.9g, \"hulls\": [",
      d.rest_z, d.lowest_mesh_z, d.speed, d.tilt, hi - lo);
  for (size_t h = 0; h < meshes.size(); ++h) {
    std::printf("%s\n  [", h ? "," : "");
    for (size_t i = 0; i < meshes[h].positions.size(); ++i)
      std::printf("%s%.9g", i ? "," : "", static_cast<double>(meshes[h].positions[i]));
    std::printf("]");
  }
  std::printf("]}\n");
  return 0;
}
