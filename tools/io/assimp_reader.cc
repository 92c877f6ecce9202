#include "io/assimp_reader.h"

#include <assimp/GltfMaterial.h>
#include <assimp/anim.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "io/assimp_cameras_lights.h"
#include "scene/transform.h"

namespace hullpack {
namespace {

Matrix4 ToColumnMajor(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major (a1..a4 is the first row).
  return {m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2,
          m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4};
}

class AssimpConverter {
 public:
  AssimpConverter(const aiScene& ai, const std::string& name) : ai_(ai), name_(name) {}

  Scene Convert() {
    ConvertImagesAndMaterials();
    mesh_index_.assign(ai_.mNumMeshes, -1);
    for (unsigned i = 0; i < ai_.mNumMeshes; ++i) ConvertMesh(i);
    if (ai_.mRootNode) ConvertNode(*ai_.mRootNode, -1);
    ConvertSkins();
    ConvertAnimations();
    const CamerasAndLightsLost lost = ConvertCamerasAndLights(ai_, node_of_name_, &scene_);
    Note(lost.cameras, "cameras of no node not kept");
    Note(lost.lights, "lights of no node, ambient, area or undefined lights not kept");
    Note(point_line_meshes_, "point or line primitives not kept: meshes hold triangles only");
    Note(morph_targets_, "morph targets not kept (vertex blending, or not one offset per vertex)");
    Note(extra_color_sets_, "extra vertex colour sets not kept (the first is)");
    Note(clipped_influences_,
         "vertices with more than 4 joint influences: the 4 largest kept, renormalized");
    for (const Mesh& m : scene_.meshes) scene_.source_vertex_records += m.vertex_count();
    return std::move(scene_);
  }

 private:
  void Note(size_t count, const std::string& what) {
    if (count) scene_.dropped.push_back(std::to_string(count) + " " + what);
  }

  int ImageFor(const aiString& path) {
    const std::string key(path.C_Str());
    auto it = image_of_path_.find(key);
    if (it != image_of_path_.end()) return it->second;
    Image image;
    image.name = key;
    const aiTexture* embedded = ai_.GetEmbeddedTexture(path.C_Str());
    if (embedded) {
      if (embedded->mHeight == 0 && embedded->pcData) {
        const uint8_t* bytes = reinterpret_cast<const uint8_t*>(embedded->pcData);
        image.bytes.assign(bytes, bytes + embedded->mWidth);
        const std::string hint(embedded->achFormatHint);
        image.mime_type = hint == "jpg" || hint == "jpeg" ? "image/jpeg" : "image/" + hint;
      } else {
        scene_.dropped.push_back("uncompressed embedded texture '" + key + "' not kept");
        image_of_path_.emplace(key, -1);
        return -1;
      }
    } else {
      image.uri = key;
    }
    scene_.images.push_back(std::move(image));
    const int index = static_cast<int>(scene_.images.size() - 1);
    image_of_path_.emplace(key, index);
    return index;
  }

  TextureRef Texture(const aiMaterial& m, aiTextureType type) {
    TextureRef ref;
    aiString path;
    unsigned uv_index = 0;
    if (m.GetTextureCount(type) == 0 ||
        m.GetTexture(type, 0, &path, nullptr, &uv_index) != AI_SUCCESS)
      return ref;
    ref.image = ImageFor(path);
    ref.uv_set = static_cast<int>(uv_index);
    int mode = 0;
    if (m.Get(AI_MATKEY_MAPPINGMODE_U(type, 0), mode) == AI_SUCCESS)
      ref.sampler.wrap_s = WrapCode(mode);
    if (m.Get(AI_MATKEY_MAPPINGMODE_V(type, 0), mode) == AI_SUCCESS)
      ref.sampler.wrap_t = WrapCode(mode);
    // Only assimp's glTF importer sets filters; they are glTF's own codes already.
    m.Get(AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, 0), ref.sampler.mag_filter);
    m.Get(AI_MATKEY_GLTF_MAPPINGFILTER_MIN(type, 0), ref.sampler.min_filter);
    return ref;
  }

  static int WrapCode(int map_mode) {
    switch (map_mode) {
      case aiTextureMapMode_Clamp:
      case aiTextureMapMode_Decal:  // glTF has no border colour: clamping comes closest
        return 33071;
      case aiTextureMapMode_Mirror:
        return 33648;
      default:
        return 10497;
    }
  }

