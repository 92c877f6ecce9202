// The glTF reader's decoder (glb_reader.h), shared by its files, one concern each:
// glb_reader_container.cc (base64, data URIs, files, JSON access, extensions, buffers),
// glb_reader_accessors.cc (buffer views and accessors), glb_reader_materials.cc (images and
// materials), glb_reader_meshes.cc, glb_reader_skins.cc, glb_reader_nodes.cc, and glb_reader.cc
// (the order of the stages and the public functions). Internal to tools/gltf.
#ifndef HULLPACK_TOOLS_GLTF_GLB_READER_DECODER_H_
#define HULLPACK_TOOLS_GLTF_GLB_READER_DECODER_H_

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "common/status.h"
#include "gltf/glb_reader.h"
#include "gltf/gltf_document.h"
#include "scene/scene.h"

namespace hullpack {
namespace glb_reader_internal {

using nlohmann::json;

#define HP_RETURN_IF_ERROR(expr)             \
  do {                                       \
    Status hp_status_ = (expr);              \
    if (!hp_status_.ok()) return hp_status_; \
  } while (0)

constexpr uint64_t kMaxIndex = static_cast<uint64_t>(std::numeric_limits<int>::max());

inline std::string Item(const char* array, uint64_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// a * b + c without overflow; false when it would not fit.
inline bool MulAdd(uint64_t a, uint64_t b, uint64_t c, uint64_t* out) {
  uint64_t m;
  if (__builtin_mul_overflow(a, b, &m)) return false;
  return !__builtin_add_overflow(m, c, out);
}

inline uint32_t LoadU32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

inline uint16_t LoadU16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }

// Base64, data URIs and files (glb_reader_container.cc).
bool DecodeBase64(const std::string& text, size_t begin, std::vector<uint8_t>* out);
struct DataUri {
  std::string mime_type;
  std::vector<uint8_t> bytes;
};

// "data:<mime>;base64,<payload>". Returns false with `error` set when malformed.
bool ParseDataUri(const std::string& uri, DataUri* out, std::string* error);
bool IsDataUri(const std::string& uri);
Status ReadWholeFile(const std::string& path, std::vector<uint8_t>* out);

// A checked accessor: where its elements are and how to read them.
struct AccessorView {
  const uint8_t* data = nullptr;  // first element; nullptr for a zero-filled accessor
  size_t count = 0;
  int components = 0;
  int component_type = 0;
  size_t stride = 0;
  bool normalized = false;
  std::string type;
};

// One component of an accessor element (glb_reader_accessors.cc).
double ReadComponent(const uint8_t* p, int component_type, bool normalized);
uint32_t ReadUnsigned(const uint8_t* p, int component_type);

struct BufferData {
  bool resolved = false;
  std::vector<uint8_t> storage;  // data URI or external file contents
  const uint8_t* data = nullptr;
  size_t size = 0;  // the declared byteLength (checked against the data)
};

// A texture's KHR_texture_transform: uv' = offset + rotate(scale * uv), as glTF viewers and
// engines apply it. The reader bakes it into the UV set (a packed file keeps no material
// extension), so the texture lands where the source file puts it.
struct UvTransform {
  double offset[2] = {0, 0};
  double rotation = 0;
  double scale[2] = {1, 1};
  bool conflicting = false;  // textures of one material sample this set with different transforms

  bool identity() const {
    return offset[0] == 0 && offset[1] == 0 && rotation == 0 && scale[0] == 1 && scale[1] == 1;
  }
  bool same(const UvTransform& o) const {
    return offset[0] == o.offset[0] && offset[1] == o.offset[1] && rotation == o.rotation &&
           scale[0] == o.scale[0] && scale[1] == o.scale[1];
  }
  void Apply(float* uv) const;
};

class Decoder {
 public:
  Decoder(const GltfDocument& doc, const std::string& name, const GltfReadOptions& options)
      : doc_(doc), root_(doc.json()), name_(name), options_(options) {
    uint64_t input = doc.source_size() != 0 ? doc.source_size() : doc.binary().size();
    budget_ = input * std::max<size_t>(options.max_expansion, 1) + (1u << 20);
  }

  Result<Scene> Run();

 private:
  Status Error(const std::string& where, const std::string& what) const {
    return Status(StatusCode::kParseError, name_ + ": " + where + ": " + what);
  }
  Status Unsupported(const std::string& where, const std::string& what) const {
    return Status(StatusCode::kUnsupported, name_ + ": " + where + ": " + what);
  }
  Status Charge(uint64_t bytes, const std::string& where) {
    if (bytes > budget_) {
      return Unsupported(where, "decoded data would exceed the limit of " +
                                    std::to_string(options_.max_expansion) +
                                    " bytes per input byte (file too small for what it declares)");
    }
    budget_ -= bytes;
    return Status::Ok();
  }

