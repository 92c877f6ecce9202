// Meshes: primitives concatenated into one scene Mesh per glTF mesh.
#include "gltf/glb_reader_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <utility>

namespace hullpack {
namespace glb_reader_internal {

namespace {

// Pads a per-vertex array to `vertices` entries of `width`, filling with `fill`.
template <typename T>
void PadTo(std::vector<T>& v, size_t vertices, size_t width, T fill) {
  if (v.size() < vertices * width) v.resize(vertices * width, fill);
}

}  // namespace

Status Decoder::DecodeMorphTargetNamesAndWeights(const json& j, const std::string& mw, Mesh* out) {
  const size_t vc = out->vertex_count();
  bool any_normals = false;
  for (const MorphTarget& t : out->morph_targets) any_normals |= !t.normals.empty();
  if (any_normals && out->normals.empty()) {  // offsets of normals the mesh does not have
    Drop(mw + ": morph-target NORMAL offsets of a mesh without normals");
    any_normals = false;
    for (MorphTarget& t : out->morph_targets) t.normals.clear();
  }
  for (MorphTarget& t : out->morph_targets) {
    PadTo(t.positions, vc, 3, 0.0f);
    if (any_normals) PadTo(t.normals, vc, 3, 0.0f);
  }
  auto weights = j.find("weights");
  if (weights != j.end()) {
    if (!weights->is_array() || weights->size() != out->morph_targets.size())
      return Error(mw, "weights must be an array of one number per morph target");
    for (const json& w : *weights) {
      if (!w.is_number() || !std::isfinite(w.get<double>()))
        return Error(mw, "weights holds a value that is not a finite number");
      out->morph_weights.push_back(w.get<float>());
    }
  }
  // targetNames is the convention of Blender's and three.js's exporters (not in the specification).
  auto extras = j.find("extras");
  if (extras != j.end() && extras->is_object()) {
    auto names = extras->find("targetNames");
    if (names != extras->end() && names->is_array() && names->size() == out->morph_targets.size()) {
      for (size_t t = 0; t < names->size(); ++t) {
        if ((*names)[t].is_string()) out->morph_targets[t].name = (*names)[t].get<std::string>();
      }
    }
  }
  return Status::Ok();
}

Status Decoder::DecodeMesh(int64_t mesh_index, Scene* scene, Mesh* out) {
  const json* meshes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("meshes", &meshes));
  const std::string mw = Item("meshes", static_cast<uint64_t>(mesh_index));
  const json& j = (*meshes)[static_cast<size_t>(mesh_index)];
  HP_RETURN_IF_ERROR(GetString(j, "name", mw, &out->name));
  // The writer's zero-filled padding UV sets (see glb_writer.cc) are dropped again.
  constexpr uint64_t kNoUvSetLimit = std::numeric_limits<uint64_t>::max();
  uint64_t uv_set_limit = kNoUvSetLimit;
  auto extras = j.find("extras");
  if (extras != j.end() && extras->is_object()) {
    auto hp = extras->find("hullpack");
    if (hp != extras->end() && hp->is_object()) {
      HP_RETURN_IF_ERROR(GetBool(*hp, "collides", mw + ".extras.hullpack", &out->collides));
      HP_RETURN_IF_ERROR(
          GetUint(*hp, "uv_sets", mw + ".extras.hullpack", kNoUvSetLimit, &uv_set_limit));
    }
  }
  const json* primitives = nullptr;
  HP_RETURN_IF_ERROR(GetArray(j, "primitives", mw, &primitives));
  if (primitives == nullptr) return Error(mw, "has no primitives");

  std::map<std::string, std::pair<size_t, size_t>> vertex_blocks;  // attribute set -> (base, count)
  // attribute set -> the material transforms baked into its UVs
  std::map<std::string, const std::map<int, UvTransform>*> block_transforms;
  std::vector<int> triangle_material;
  bool has_normals = false, has_tangents = false, has_colors = false, has_skin = false;
  size_t uv_count = 0;
  int64_t target_count = -1;  // glTF: every primitive of a mesh has the same morph targets
  const size_t material_count = TopCount("materials");

