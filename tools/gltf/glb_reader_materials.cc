// Images and materials (metallic-roughness factors, the five texture slots with their samplers,
// alpha modes, KHR_materials_unlit and KHR_materials_emissive_strength).
#include <cmath>

#include "gltf/glb_reader_decoder.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace hullpack {
namespace glb_reader_internal {

Status Decoder::DecodeImages(Scene* scene) {
  const json* images = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("images", &images));
  if (images == nullptr) return Status::Ok();
  for (size_t i = 0; i < images->size(); ++i) {
    const json& j = (*images)[i];
    const std::string iw = Item("images", i);
    Image img;
    HP_RETURN_IF_ERROR(GetString(j, "name", iw, &img.name));
    HP_RETURN_IF_ERROR(GetString(j, "mimeType", iw, &img.mime_type));
    std::string uri;
    HP_RETURN_IF_ERROR(GetString(j, "uri", iw, &uri));
    int64_t view = -1;
    HP_RETURN_IF_ERROR(GetIndex(j, "bufferView", iw, &view));
    if (view >= 0) {
      const uint8_t* data = nullptr;
      size_t size = 0, stride = 0;
      HP_RETURN_IF_ERROR(GetBufferView(view, iw, &data, &size, &stride));
      HP_RETURN_IF_ERROR(Charge(size, iw));
      img.bytes.assign(data, data + size);
    } else if (IsDataUri(uri)) {
      DataUri parsed;
      std::string error;
      if (!ParseDataUri(uri, &parsed, &error)) return Error(iw, error);
      img.bytes = std::move(parsed.bytes);
      if (img.mime_type.empty()) img.mime_type = parsed.mime_type;
    } else if (!uri.empty()) {
      img.uri = uri;
    } else {
      return Error(iw, "has neither a uri nor a bufferView");
    }
    scene->images.push_back(std::move(img));
  }
  return Status::Ok();
}

Status Decoder::DecodeTextureRef(const json& material, const char* key, const std::string& where,
                                 bool inside_pbr, TextureRef* out) {
  const json* holder = &material;
  if (inside_pbr) {
    auto it = material.find("pbrMetallicRoughness");
    if (it == material.end()) return Status::Ok();
    holder = &*it;
  }
  auto it = holder->find(key);
  if (it == holder->end()) return Status::Ok();
  const std::string tw = where + "." + key;
  if (!it->is_object()) return Error(tw, "is not an object");
  int64_t texture = -1;
  uint64_t tex_coord = 0;
  HP_RETURN_IF_ERROR(GetIndex(*it, "index", tw, &texture));
  HP_RETURN_IF_ERROR(GetUint(*it, "texCoord", tw, 0, &tex_coord));
  if (texture < 0) return Error(tw, "has no texture index");
  if (tex_coord > 255)
    return Error(tw, "texCoord " + std::to_string(tex_coord) + " is out of range");
  const json* textures = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("textures", &textures));
  if (textures == nullptr || static_cast<size_t>(texture) >= textures->size()) {
    return Error(tw, "texture " + std::to_string(texture) + " does not exist");
  }
  const std::string xw = Item("textures", static_cast<uint64_t>(texture));
  const json& t = (*textures)[static_cast<size_t>(texture)];
  int64_t source = -1;
  HP_RETURN_IF_ERROR(GetIndex(t, "source", xw, &source));
  if (source < 0) {
    // An extension (KHR_texture_basisu, EXT_texture_webp, ...) may name the image instead.
    auto ext = t.find("extensions");
    if (ext != t.end() && ext->is_object()) {
      for (const auto& e : ext->items()) {
        if (e.value().is_object() && e.value().contains("source")) {
          HP_RETURN_IF_ERROR(GetIndex(e.value(), "source", xw + ".extensions." + e.key(), &source));
          break;
        }
      }
    }
  }
  if (source < 0) {
    Drop(tw + ": texture without an image");
    return Status::Ok();
  }
  if (static_cast<size_t>(source) >= TopCount("images")) {
    return Error(xw, "source image " + std::to_string(source) + " does not exist");
  }
  HP_RETURN_IF_ERROR(DecodeSampler(t, xw, &out->sampler));
  auto transform_ext = it->find("extensions");
  if (transform_ext != it->end() && transform_ext->is_object() &&
      transform_ext->contains("KHR_texture_transform")) {
    const json& tt = (*transform_ext)["KHR_texture_transform"];
    const std::string ttw = tw + ".extensions.KHR_texture_transform";
    if (!tt.is_object()) return Error(ttw, "is not an object");
    UvTransform transform;
    HP_RETURN_IF_ERROR(GetNumbers(tt, "offset", ttw, 2, transform.offset));
    HP_RETURN_IF_ERROR(GetNumber(tt, "rotation", ttw, &transform.rotation));
    HP_RETURN_IF_ERROR(GetNumbers(tt, "scale", ttw, 2, transform.scale));
    HP_RETURN_IF_ERROR(GetUint(tt, "texCoord", ttw, tex_coord, &tex_coord));
    if (tex_coord > 255)
      return Error(ttw, "texCoord " + std::to_string(tex_coord) + " is out of range");
    for (double v : {transform.offset[0], transform.offset[1], transform.rotation,
                     transform.scale[0], transform.scale[1]}) {
      if (!std::isfinite(v)) return Error(ttw, "holds a number that is not finite");
    }
    auto [known, added] = current_uv_transforms_.emplace(static_cast<int>(tex_coord), transform);
    if (!added && !known->second.same(transform)) known->second.conflicting = true;
  } else {
    auto [known, added] =
        current_uv_transforms_.emplace(static_cast<int>(tex_coord), UvTransform());
    if (!added && !known->second.identity()) known->second.conflicting = true;
  }
  out->image = static_cast<int>(source);
  out->uv_set = static_cast<int>(tex_coord);
  return Status::Ok();
}