  // JSON access. Each returns an error naming `where` when the value has the wrong type.
  Status GetArray(const json& obj, const char* key, const std::string& where,
                  const json** out) const;
  Status GetIndex(const json& obj, const char* key, const std::string& where, int64_t* out) const;
  Status GetUint(const json& obj, const char* key, const std::string& where, uint64_t def,
                 uint64_t* out) const;
  Status GetNumbers(const json& obj, const char* key, const std::string& where, size_t n,
                    double* out) const;
  Status GetNumber(const json& obj, const char* key, const std::string& where, double* out) const;
  Status GetString(const json& obj, const char* key, const std::string& where,
                   std::string* out) const;
  Status GetBool(const json& obj, const char* key, const std::string& where, bool* out) const;
  // The top-level array `key` (empty when missing); elements must be objects.
  Status TopLevel(const char* key, const json** out);
  size_t TopCount(const char* key) const {
    auto it = root_.find(key);
    return it != root_.end() && it->is_array() ? it->size() : 0;
  }

  Status CheckExtensions();
  Status GetBuffer(int64_t index, const std::string& where, const BufferData** out);
  Status GetBufferView(int64_t index, const std::string& where, const uint8_t** data, size_t* size,
                       size_t* stride);
  // A sparse accessor is an error unless `allow_sparse` (its base is then described by `out`; the
  // caller applies the substitutions: ApplySparse).
  Status GetAccessor(int64_t index, const std::string& where, AccessorView* out,
                     bool allow_sparse = false);
  // The `sparse` substitutions of accessor `index` (described by `a`) written into `out`
  // (a.count x a.components floats): indices strictly increasing and below the count.
  Status ApplySparse(int64_t index, const AccessorView& a, std::vector<float>* out);
  // An accessor as floats (normalized integers mapped per the spec, sparse substitutions applied);
  // its component count must be one of `allowed_components`.
  Status ReadFloats(int64_t index, const std::string& where,
                    std::initializer_list<int> allowed_components, std::vector<float>* out,
                    int* components);
  Status ReadIndices(int64_t index, const std::string& where, std::vector<uint32_t>* out);

  Status DecodeImages(Scene* scene);
  Status DecodeTextureRef(const json& material, const char* key, const std::string& where,
                          bool inside_pbr, TextureRef* out);
  Status DecodeSampler(const json& texture, const std::string& where, Sampler* out);
  // normalTexture.scale or occlusionTexture.strength, when the slot has one.
  Status DecodeTextureStrength(const json& material, const char* slot, const char* key,
                               const std::string& where, float* out);
  Status DecodeMaterials(Scene* scene);
  Status DecodeMesh(int64_t index, Scene* scene, Mesh* out);
  // Pads the mesh's morph targets to its vertex count; mesh.weights and extras.targetNames.
  Status DecodeMorphTargetNamesAndWeights(const json& mesh, const std::string& where, Mesh* out);
  Status DecodeSkins(Scene* scene);
  Status DecodeCameras(Scene* scene);
  Status DecodeLights(Scene* scene);
  Status DecodeNodes(Scene* scene);
  Status DecodeAnimations(Scene* scene);
  // The morph-target count of node `node`'s mesh (0 without one); node < the node count.
  size_t MorphTargetsOfNode(const Scene& scene, size_t node) const;
  // Nodes that animations drive but that the file gave as a matrix (invalid glTF, but seen) get
  // the TRS of their matrix; channels of a node without one (shear) are dropped.
  void GiveAnimatedNodesTrs(Scene* scene);
  // `width`: values per key (for weights, the morph-target count of the driven mesh).
  Status DecodeAnimationSampler(const json& j, const std::string& where, AnimationPath path,
                                size_t width, AnimationSampler* out);
  void Drop(const std::string& what) { dropped_.push_back(what); }

  const GltfDocument& doc_;
  const json& root_;
  std::string name_;
  GltfReadOptions options_;
  uint64_t budget_ = 0;
  std::vector<std::unique_ptr<BufferData>> buffers_;
  std::vector<std::string> dropped_;
  size_t non_triangle_primitives_ = 0;
  std::set<std::string> dropped_attributes_;
  int default_material_ = -1;
  // Per material: the transform of each UV set its textures sample (DecodeMaterials), and the one
  // being read.
  std::vector<std::map<int, UvTransform>> material_uv_transforms_;
  std::map<int, UvTransform> current_uv_transforms_;
  std::map<std::string, const json*> top_level_;  // checked top-level arrays (nullptr: absent)
};

}  // namespace glb_reader_internal
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_GLB_READER_DECODER_H_
