// One 3MF model part (an XML file of the package, such as 3D/3dmodel.model) as plain data: what
// tools/io/threemf_reader.h turns into the scene model. Parsing checks the XML and the values
// (numbers, colours, transforms, ids); references between resources are checked by the reader,
// which sees every part.
#ifndef HULLPACK_TOOLS_IO_THREEMF_MODEL_H_
#define HULLPACK_TOOLS_IO_THREEMF_MODEL_H_

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

struct ThreeMfTriangle {
  std::array<uint32_t, 3> v = {0, 0, 0};
  int64_t pid = -1;                         // property group, -1 = the object's
  std::array<int64_t, 3> p = {-1, -1, -1};  // property index per corner, -1 = not given
};

// A reference to an object, optionally in another model part (production extension's p:path).
struct ThreeMfObjectRef {
  uint32_t object_id = 0;
  std::string path;  // empty = the referring part
  Matrix4 transform = kIdentity;
};

struct ThreeMfObject {
  std::string name;
  std::string type = "model";
  int64_t pid = -1;
  int64_t pindex = -1;
  bool has_mesh = false;
  std::vector<float> positions;  // 3 per vertex
  std::vector<ThreeMfTriangle> triangles;
  std::vector<ThreeMfObjectRef> components;
};

struct ThreeMfBaseMaterial {
  std::string name;
  std::array<float, 4> srgb = {1, 1, 1, 1};
};

struct ThreeMfTexture {
  std::string path;
  std::string content_type;
  Sampler sampler;
};

struct ThreeMfTextureGroup {
  uint32_t texture_id = 0;
  std::vector<float> uvs;  // 2 per coordinate, as the file gives them (v = 0 at the bottom)
};

struct ThreeMfModel {
  double metres_per_unit = 0.001;
  std::map<uint32_t, ThreeMfObject> objects;
  std::map<uint32_t, std::vector<ThreeMfBaseMaterial>> base_materials;
  std::map<uint32_t, std::vector<std::array<float, 4>>> color_groups;  // sRGB
  std::map<uint32_t, ThreeMfTexture> textures;
  std::map<uint32_t, ThreeMfTextureGroup> texture_groups;
  std::set<uint32_t> unsupported_groups;  // composite materials, multi-properties
  std::vector<ThreeMfObjectRef> build;
  std::vector<std::string> dropped;
};

// Parses one model part's XML. `where` names the package and part in messages.
Result<ThreeMfModel> ParseThreeMfModel(std::string_view xml, const std::string& where);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_THREEMF_MODEL_H_