Status Decoder::DecodeSampler(const json& texture, const std::string& where, Sampler* out) {
  int64_t index = -1;
  HP_RETURN_IF_ERROR(GetIndex(texture, "sampler", where, &index));
  if (index < 0) return Status::Ok();
  const json* samplers = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("samplers", &samplers));
  if (samplers == nullptr || static_cast<size_t>(index) >= samplers->size())
    return Error(where, "sampler " + std::to_string(index) + " does not exist");
  const json& j = (*samplers)[static_cast<size_t>(index)];
  const std::string sw = Item("samplers", static_cast<uint64_t>(index));
  uint64_t mag = 0, min = 0, wrap_s = 10497, wrap_t = 10497;
  HP_RETURN_IF_ERROR(GetUint(j, "magFilter", sw, 0, &mag));
  HP_RETURN_IF_ERROR(GetUint(j, "minFilter", sw, 0, &min));
  HP_RETURN_IF_ERROR(GetUint(j, "wrapS", sw, 10497, &wrap_s));
  HP_RETURN_IF_ERROR(GetUint(j, "wrapT", sw, 10497, &wrap_t));
  // Codes glTF does not define are left to the viewer (filters) or to REPEAT (wraps), as a
  // viewer given them would do.
  auto known = [](uint64_t v, std::initializer_list<uint64_t> codes) {
    return std::find(codes.begin(), codes.end(), v) != codes.end();
  };
  out->mag_filter = known(mag, {9728, 9729}) ? static_cast<int>(mag) : 0;
  out->min_filter = known(min, {9728, 9729, 9984, 9985, 9986, 9987}) ? static_cast<int>(min) : 0;
  out->wrap_s = known(wrap_s, {33071, 33648, 10497}) ? static_cast<int>(wrap_s) : 10497;
  out->wrap_t = known(wrap_t, {33071, 33648, 10497}) ? static_cast<int>(wrap_t) : 10497;
  return Status::Ok();
}

void UvTransform::Apply(float* uv) const {
  const double u = scale[0] * double(uv[0]), v = scale[1] * double(uv[1]);
  const double c = std::cos(rotation), s = std::sin(rotation);
  uv[0] = static_cast<float>(offset[0] + c * u + s * v);
  uv[1] = static_cast<float>(offset[1] + c * v - s * u);
}

Status Decoder::DecodeTextureStrength(const json& material, const char* slot, const char* key,
                                      const std::string& where, float* out) {
  auto it = material.find(slot);
  if (it == material.end() || !it->is_object()) return Status::Ok();
  double value = *out;
  HP_RETURN_IF_ERROR(GetNumber(*it, key, where + "." + slot, &value));
  *out = static_cast<float>(value);
  return Status::Ok();
}