  // glTF inputs carry their alpha mode; other formats say only how opaque a material is, and any
  // transparency (a factor below one, an opacity map) needs blending to show.
  void ConvertAlpha(const aiMaterial& am, Material& m) {
    aiString gltf_mode;
    if (am.Get(AI_MATKEY_GLTF_ALPHAMODE, gltf_mode) == AI_SUCCESS) {
      const std::string mode = gltf_mode.C_Str();
      if (mode == "MASK") m.alpha_mode = AlphaMode::kMask;
      if (mode == "BLEND") m.alpha_mode = AlphaMode::kBlend;
      am.Get(AI_MATKEY_GLTF_ALPHACUTOFF, m.alpha_cutoff);
      return;
    }
    float opacity = 1.0f;
    const bool translucent = am.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f;
    const bool opacity_map = am.GetTextureCount(aiTextureType_OPACITY) > 0;
    if (!translucent && !opacity_map) return;
    m.alpha_mode = AlphaMode::kBlend;
    if (translucent) m.base_color[3] = opacity;
    // glTF reads alpha from the base colour texture only: an opacity map that is another image
    // (not the base colour's own alpha) has no place.
    if (opacity_map) {
      aiString path;
      if (am.GetTexture(aiTextureType_OPACITY, 0, &path) == AI_SUCCESS &&
          (!m.base_color_texture.used() ||
           scene_.images[m.base_color_texture.image].name != path.C_Str())) {
        scene_.dropped.push_back("opacity map '" + std::string(path.C_Str()) + "' of material '" +
                                 m.name + "' not kept: alpha comes from the base colour texture");
      }
    }
  }

