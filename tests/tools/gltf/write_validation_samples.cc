// Writes the GLBs that the glTF-Validator test checks: gltf_write_samples OUTPUT_DIR.
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "gltf/glb_writer.h"
#include "gltf_test_scenes.h"

namespace {

bool Write(const std::string& dir, const std::string& name, const hullpack::Scene& scene) {
  hullpack::Result<std::vector<uint8_t>> glb = hullpack::EncodeGlb(scene);
  if (!glb.ok()) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), glb.status().ToString().c_str());
    return false;
  }
  const std::string path = dir + "/" + name;
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(glb->data()), static_cast<std::streamsize>(glb->size()));
  if (!out) {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return false;
  }
  std::printf("wrote %s (%zu bytes)\n", path.c_str(), glb->size());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  mkdir(dir.c_str(), 0755);
  using namespace hullpack;
  // The rich scene's external image, so the validator can load and check it too.
  mkdir((dir + "/textures").c_str(), 0755);
  const std::vector<uint8_t>& png = testing_gltf::TinyPng();
  std::ofstream(dir + "/textures/wood dark.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  bool ok = Write(dir, "rich.glb", testing_gltf::MakeRichScene());
  ok = Write(dir, "large.glb", testing_gltf::MakeLargeScene()) && ok;
  Scene plain;
  plain.meshes.push_back(testing_gltf::MakeGrid(2, 2, 1, 0.0f));
  plain.meshes.back().name = "grid";
  Mesh hull;  // a closed tetrahedron, as a hull set would hold
  hull.name = "hull 0";
  hull.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  hull.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  plain.meshes.push_back(hull);
  ok = Write(dir, "no_nodes.glb", plain) && ok;

  // A deliberately wrong file (POSITION max too small) that the validator must reject, so the
  // validator test is known to be able to fail.
  GltfDocument broken;
  if (!BuildGltfDocument(plain, {}, &broken, nullptr).ok()) return 1;
  broken.json()["accessors"][0]["max"][0] = -5.0;
  Result<std::vector<uint8_t>> bytes = broken.Serialize();
  std::ofstream out(dir + "/broken.glb", std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes->data()),
            static_cast<std::streamsize>(bytes->size()));
  ok = ok && static_cast<bool>(out);
  return ok ? 0 : 1;
}