Status Decoder::DecodeMaterials(Scene* scene) {
  const json* materials = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("materials", &materials));
  if (materials == nullptr) return Status::Ok();
  for (size_t i = 0; i < materials->size(); ++i) {
    const json& j = (*materials)[i];
    const std::string mw = Item("materials", i);
    Material m;
    current_uv_transforms_.clear();
    HP_RETURN_IF_ERROR(GetString(j, "name", mw, &m.name));
    auto pbr = j.find("pbrMetallicRoughness");
    if (pbr != j.end()) {
      if (!pbr->is_object()) return Error(mw, "pbrMetallicRoughness is not an object");
      const std::string pw = mw + ".pbrMetallicRoughness";
      double base[4] = {1, 1, 1, 1};
      double metallic = 1, roughness = 1;
      HP_RETURN_IF_ERROR(GetNumbers(*pbr, "baseColorFactor", pw, 4, base));
      HP_RETURN_IF_ERROR(GetNumber(*pbr, "metallicFactor", pw, &metallic));
      HP_RETURN_IF_ERROR(GetNumber(*pbr, "roughnessFactor", pw, &roughness));
      for (int c = 0; c < 4; ++c)
        m.base_color[static_cast<size_t>(c)] = static_cast<float>(base[c]);
      m.metallic = static_cast<float>(metallic);
      m.roughness = static_cast<float>(roughness);
      HP_RETURN_IF_ERROR(DecodeTextureRef(j, "baseColorTexture", mw, true, &m.base_color_texture));
      HP_RETURN_IF_ERROR(
          DecodeTextureRef(j, "metallicRoughnessTexture", mw, true, &m.metallic_roughness_texture));
    }
    double emissive[3] = {0, 0, 0};
    HP_RETURN_IF_ERROR(GetNumbers(j, "emissiveFactor", mw, 3, emissive));
    for (int c = 0; c < 3; ++c)
      m.emissive[static_cast<size_t>(c)] = static_cast<float>(emissive[c]);
    HP_RETURN_IF_ERROR(GetBool(j, "doubleSided", mw, &m.double_sided));
    std::string alpha_mode;
    HP_RETURN_IF_ERROR(GetString(j, "alphaMode", mw, &alpha_mode));
    if (alpha_mode == "MASK") {
      m.alpha_mode = AlphaMode::kMask;
    } else if (alpha_mode == "BLEND") {
      m.alpha_mode = AlphaMode::kBlend;
    } else if (!alpha_mode.empty() && alpha_mode != "OPAQUE") {
      return Error(mw, "alphaMode '" + alpha_mode + "' is not OPAQUE, MASK or BLEND");
    }
    double cutoff = 0.5;
    HP_RETURN_IF_ERROR(GetNumber(j, "alphaCutoff", mw, &cutoff));
    if (cutoff < 0) return Error(mw, "alphaCutoff is negative");
    m.alpha_cutoff = static_cast<float>(cutoff);
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "normalTexture", mw, false, &m.normal_texture));
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "occlusionTexture", mw, false, &m.occlusion_texture));
    HP_RETURN_IF_ERROR(DecodeTextureRef(j, "emissiveTexture", mw, false, &m.emissive_texture));
    HP_RETURN_IF_ERROR(DecodeTextureStrength(j, "normalTexture", "scale", mw, &m.normal_scale));
    HP_RETURN_IF_ERROR(
        DecodeTextureStrength(j, "occlusionTexture", "strength", mw, &m.occlusion_strength));
    auto ext = j.find("extensions");
    if (ext != j.end() && ext->is_object()) {
      m.unlit = ext->contains("KHR_materials_unlit");
      auto strength = ext->find("KHR_materials_emissive_strength");
      if (strength != ext->end()) {
        const std::string ew = mw + ".extensions.KHR_materials_emissive_strength";
        if (!strength->is_object()) return Error(ew, "is not an object");
        double value = 1;
        HP_RETURN_IF_ERROR(GetNumber(*strength, "emissiveStrength", ew, &value));
        if (value < 0) return Error(ew, "emissiveStrength is negative");
        m.emissive_strength = static_cast<float>(value);
      }
    }
    scene->materials.push_back(std::move(m));
    for (const auto& [set, transform] : current_uv_transforms_) {
      if (transform.conflicting) {
        Drop(mw + ": textures sampling TEXCOORD_" + std::to_string(set) +
             " with different KHR_texture_transforms (kept untransformed)");
      }
    }
    material_uv_transforms_.push_back(current_uv_transforms_);
  }
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