  void ConvertImagesAndMaterials() {
    // A lone material named AI_DEFAULT_MATERIAL_NAME is assimp's stand-in for a file without
    // materials (STL, PLY): no triangle is given it (ConvertMesh), so it is not one of the scene's.
    if (ai_.mNumMaterials == 1 && !HasNamedMaterial()) return;
    for (unsigned i = 0; i < ai_.mNumMaterials; ++i) {
      const aiMaterial& am = *ai_.mMaterials[i];
      Material m;
      aiString name;
      if (am.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
      aiColor4D color;
      if (am.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
          am.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
        m.base_color = {color.r, color.g, color.b, color.a};
      }
      am.Get(AI_MATKEY_METALLIC_FACTOR, m.metallic);
      am.Get(AI_MATKEY_ROUGHNESS_FACTOR, m.roughness);
      aiColor3D emissive;
      if (am.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS)
        m.emissive = {emissive.r, emissive.g, emissive.b};
      int two_sided = 0;
      if (am.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) m.double_sided = two_sided != 0;
      m.base_color_texture = Texture(am, aiTextureType_BASE_COLOR);
      if (!m.base_color_texture.used()) m.base_color_texture = Texture(am, aiTextureType_DIFFUSE);
      m.metallic_roughness_texture = Texture(am, aiTextureType_UNKNOWN);
      m.normal_texture = Texture(am, aiTextureType_NORMALS);
      m.occlusion_texture = Texture(am, aiTextureType_LIGHTMAP);
      m.emissive_texture = Texture(am, aiTextureType_EMISSIVE);
      ConvertAlpha(am, m);
      int shading = 0;
      if (am.Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS)
        m.unlit = shading == aiShadingMode_Unlit;  // aiShadingMode_NoShading is the same value
      am.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), m.normal_scale);
      am.Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), m.occlusion_strength);
      scene_.materials.push_back(std::move(m));
    }
  }

  void ConvertMesh(unsigned index) {
    const aiMesh& am = *ai_.mMeshes[index];
    if (!(am.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || am.mNumFaces == 0) {
      ++point_line_meshes_;
      return;
    }
    Mesh m;
    m.name = am.mName.C_Str();
    const size_t n = am.mNumVertices;
    m.positions.resize(n * 3);
    for (size_t i = 0; i < n; ++i) {
      m.positions[i * 3] = am.mVertices[i].x;
      m.positions[i * 3 + 1] = am.mVertices[i].y;
      m.positions[i * 3 + 2] = am.mVertices[i].z;
    }
    if (am.mNormals) {
      m.normals.resize(n * 3);
      for (size_t i = 0; i < n; ++i) {
        m.normals[i * 3] = am.mNormals[i].x;
        m.normals[i * 3 + 1] = am.mNormals[i].y;
        m.normals[i * 3 + 2] = am.mNormals[i].z;
      }
    }
    if (am.mTangents && am.mBitangents && am.mNormals) {
      m.tangents.resize(n * 4);
      for (size_t i = 0; i < n; ++i) {
        const aiVector3D& t = am.mTangents[i];
        const aiVector3D& b = am.mBitangents[i];
        const aiVector3D& nn = am.mNormals[i];
        const aiVector3D c = nn ^ t;  // cross product
        m.tangents[i * 4] = t.x;
        m.tangents[i * 4 + 1] = t.y;
        m.tangents[i * 4 + 2] = t.z;
        m.tangents[i * 4 + 3] = (c * b) < 0.0f ? -1.0f : 1.0f;
      }
    }
    for (unsigned k = 0; k < AI_MAX_NUMBER_OF_TEXTURECOORDS && am.HasTextureCoords(k); ++k) {
      std::vector<float> uv(n * 2);
      for (size_t i = 0; i < n; ++i) {
        uv[i * 2] = am.mTextureCoords[k][i].x;
        uv[i * 2 + 1] = am.mTextureCoords[k][i].y;
      }
      m.uv_sets.push_back(std::move(uv));
    }
    if (am.HasVertexColors(0)) {
      m.colors.resize(n * 4);
      for (size_t i = 0; i < n; ++i) {
        const aiColor4D& c = am.mColors[0][i];
        m.colors[i * 4] = c.r;
        m.colors[i * 4 + 1] = c.g;
        m.colors[i * 4 + 2] = c.b;
        m.colors[i * 4 + 3] = c.a;
      }
    }
    for (unsigned k = 1; k < AI_MAX_NUMBER_OF_COLOR_SETS; ++k)
      extra_color_sets_ += am.HasVertexColors(k);
    ConvertMorphTargets(am, m);
    m.indices.reserve(static_cast<size_t>(am.mNumFaces) * 3);
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points/lines sorted into this mesh by SortByPType
      m.indices.insert(m.indices.end(), face.mIndices, face.mIndices + 3);
    }
    if (ai_.mNumMaterials > 1 ||
        (ai_.mNumMaterials == 1 && am.mMaterialIndex == 0 && HasNamedMaterial())) {
      m.material_ids.assign(m.triangle_count(), am.mMaterialIndex);
    }
    if (am.HasBones()) ConvertBones(am, m);
    mesh_index_[index] = static_cast<int>(scene_.meshes.size());
    scene_.meshes.push_back(std::move(m));
  }

  // to - from, 3 floats per vector.
  static std::vector<float> Offsets(const aiVector3D* to, const aiVector3D* from, size_t n) {
    std::vector<float> out(n * 3);
    for (size_t i = 0; i < n; ++i) {
      const aiVector3D d = to[i] - from[i];
      out[i * 3] = d.x;
      out[i * 3 + 1] = d.y;
      out[i * 3 + 2] = d.z;
    }
    return out;
  }

  // assimp's anim meshes hold the target's positions and normals; the scene model (as glTF) holds
  // their offsets from the mesh's. Relative and normalized morphing both come out as
  // base + sum w * (target - base); vertex blending has no such form and is dropped.
  void ConvertMorphTargets(const aiMesh& am, Mesh& m) {
    std::vector<int>& index = target_index_[scene_.meshes.size()];
    const size_t n = am.mNumVertices;
    bool any_normals = false, any_weight = false;
    for (unsigned k = 0; k < am.mNumAnimMeshes; ++k) {
      const aiAnimMesh* a = am.mAnimMeshes[k];
      if (!a || !a->mVertices || a->mNumVertices != n ||
          am.mMethod == aiMorphingMethod_VERTEX_BLEND) {
        ++morph_targets_;
        index.push_back(-1);
        continue;
      }
      MorphTarget t;
      t.name = a->mName.C_Str();
      t.positions = Offsets(a->mVertices, am.mVertices, n);
      if (a->mNormals && am.mNormals) {
        any_normals = true;
        t.normals = Offsets(a->mNormals, am.mNormals, n);
      }
      index.push_back(static_cast<int>(m.morph_targets.size()));
      m.morph_targets.push_back(std::move(t));
      m.morph_weights.push_back(std::isfinite(a->mWeight) ? a->mWeight : 0.0f);
      any_weight |= m.morph_weights.back() != 0;
    }
    // Every target or none has normal offsets: the others get zeros.
    for (MorphTarget& t : m.morph_targets) {
      if (any_normals && t.normals.empty()) t.normals.assign(n * 3, 0.0f);
    }
    if (!any_weight) m.morph_weights.clear();
  }

  bool HasNamedMaterial() const {
    aiString name;
    return ai_.mMaterials[0]->Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
           std::string(name.C_Str()) != AI_DEFAULT_MATERIAL_NAME;
  }

  // Per vertex: the (up to) four largest influences, renormalized to sum to one.
  void ConvertBones(const aiMesh& am, Mesh& m) {
    const size_t n = am.mNumVertices;
    std::vector<std::array<std::pair<float, uint16_t>, 8>> influences(n);
    std::vector<uint8_t> counts(n, 0);
    for (unsigned b = 0; b < am.mNumBones && b < 65535; ++b) {
      const aiBone& bone = *am.mBones[b];
      for (unsigned w = 0; w < bone.mNumWeights; ++w) {
        const aiVertexWeight& vw = bone.mWeights[w];
        if (vw.mVertexId >= n || !(vw.mWeight > 0.0f)) continue;
        auto& slots = influences[vw.mVertexId];
        uint8_t& c = counts[vw.mVertexId];
        if (c < slots.size()) {
          slots[c++] = {vw.mWeight, static_cast<uint16_t>(b)};
        } else {
          auto smallest = std::min_element(slots.begin(), slots.end());
          if (smallest->first < vw.mWeight) *smallest = {vw.mWeight, static_cast<uint16_t>(b)};
        }
      }
    }
    m.joints.assign(n * 4, 0);
    m.weights.assign(n * 4, 0.0f);
    for (size_t i = 0; i < n; ++i) {
      auto& slots = influences[i];
      const uint8_t c = counts[i];
      std::sort(slots.begin(), slots.begin() + c, [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
      });
      if (c > 4) ++clipped_influences_;
      float sum = 0;
      for (int k = 0; k < std::min<int>(c, 4); ++k) sum += slots[k].first;
      for (int k = 0; k < std::min<int>(c, 4); ++k) {
        m.joints[i * 4 + k] = slots[k].second;
        m.weights[i * 4 + k] = sum > 0 ? slots[k].first / sum : 0.0f;
      }
    }
    skinned_.push_back({&am, scene_.meshes.size()});
  }

  int ConvertNode(const aiNode& an, int parent) {
    const int index = static_cast<int>(scene_.nodes.size());
    scene_.nodes.emplace_back();
    {
      Node& node = scene_.nodes.back();
      node.name = an.mName.C_Str();
      node.parent = parent;
      node.local_transform = ToColumnMajor(an.mTransformation);
      for (unsigned i = 0; i < an.mNumMeshes; ++i) {
        const unsigned mi = an.mMeshes[i];
        if (mi < mesh_index_.size() && mesh_index_[mi] >= 0) node.meshes.push_back(mesh_index_[mi]);
      }
    }
    // A repeated name keeps its first node in depth-first order, the one aiNode::FindNode (which
    // assimp resolves bones and animation channels with) returns.
    node_of_name_.emplace(an.mName.C_Str(), index);
    ++nodes_named_[an.mName.C_Str()];
    for (unsigned c = 0; c < an.mNumChildren; ++c) {
      const int child = ConvertNode(*an.mChildren[c], index);
      scene_.nodes[index].children.push_back(child);
    }
    return index;
  }

  void ConvertSkins() {
    for (const auto& [am, mesh] : skinned_) {
      Skin skin;
      skin.name = std::string(am->mName.C_Str()) + "_skin";
      for (unsigned b = 0; b < am->mNumBones; ++b) {
        const aiBone& bone = *am->mBones[b];
        auto it = node_of_name_.find(bone.mName.C_Str());
        skin.joints.push_back(it == node_of_name_.end() ? -1 : it->second);
        const Matrix4 inv = ToColumnMajor(bone.mOffsetMatrix);
        skin.inverse_bind_matrices.insert(skin.inverse_bind_matrices.end(), inv.begin(), inv.end());
      }
      if (std::find(skin.joints.begin(), skin.joints.end(), -1) != skin.joints.end()) {
        scene_.dropped.push_back("skin of mesh '" + std::string(am->mName.C_Str()) +
                                 "' names joints with no node: skin not kept");
        scene_.meshes[mesh].joints.clear();
        scene_.meshes[mesh].weights.clear();
        continue;
      }
      const int skin_index = static_cast<int>(scene_.skins.size());
      scene_.skins.push_back(std::move(skin));
      for (Node& node : scene_.nodes) {
        if (std::find(node.meshes.begin(), node.meshes.end(), static_cast<int>(mesh)) !=
            node.meshes.end())
          node.skin = skin_index;
      }
    }
  }

  // Each aiAnimation becomes one Animation: a sampler and channel per animated path of a node.
  void ConvertAnimations() {
    for (unsigned a = 0; a < ai_.mNumAnimations; ++a) {
      const aiAnimation& aa = *ai_.mAnimations[a];
      Animation anim;
      anim.name = aa.mName.C_Str();
      const std::string label = "animation '" + anim.name + "'";
      // Keys are in ticks; assimp's own convention (its viewer and evaluators) takes an
      // unspecified rate, 0, as 25 ticks per second.
      const double ticks_per_second = aa.mTicksPerSecond != 0 ? aa.mTicksPerSecond : 25.0;
      std::vector<std::string> unknown_nodes, sheared_nodes;
      for (unsigned c = 0; c < aa.mNumChannels; ++c) {
        const aiNodeAnim& channel = *aa.mChannels[c];
        const std::string node_name = channel.mNodeName.C_Str();
        auto it = node_of_name_.find(node_name);
        if (it == node_of_name_.end()) {
          unknown_nodes.push_back("'" + node_name + "'");
          continue;
        }
        FoldFbxHelpersInto(it->second);
        if (!GiveTrs(it->second)) {
          sheared_nodes.push_back("'" + node_name + "'");
          continue;
        }
        if (nodes_named_[node_name] > 1) {
          scene_.dropped.push_back(label + ": " + std::to_string(nodes_named_[node_name]) +
                                   " nodes are named '" + node_name +
                                   "': its channel drives the first, as assimp does");
        }
        AddChannel(anim, it->second, AnimationPath::kTranslation, channel.mPositionKeys,
                   channel.mNumPositionKeys, ticks_per_second);
        AddChannel(anim, it->second, AnimationPath::kRotation, channel.mRotationKeys,
                   channel.mNumRotationKeys, ticks_per_second);
        AddChannel(anim, it->second, AnimationPath::kScale, channel.mScalingKeys,
                   channel.mNumScalingKeys, ticks_per_second);
      }
      NoteNames(label + ": channels of nodes the scene does not have not kept", unknown_nodes);
      NoteNames(
          label + ": channels of nodes with sheared transforms (TRS cannot hold them) not kept",
          sheared_nodes);
      Note(aa.mNumMeshChannels, label + ": mesh (vertex) animation channels not kept");
      size_t lost_morph_channels = 0;
      for (unsigned c = 0; c < aa.mNumMorphMeshChannels; ++c) {
        if (!aa.mMorphMeshChannels[c] ||
            !AddMorphChannel(anim, *aa.mMorphMeshChannels[c], ticks_per_second))
          ++lost_morph_channels;
      }
      Note(lost_morph_channels,
           label + ": morph animation channels of no node or mesh with morph targets not kept");
      if (anim.channels.empty()) {
        scene_.dropped.push_back(label + " has no node channel left: not kept");
        continue;
      }
      StartAtZero(anim, label);
      scene_.animations.push_back(std::move(anim));
    }
  }

  // glTF times cannot be negative (FBX clips may start before frame 0): such a clip is shifted to
  // start at 0, which keeps its timing relative to itself.
  void StartAtZero(Animation& anim, const std::string& label) {
    float first = 0;
    for (const AnimationSampler& s : anim.samplers) {
      if (!s.times.empty()) first = std::min(first, s.times.front());
    }
    if (first >= 0) return;
    for (AnimationSampler& s : anim.samplers) {
      for (float& t : s.times) t -= first;
    }
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%g", first);
    scene_.dropped.push_back(label + " started at " + seconds +
                             " s: shifted to start at 0 (glTF times cannot be negative)");
  }

  void NoteNames(const std::string& what, const std::vector<std::string>& names) {
    if (names.empty()) return;
    std::string line = what + ":";
    for (size_t i = 0; i < names.size(); ++i) line += (i ? ", " : " ") + names[i];
    scene_.dropped.push_back(line);
  }

  // assimp 5.2's FBX importer splits a node with pre- or post-rotation into helper nodes above it
  // ("X_$AssimpFbx$_Translation", "X_$AssimpFbx$_PreRotation", ...; X itself identity) yet keys
  // X's channel with the whole local transform, helpers' part included: played as it is, that part
  // counts twice. So the helpers' product moves into X and they become identity (same rest pose).
  // Pivots and offsets are different: assimp keys those helpers themselves, and they stay.
  void FoldFbxHelpersInto(int node_index) {
    const std::string prefix = scene_.nodes[node_index].name + "_$AssimpFbx$_";
    std::vector<int> helpers;
    for (int p = scene_.nodes[node_index].parent;
         p >= 0 && scene_.nodes[p].name.compare(0, prefix.size(), prefix) == 0;
         p = scene_.nodes[p].parent) {
      const std::string part = scene_.nodes[p].name.substr(prefix.size());
      if (part != "Translation" && part != "PreRotation" && part != "Rotation" &&
          part != "PostRotation" && part != "Scaling")
        return;
      helpers.push_back(p);
    }
    Matrix4 local = scene_.nodes[node_index].local_transform;
    for (int h : helpers) {  // nearest first: each helper multiplies from the left
      local = Multiply(scene_.nodes[h].local_transform, local);
      scene_.nodes[h].local_transform = kIdentity;
      scene_.nodes[h].trs.reset();
    }
    if (!helpers.empty()) scene_.nodes[node_index].local_transform = local;
  }

  static Matrix4 Multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 out{};
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 4; ++k) out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
      }
    }
    return out;
  }

  // glTF animates translation, rotation and scale separately, so an animated node needs its rest
  // transform as TRS. False when the matrix has shear (or no inverse), which TRS cannot express.
  bool GiveTrs(int node_index) {
    Node& node = scene_.nodes[node_index];
    if (node.trs) return true;
    Trs trs;
    if (!DecomposeMatrix(node.local_transform, &trs)) return false;
    node.trs = trs;
    node.local_transform = TrsMatrix(trs);  // equal up to rounding; the model wants it exact
    return true;
  }

  static void AppendValue(const aiVector3D& v, std::vector<float>& out) {
    out.insert(out.end(), {v.x, v.y, v.z});
  }
  static void AppendValue(const aiQuaternion& q, std::vector<float>& out) {
    // aiQuaternion is w, x, y, z; glTF's is x, y, z, w and must be unit length.
    const float norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    const float scale = norm > 0 ? 1.0f / norm : 1.0f;
    out.insert(out.end(), {q.x * scale, q.y * scale, q.z * scale, q.w * scale});
  }

  // One sampler (linear: assimp 5.2 keeps no interpolation per key) and its channel. glTF wants
  // strictly ascending times: a key at or before the previous kept time is left out.
  template <typename Key>
  void AddChannel(Animation& anim, int node, AnimationPath path, const Key* keys, unsigned count,
                  double ticks_per_second) {
    if (count == 0 || !keys) return;
    AnimationSampler sampler;
    for (unsigned k = 0; k < count; ++k) {
      const float seconds = static_cast<float>(keys[k].mTime / ticks_per_second);
      if (!std::isfinite(seconds) || (!sampler.times.empty() && !(seconds > sampler.times.back())))
        continue;
      sampler.times.push_back(seconds);
      AppendValue(keys[k].mValue, sampler.values);
    }
    if (sampler.times.empty()) return;
    AnimationChannel channel;
    channel.sampler = static_cast<int>(anim.samplers.size());
    channel.node = node;
    channel.path = path;
    anim.samplers.push_back(std::move(sampler));
    anim.channels.push_back(channel);
  }

  // The node a morph channel drives: the node of that name, else the first node whose first mesh
  // has that name; -1 when neither's first mesh has morph targets.
  int MorphChannelNode(const std::string& name) const {
    auto has_targets = [&](int node) {
      const Node& n = scene_.nodes[static_cast<size_t>(node)];
      return !n.meshes.empty() &&
             !scene_.meshes[static_cast<size_t>(n.meshes[0])].morph_targets.empty();
    };
    auto it = node_of_name_.find(name);
    if (it != node_of_name_.end() && has_targets(it->second)) return it->second;
    for (size_t i = 0; i < scene_.nodes.size(); ++i) {
      const Node& n = scene_.nodes[i];
      if (has_targets(static_cast<int>(i)) &&
          scene_.meshes[static_cast<size_t>(n.meshes[0])].name == name)
        return static_cast<int>(i);
    }
    return -1;
  }

  // A morph channel's keys (target indices and weights) as a weights track of all the mesh's
  // targets, the ones a key does not name at 0.
  bool AddMorphChannel(Animation& anim, const aiMeshMorphAnim& channel, double ticks_per_second) {
    const int node = MorphChannelNode(channel.mName.C_Str());
    if (node < 0 || channel.mNumKeys == 0 || !channel.mKeys) return false;
    for (const AnimationChannel& c : anim.channels) {
      if (c.node == node && c.path == AnimationPath::kWeights) return false;  // glTF: one per node
    }
    const int mesh = scene_.nodes[static_cast<size_t>(node)].meshes[0];
    const std::vector<int>& index = target_index_[static_cast<size_t>(mesh)];
    const size_t width = scene_.meshes[static_cast<size_t>(mesh)].morph_targets.size();
    AnimationSampler sampler;
    for (unsigned k = 0; k < channel.mNumKeys; ++k) {
      const aiMeshMorphKey& key = channel.mKeys[k];
      const float seconds = static_cast<float>(key.mTime / ticks_per_second);
      if (!std::isfinite(seconds) || (!sampler.times.empty() && !(seconds > sampler.times.back())))
        continue;
      sampler.times.push_back(seconds);
      sampler.values.resize(sampler.values.size() + width, 0.0f);
      float* weights = &sampler.values[sampler.values.size() - width];
      for (unsigned v = 0; key.mValues && key.mWeights && v < key.mNumValuesAndWeights; ++v) {
        const unsigned target = key.mValues[v];
        const float w = static_cast<float>(key.mWeights[v]);
        if (target < index.size() && index[target] >= 0 && std::isfinite(w))
          weights[index[target]] = w;
      }
    }
    if (sampler.times.empty()) return false;
    anim.channels.push_back(
        {static_cast<int>(anim.samplers.size()), node, AnimationPath::kWeights});
    anim.samplers.push_back(std::move(sampler));
    return true;
  }

  const aiScene& ai_;
  const std::string& name_;
  Scene scene_;
  std::vector<int> mesh_index_;
  // Per scene mesh: its aiMesh's anim mesh index -> morph target index (-1: dropped).
  std::map<size_t, std::vector<int>> target_index_;
  std::map<std::string, int> image_of_path_;
  std::unordered_map<std::string, int> node_of_name_;
  std::unordered_map<std::string, int> nodes_named_;  // how many nodes bear each name
  std::vector<std::pair<const aiMesh*, size_t>> skinned_;
  size_t point_line_meshes_ = 0, morph_targets_ = 0, extra_color_sets_ = 0, clipped_influences_ = 0;
};