  for (size_t p = 0; p < primitives->size(); ++p) {
    const std::string pw = mw + ".primitives[" + std::to_string(p) + "]";
    const json& prim = (*primitives)[p];
    if (!prim.is_object()) return Error(pw, "is not an object");
    uint64_t mode = gltf::kModeTriangles;
    HP_RETURN_IF_ERROR(GetUint(prim, "mode", pw, gltf::kModeTriangles, &mode));
    if (mode > gltf::kModeTriangleFan) return Error(pw, "unknown mode " + std::to_string(mode));
    if (mode < gltf::kModeTriangles) {
      ++non_triangle_primitives_;
      continue;
    }
    auto attrs_it = prim.find("attributes");
    if (attrs_it == prim.end() || !attrs_it->is_object())
      return Error(pw, "has no attributes object");
    const json& attrs = *attrs_it;
    // The attributes this reader keeps, and their accessors.
    std::map<std::string, int64_t> used;
    for (const auto& kv : attrs.items()) {
      const std::string& sem = kv.key();
      int64_t acc = -1;
      HP_RETURN_IF_ERROR(GetIndex(attrs, sem.c_str(), pw + ".attributes", &acc));
      if (acc < 0) return Error(pw, "attribute " + sem + " has no accessor");
      bool keep = sem == "POSITION" || sem == "NORMAL" || sem == "TANGENT" || sem == "COLOR_0" ||
                  sem == "JOINTS_0" || sem == "WEIGHTS_0";
      if (!keep && sem.compare(0, 9, "TEXCOORD_") == 0 && sem.size() > 9 && sem.size() <= 11 &&
          std::all_of(sem.begin() + 9, sem.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        keep = true;
      }
      if (keep) {
        used[sem] = acc;
      } else {
        dropped_attributes_.insert(sem);
      }
    }
    if (used.count("POSITION") == 0) return Error(pw, "has no POSITION attribute");
    // Morph targets: per target the accessors of its POSITION and NORMAL offsets (-1: none).
    std::vector<std::pair<int64_t, int64_t>> targets;
    const json* targets_json = nullptr;
    HP_RETURN_IF_ERROR(GetArray(prim, "targets", pw, &targets_json));
    if (targets_json != nullptr) {
      for (size_t t = 0; t < targets_json->size(); ++t) {
        const std::string tw = pw + ".targets[" + std::to_string(t) + "]";
        const json& target = (*targets_json)[t];
        if (!target.is_object()) return Error(tw, "is not an object");
        int64_t position = -1, normal = -1;
        HP_RETURN_IF_ERROR(GetIndex(target, "POSITION", tw, &position));
        HP_RETURN_IF_ERROR(GetIndex(target, "NORMAL", tw, &normal));
        for (const auto& kv : target.items()) {
          if (kv.key() != "POSITION" && kv.key() != "NORMAL")
            dropped_attributes_.insert("morph target " + kv.key());
        }
        targets.emplace_back(position, normal);
      }
    }
    if (target_count >= 0 && targets.size() != static_cast<size_t>(target_count)) {
      return Error(pw, "has " + std::to_string(targets.size()) +
                           " morph targets, another primitive of the mesh " +
                           std::to_string(target_count));
    }
    target_count = static_cast<int64_t>(targets.size());
    out->morph_targets.resize(targets.size());
    std::string key;
    for (const auto& kv : used) key += kv.first + "=" + std::to_string(kv.second) + ";";
    for (const auto& t : targets)
      key += "T" + std::to_string(t.first) + "," + std::to_string(t.second) + ";";
    int64_t material = -1;
    HP_RETURN_IF_ERROR(GetIndex(prim, "material", pw, &material));
    if (material >= 0 && static_cast<size_t>(material) >= material_count) {
      return Error(pw, "material " + std::to_string(material) + " does not exist");
    }
    // The material's texture transforms, baked into the UVs its primitive's vertices carry.
    static const std::map<int, UvTransform> kNoTransforms;
    const std::map<int, UvTransform>& transforms =
        material >= 0 && static_cast<size_t>(material) < material_uv_transforms_.size()
            ? material_uv_transforms_[static_cast<size_t>(material)]
            : kNoTransforms;
    // The transform baked into UV set `set` under `of` (none when identity or conflicting).
    auto baked_for = [](const std::map<int, UvTransform>& of, size_t set) -> const UvTransform* {
      auto t = of.find(static_cast<int>(set));
      return t == of.end() || t->second.conflicting || t->second.identity() ? nullptr : &t->second;
    };
    auto transform_of = [&](size_t set) { return baked_for(transforms, set); };

    size_t base = 0, count = 0;
    auto block = vertex_blocks.find(key);
    if (block != vertex_blocks.end()) {
      base = block->second.first;
      count = block->second.second;
      const std::map<int, UvTransform>& baked = *block_transforms[key];
      for (size_t u = 0; u < uv_count; ++u) {
        const UvTransform* first = baked_for(baked, u);
        const UvTransform* now = transform_of(u);
        if (first == now || (first && now && first->same(*now))) continue;
        Drop(pw +
             ": shares its vertices with a primitive of another KHR_texture_transform (the "
             "first primitive's is baked into TEXCOORD_" +
             std::to_string(u) + ")");
      }
    } else {
      block_transforms[key] = &transforms;
      int comps = 0;
      std::vector<float> positions;
      HP_RETURN_IF_ERROR(ReadFloats(used["POSITION"], pw + ".POSITION", {3}, &positions, &comps));
      count = positions.size() / 3;
      base = out->vertex_count();
      if (base + count > std::numeric_limits<uint32_t>::max())
        return Unsupported(pw, "more than 2^32-1 vertices");
      auto read_attr = [&](const std::string& sem, std::initializer_list<int> allowed,
                           std::vector<float>* values, int* c) -> Status {
        HP_RETURN_IF_ERROR(ReadFloats(used[sem], pw + "." + sem, allowed, values, c));
        if (values->size() / static_cast<size_t>(*c) != count) {
          return Error(pw, sem + " has " +
                               std::to_string(values->size() / static_cast<size_t>(*c)) +
                               " elements but POSITION has " + std::to_string(count));
        }
        return Status::Ok();
      };
      out->positions.insert(out->positions.end(), positions.begin(), positions.end());
      std::vector<float> values;
      if (used.count("NORMAL") != 0) {
        HP_RETURN_IF_ERROR(read_attr("NORMAL", {3}, &values, &comps));
        PadTo(out->normals, base, 3, 0.0f);
        out->normals.insert(out->normals.end(), values.begin(), values.end());
        has_normals = true;
      }
      if (used.count("TANGENT") != 0) {
        HP_RETURN_IF_ERROR(read_attr("TANGENT", {4}, &values, &comps));
        PadTo(out->tangents, base, 4, 0.0f);
        out->tangents.insert(out->tangents.end(), values.begin(), values.end());
        has_tangents = true;
      }
      for (size_t u = 0;; ++u) {
        const std::string sem = "TEXCOORD_" + std::to_string(u);
        if (used.count(sem) == 0) break;
        HP_RETURN_IF_ERROR(read_attr(sem, {2}, &values, &comps));
        if (const UvTransform* t = transform_of(u)) {
          for (size_t v = 0; v + 1 < values.size(); v += 2) t->Apply(&values[v]);
        }
        if (out->uv_sets.size() <= u) out->uv_sets.resize(u + 1);
        PadTo(out->uv_sets[u], base, 2, 0.0f);
        out->uv_sets[u].insert(out->uv_sets[u].end(), values.begin(), values.end());
        uv_count = std::max(uv_count, u + 1);
      }
      for (const auto& kv : used) {
        if (kv.first.compare(0, 9, "TEXCOORD_") == 0 &&
            std::stoul(kv.first.substr(9)) >= uv_count) {
          dropped_attributes_.insert(kv.first + " (TEXCOORD sets must be contiguous)");
        }
      }
      if (used.count("COLOR_0") != 0) {
        HP_RETURN_IF_ERROR(read_attr("COLOR_0", {3, 4}, &values, &comps));
        PadTo(out->colors, base, 4, 1.0f);
        for (size_t v = 0; v < count; ++v) {
          for (int c = 0; c < 4; ++c) {
            out->colors.push_back(
                c < comps ? values[v * static_cast<size_t>(comps) + static_cast<size_t>(c)] : 1.0f);
          }
        }
        has_colors = true;
      }
      if (used.count("JOINTS_0") != 0 && used.count("WEIGHTS_0") != 0) {
        AccessorView ja;
        const std::string jw = pw + ".JOINTS_0";
        HP_RETURN_IF_ERROR(GetAccessor(used["JOINTS_0"], jw, &ja));
        if (ja.components != 4 || ja.normalized ||
            (ja.component_type != gltf::kUnsignedByte &&
             ja.component_type != gltf::kUnsignedShort)) {
          return Error(jw, "must be an unnormalized VEC4 of unsigned bytes or shorts");
        }
        if (ja.count != count) return Error(jw, "count differs from POSITION");
        HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(count) * 4 * sizeof(uint16_t), jw));
        PadTo(out->joints, base, 4, static_cast<uint16_t>(0));
        const size_t csize = gltf::ComponentSize(ja.component_type);
        for (size_t v = 0; v < count; ++v) {
          for (size_t c = 0; c < 4; ++c) {
            out->joints.push_back(
                ja.data == nullptr ? 0
                                   : static_cast<uint16_t>(ReadUnsigned(
                                         ja.data + v * ja.stride + c * csize, ja.component_type)));
          }
        }
        HP_RETURN_IF_ERROR(read_attr("WEIGHTS_0", {4}, &values, &comps));
        PadTo(out->weights, base, 4, 0.0f);
        out->weights.insert(out->weights.end(), values.begin(), values.end());
        has_skin = true;
      } else if (used.count("JOINTS_0") != 0 || used.count("WEIGHTS_0") != 0) {
        dropped_attributes_.insert("JOINTS_0/WEIGHTS_0 without its partner");
      }
      for (size_t t = 0; t < targets.size(); ++t) {
        const std::string tw = pw + ".targets[" + std::to_string(t) + "]";
        MorphTarget& target = out->morph_targets[t];
        auto read_offsets = [&](int64_t accessor, const char* sem, std::vector<float>* to) {
          if (accessor < 0) return Status::Ok();
          std::vector<float> offsets;
          int c = 0;
          HP_RETURN_IF_ERROR(ReadFloats(accessor, tw + "." + sem, {3}, &offsets, &c));
          if (offsets.size() != count * 3)
            return Error(tw, std::string(sem) + " count differs from the primitive's POSITION");
          PadTo(*to, base, 3, 0.0f);
          to->insert(to->end(), offsets.begin(), offsets.end());
          return Status::Ok();
        };
        HP_RETURN_IF_ERROR(read_offsets(targets[t].first, "POSITION", &target.positions));
        HP_RETURN_IF_ERROR(read_offsets(targets[t].second, "NORMAL", &target.normals));
      }
      vertex_blocks.emplace(key, std::make_pair(base, count));
    }

