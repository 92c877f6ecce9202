// Nodes: the hierarchy (matrix or TRS), meshes and skins of each node.
#include "gltf/glb_reader_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include "gltf/node_forest.h"
#include "scene/transform.h"

namespace hullpack {
namespace glb_reader_internal {

Status Decoder::DecodeNodes(Scene* scene) {
  const json* nodes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("nodes", &nodes));
  if (nodes == nullptr) return Status::Ok();
  const size_t n = nodes->size();
  scene->nodes.resize(n);
  std::vector<bool> mesh_of_parent(n, false);
  for (size_t i = 0; i < n; ++i) {
    const json& j = (*nodes)[i];
    const std::string nw = Item("nodes", i);
    Node& node = scene->nodes[i];
    HP_RETURN_IF_ERROR(GetString(j, "name", nw, &node.name));
    const json* children = nullptr;
    HP_RETURN_IF_ERROR(GetArray(j, "children", nw, &children));
    if (children != nullptr) {
      for (size_t k = 0; k < children->size(); ++k) {
        const json& c = (*children)[k];
        if (!c.is_number_integer() || c.get<int64_t>() < 0 ||
            static_cast<uint64_t>(c.get<int64_t>()) >= n) {
          return Error(nw, "child " + std::to_string(k) + " is not a node index");
        }
        const size_t child = static_cast<size_t>(c.get<int64_t>());
        if (child == i) return Error(nw, "lists itself as a child");
        if (scene->nodes[child].parent != -1) {
          return Error(nw, "child node " + std::to_string(child) + " already has parent " +
                               std::to_string(scene->nodes[child].parent));
        }
        scene->nodes[child].parent = static_cast<int>(i);
        node.children.push_back(static_cast<int>(child));
      }
    }
    if (j.contains("matrix")) {
      double m[16];
      HP_RETURN_IF_ERROR(GetNumbers(j, "matrix", nw, 16, m));
      std::copy(m, m + 16, node.local_transform.begin());
    } else if (j.contains("translation") || j.contains("rotation") || j.contains("scale")) {
      Trs trs;
      HP_RETURN_IF_ERROR(GetNumbers(j, "translation", nw, 3, trs.translation.data()));
      HP_RETURN_IF_ERROR(GetNumbers(j, "rotation", nw, 4, trs.rotation.data()));
      HP_RETURN_IF_ERROR(GetNumbers(j, "scale", nw, 3, trs.scale.data()));
      node.local_transform = TrsMatrix(trs);
      node.trs = trs;
    }
    int64_t mesh = -1, skin = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "mesh", nw, &mesh));
    HP_RETURN_IF_ERROR(GetIndex(j, "skin", nw, &skin));
    if (mesh >= 0) {
      if (static_cast<size_t>(mesh) >= scene->meshes.size())
        return Error(nw, "mesh " + std::to_string(mesh) + " does not exist");
      node.meshes.push_back(static_cast<int>(mesh));
      // A node's own morph weights replace its mesh's defaults; the scene model keeps one set per
      // mesh, which is exact while a mesh is instanced by nodes that agree.
      auto weights = j.find("weights");
      Mesh& m = scene->meshes[static_cast<size_t>(mesh)];
      if (weights != j.end() && weights->is_array() && weights->size() == m.morph_targets.size() &&
          std::all_of(weights->begin(), weights->end(), [](const json& w) {
            return w.is_number() && std::isfinite(w.get<double>());
          })) {
        m.morph_weights = weights->get<std::vector<float>>();
      }
    }
    if (skin >= 0) {
      if (static_cast<size_t>(skin) >= scene->skins.size())
        return Error(nw, "skin " + std::to_string(skin) + " does not exist");
      node.skin = static_cast<int>(skin);
    }
    int64_t camera = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "camera", nw, &camera));
    if (camera >= 0) {
      if (static_cast<size_t>(camera) >= scene->cameras.size())
        return Error(nw, "camera " + std::to_string(camera) + " does not exist");
      node.camera = static_cast<int>(camera);
    }
    auto ext = j.find("extensions");
    if (ext != j.end() && ext->is_object()) {
      auto punctual = ext->find("KHR_lights_punctual");
      if (punctual != ext->end()) {
        if (!punctual->is_object()) return Error(nw, "KHR_lights_punctual is not an object");
        int64_t light = -1;
        HP_RETURN_IF_ERROR(
            GetIndex(*punctual, "light", nw + ".extensions.KHR_lights_punctual", &light));
        if (light < 0 || static_cast<size_t>(light) >= scene->lights.size())
          return Error(nw, "light " + std::to_string(light) + " does not exist");
        node.light = static_cast<int>(light);
      }
    }
    auto extras = j.find("extras");
    if (extras != j.end() && extras->is_object()) {
      auto hp = extras->find("hullpack");
      if (hp != extras->end() && hp->is_object()) {
        bool marker = false;
        HP_RETURN_IF_ERROR(GetBool(*hp, "mesh_of_parent", nw + ".extras.hullpack", &marker));
        mesh_of_parent[i] = marker;
      }
    }
  }
  const int on_cycle = gltf_internal::FirstNodeOnCycle(scene->nodes);
  if (on_cycle >= 0) {
    return Error(Item("nodes", static_cast<uint64_t>(on_cycle)),
                 "is part of a cycle in the node hierarchy");
  }

  // Fold the writer's extra-mesh children back into their parents.
  std::vector<bool> referenced(n, false);
  for (const Skin& s : scene->skins) {
    for (int jn : s.joints) referenced[static_cast<size_t>(jn)] = true;
    if (s.skeleton >= 0) referenced[static_cast<size_t>(s.skeleton)] = true;
  }
  // A weights channel of an extra-mesh child that repeats its parent's (same clip, same sampler:
  // what the writer adds so that every mesh of the node morphs) goes with the child.
  auto mirrors_parent = [&](const Animation& a, const AnimationChannel& c) {
    const Node& node = scene->nodes[static_cast<size_t>(c.node)];
    if (c.path != AnimationPath::kWeights || !mesh_of_parent[static_cast<size_t>(c.node)] ||
        node.parent < 0)
      return false;
    for (const AnimationChannel& p : a.channels) {
      if (p.node == node.parent && p.path == AnimationPath::kWeights && p.sampler == c.sampler)
        return true;
    }
    return false;
  };
  for (const Animation& a : scene->animations) {
    for (const AnimationChannel& c : a.channels) {
      if (!mirrors_parent(a, c)) referenced[static_cast<size_t>(c.node)] = true;
    }
  }
  std::vector<int> remap(n, -1);
  std::vector<bool> remove(n, false);
  for (size_t i = 0; i < n; ++i) {
    const Node& node = scene->nodes[i];
    const bool fold = mesh_of_parent[i] && node.parent >= 0 && node.children.empty() &&
                      node.meshes.size() == 1 && !referenced[i] &&
                      node.local_transform == kIdentity && node.camera < 0 && node.light < 0 &&
                      node.skin == scene->nodes[static_cast<size_t>(node.parent)].skin;
    remove[i] = fold;
  }
  if (std::find(remove.begin(), remove.end(), true) == remove.end()) return Status::Ok();
  for (size_t i = 0; i < n; ++i) {
    if (!remove[i]) continue;
    Node& parent = scene->nodes[static_cast<size_t>(scene->nodes[i].parent)];
    parent.meshes.push_back(scene->nodes[i].meshes[0]);
  }
  std::vector<Node> kept;
  for (size_t i = 0; i < n; ++i) {
    if (remove[i]) continue;
    remap[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(scene->nodes[i]));
  }
  for (Node& node : kept) {
    if (node.parent >= 0) node.parent = remap[static_cast<size_t>(node.parent)];
    std::vector<int> children;
    for (int c : node.children) {
      if (remap[static_cast<size_t>(c)] >= 0) children.push_back(remap[static_cast<size_t>(c)]);
    }
    node.children = std::move(children);
  }
  for (Skin& s : scene->skins) {
    for (int& jn : s.joints) jn = remap[static_cast<size_t>(jn)];
    if (s.skeleton >= 0) s.skeleton = remap[static_cast<size_t>(s.skeleton)];
  }
  for (Animation& a : scene->animations) {
    std::vector<AnimationChannel> channels;
    for (AnimationChannel& c : a.channels) {
      if (remap[static_cast<size_t>(c.node)] < 0) continue;  // a folded child's mirror
      c.node = remap[static_cast<size_t>(c.node)];
      channels.push_back(c);
    }
    a.channels = std::move(channels);
  }
  scene->nodes = std::move(kept);
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