unsigned FlagsFor(FileFormat format) {
  // FlipUVs: assimp's convention is v = 0 at the bottom, the scene model's is glTF's.
  // ValidateDataStructure runs first and rejects broken importer output before other steps touch
  // it.
  unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType |
                   aiProcess_FlipUVs;
  // STL has no index buffer and only facet normals: drop those and weld the corners back together.
  if (format == FileFormat::kStl)
    flags |= aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices;
  return flags;
}

void Configure(Assimp::Importer& importer, FileFormat format) {
  if (format == FileFormat::kStl)
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
}

const char* HintFor(FileFormat format) {
  switch (format) {
    case FileFormat::kGltf:
      return "gltf";
    case FileFormat::kGlb:
      return "glb";
    case FileFormat::kFbx:
      return "fbx";
    case FileFormat::kDae:
      return "dae";
    case FileFormat::kPly:
      return "ply";
    case FileFormat::kStl:
      return "stl";
    default:
      return "";
  }
}

// Whether assimp's validation rejected the scene for two cameras or two lights of one name.
bool RejectedForTwinNames(const Assimp::Importer& importer) {
  const std::string why = importer.GetErrorString();
  return why.find("has the same name as") != std::string::npos &&
         (why.find("aiScene::mCameras[") != std::string::npos ||
          why.find("aiScene::mLights[") != std::string::npos);
}