    // Indices, triangulated.
    std::vector<uint32_t> indices;
    int64_t indices_accessor = -1;
    HP_RETURN_IF_ERROR(GetIndex(prim, "indices", pw, &indices_accessor));
    if (indices_accessor >= 0) {
      HP_RETURN_IF_ERROR(ReadIndices(indices_accessor, pw + ".indices", &indices));
      for (size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= count) {
          return Error(pw, "index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                               " but the primitive has " + std::to_string(count) + " vertices");
        }
      }
    } else {
      HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(count) * sizeof(uint32_t), pw));
      indices.resize(count);
      for (size_t i = 0; i < count; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    size_t triangles = 0;
    if (mode == gltf::kModeTriangles) {
      if (indices.size() % 3 != 0) {
        return Error(pw,
                     std::to_string(indices.size()) + " triangle indices is not a multiple of 3");
      }
      triangles = indices.size() / 3;
    } else {
      triangles = indices.size() >= 3 ? indices.size() - 2 : 0;
    }
    HP_RETURN_IF_ERROR(
        Charge(static_cast<uint64_t>(triangles) * (3 * sizeof(uint32_t) + sizeof(int)), pw));
    out->indices.reserve(out->indices.size() + 3 * triangles);
    const uint32_t b = static_cast<uint32_t>(base);
    for (size_t t = 0; t < triangles; ++t) {
      uint32_t v0, v1, v2;
      if (mode == gltf::kModeTriangles) {
        v0 = indices[3 * t];
        v1 = indices[3 * t + 1];
        v2 = indices[3 * t + 2];
      } else if (mode == gltf::kModeTriangleStrip) {
        v0 = indices[t];
        v1 = indices[t + 1 + t % 2];
        v2 = indices[t + 2 - t % 2];
      } else {  // fan
        v0 = indices[t + 1];
        v1 = indices[t + 2];
        v2 = indices[0];
      }
      out->indices.push_back(b + v0);
      out->indices.push_back(b + v1);
      out->indices.push_back(b + v2);
    }
    triangle_material.insert(triangle_material.end(), triangles, static_cast<int>(material));
  }

