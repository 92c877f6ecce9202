// Skins: joints and inverse bind matrices.
#include "gltf/glb_reader_decoder.h"

#include <cstring>
#include <set>
#include <utility>

namespace hullpack {
namespace glb_reader_internal {

Status Decoder::DecodeSkins(Scene* scene) {
  const json* skins = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("skins", &skins));
  if (skins == nullptr) return Status::Ok();
  const size_t node_count = TopCount("nodes");
  for (size_t i = 0; i < skins->size(); ++i) {
    const json& j = (*skins)[i];
    const std::string sw = Item("skins", i);
    Skin skin;
    HP_RETURN_IF_ERROR(GetString(j, "name", sw, &skin.name));
    const json* joints = nullptr;
    HP_RETURN_IF_ERROR(GetArray(j, "joints", sw, &joints));
    if (joints == nullptr || joints->empty()) return Error(sw, "has no joints");
    std::set<int64_t> seen;
    for (size_t k = 0; k < joints->size(); ++k) {
      const json& e = (*joints)[k];
      if (!e.is_number_integer() || e.get<int64_t>() < 0 ||
          static_cast<uint64_t>(e.get<int64_t>()) >= node_count) {
        return Error(sw, "joint " + std::to_string(k) + " is not a node index");
      }
      if (!seen.insert(e.get<int64_t>()).second) return Error(sw, "lists a joint node twice");
      skin.joints.push_back(static_cast<int>(e.get<int64_t>()));
    }
    int64_t skeleton = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "skeleton", sw, &skeleton));
    if (skeleton >= 0 && static_cast<size_t>(skeleton) >= node_count) {
      return Error(sw, "skeleton " + std::to_string(skeleton) + " is not a node");
    }
    skin.skeleton = static_cast<int>(skeleton);
    int64_t ibm = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "inverseBindMatrices", sw, &ibm));
    if (ibm >= 0) {
      int comps = 0;
      HP_RETURN_IF_ERROR(
          ReadFloats(ibm, sw + ".inverseBindMatrices", {16}, &skin.inverse_bind_matrices, &comps));
      if (skin.inverse_bind_matrices.size() != 16 * skin.joints.size()) {
        return Error(sw, "inverseBindMatrices has " +
                             std::to_string(skin.inverse_bind_matrices.size() / 16) +
                             " matrices for " + std::to_string(skin.joints.size()) + " joints");
      }
    }
    scene->skins.push_back(std::move(skin));
  }
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