void CountNodeNames(const aiNode* node, std::map<std::string, int>* count, int depth = 0) {
  if (!node || depth > 1000) return;  // the validation that follows rejects a deeper tree
  ++(*count)[node->mName.C_Str()];
  for (unsigned i = 0; node->mChildren && i < node->mNumChildren; ++i)
    CountNodeNames(node->mChildren[i], count, depth + 1);
}

// Keeps, among `count` items, the first of each name that exactly one node bears (a camera or a
// light is placed by the node of its name); the others are deleted. Returns how many were.
template <typename T>
unsigned DropTwins(T** items, unsigned* count, const std::map<std::string, int>& nodes_named) {
  std::set<std::string> seen;
  unsigned kept = 0;
  for (unsigned i = 0; items && i < *count; ++i) {
    const std::string name = items[i] ? items[i]->mName.C_Str() : "";
    const auto nodes = nodes_named.find(name);
    if (items[i] && nodes != nodes_named.end() && nodes->second == 1 && seen.insert(name).second) {
      items[kept++] = items[i];
    } else {
      delete items[i];
    }
  }
  const unsigned dropped = *count - kept;
  *count = kept;
  return dropped;
}

// Blender's COLLADA exporter can write copies of one camera or lamp object under one name, on
// nodes of one name too (the UR10's visual meshes in ros-industrial/universal_robot), which
// assimp's validation rejects the whole file for. Such a file is read again without the
// validation, the cameras and lights no single node can be told for are dropped, and then the
// scene is validated and post-processed as any other: nothing the converter reads escapes the
// check.
template <typename ReadRaw>
const aiScene* ReadDroppingTwins(Assimp::Importer& importer, FileFormat format, ReadRaw read_raw,
                                 unsigned* dropped) {
  const aiScene* raw = read_raw(0u);
  if (!raw) return nullptr;
  // The importer owns the scene; assimp's own steps edit it in place the same way.
  aiScene* scene = const_cast<aiScene*>(raw);
  std::map<std::string, int> nodes_named;
  CountNodeNames(scene->mRootNode, &nodes_named);
  *dropped = DropTwins(scene->mCameras, &scene->mNumCameras, nodes_named) +
             DropTwins(scene->mLights, &scene->mNumLights, nodes_named);
  return importer.ApplyPostProcessing(FlagsFor(format));
}