  const size_t vc = out->vertex_count();
  if (has_normals) PadTo(out->normals, vc, 3, 0.0f);
  if (has_tangents) PadTo(out->tangents, vc, 4, 0.0f);
  if (has_colors) PadTo(out->colors, vc, 4, 1.0f);
  if (has_skin) {
    PadTo(out->joints, vc, 4, static_cast<uint16_t>(0));
    PadTo(out->weights, vc, 4, 0.0f);
  }
  for (size_t u = 0; u < uv_count; ++u) PadTo(out->uv_sets[u], vc, 2, 0.0f);
  if (out->uv_sets.size() > uv_set_limit) out->uv_sets.resize(static_cast<size_t>(uv_set_limit));
  HP_RETURN_IF_ERROR(DecodeMorphTargetNamesAndWeights(j, mw, out));

  if (out->indices.empty())
    Drop(mw + (out->name.empty() ? "" : " '" + out->name + "'") + " has no triangles");
  const bool any_material =
      std::any_of(triangle_material.begin(), triangle_material.end(), [](int m) { return m >= 0; });
  if (any_material) {
    out->material_ids.resize(triangle_material.size());
    for (size_t t = 0; t < triangle_material.size(); ++t) {
      int m = triangle_material[t];
      if (m < 0) {
        if (default_material_ < 0) {
          Material def;
          def.name = "default";
          scene->materials.push_back(def);
          default_material_ = static_cast<int>(scene->materials.size() - 1);
        }
        m = default_material_;
      }
      out->material_ids[t] = static_cast<uint32_t>(m);
    }
  }
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