// `twins`: cameras and lights dropped for a name an earlier one has (ReadDroppingTwins).
Result<Scene> Finish(const aiScene* ai, Assimp::Importer& importer, const std::string& name,
                     unsigned twins) {
  if (!ai) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "the importer could not read it";
    return Status(StatusCode::kParseError, name + ": " + why);
  }
  if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) {
    // A file of no mesh (only cameras, lights or animations) is marked incomplete too, and assimp
    // draws its nodes as a placeholder mesh of the material "SkeletonMaterial".
    bool placeholders_only = true;
    for (unsigned m = 0; ai->mMeshes && m < ai->mNumMeshes && placeholders_only; ++m) {
      const aiMesh* mesh = ai->mMeshes[m];
      const aiMaterial* material =
          mesh && ai->mMaterials && mesh->mMaterialIndex < ai->mNumMaterials
              ? ai->mMaterials[mesh->mMaterialIndex]
              : nullptr;
      aiString material_name;
      placeholders_only = material && material->Get(AI_MATKEY_NAME, material_name) == AI_SUCCESS &&
                          std::string(material_name.C_Str()) == "SkeletonMaterial";
    }
    if (placeholders_only)
      return Status(StatusCode::kInvalidMesh,
                    name + ": contains no triangles (no mesh in the file)");
    return Status(StatusCode::kParseError,
                  name + ": incomplete scene (truncated or unsupported content)");
  }
  Scene scene = ConvertAssimpScene(*ai, name);
  if (twins > 0)
    scene.dropped.push_back(
        std::to_string(twins) +
        " cameras or lights not kept: another one, or several nodes, have the same name");
  return scene;
}

// Reads with `read(flags)` (a file or bytes in memory), again without the twin names assimp's
// validation rejects (ReadDroppingTwins), and converts.
template <typename Read>
Result<Scene> ReadAndConvert(Assimp::Importer& importer, FileFormat format, const std::string& name,
                             Read read) {
  Configure(importer, format);
  const aiScene* ai = read(FlagsFor(format));
  unsigned dropped = 0;
  if (!ai && RejectedForTwinNames(importer))
    ai = ReadDroppingTwins(importer, format, read, &dropped);
  return Finish(ai, importer, name, dropped);
}

}  // namespace

Scene ConvertAssimpScene(const aiScene& ai, const std::string& name) {
  return AssimpConverter(ai, name).Convert();
}

Result<Scene> ReadWithAssimp(const std::string& path, FileFormat format) {
  Assimp::Importer importer;
  return ReadAndConvert(importer, format, path,
                        [&](unsigned flags) { return importer.ReadFile(path, flags); });
}

Result<Scene> ReadWithAssimpFromMemory(const uint8_t* data, size_t size, FileFormat format,
                                       const std::string& name) {
  Assimp::Importer importer;
  return ReadAndConvert(importer, format, name, [&](unsigned flags) {
    return importer.ReadFileFromMemory(data, size, flags, HintFor(format));
  });
}

}  // namespace hullpack
