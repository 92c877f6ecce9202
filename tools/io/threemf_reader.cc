#include "io/threemf_reader.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <unordered_map>

#include "io/threemf_model.h"
#include "io/xml_scanner.h"
#include "io/zip_archive.h"

namespace hullpack {
namespace {

constexpr std::string_view kModelRelationship =
    "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";
constexpr size_t kMaxComponentDepth = 32;
// Components may place an object many times; a package whose instances multiply past this is
// refused instead of exhausting memory.
constexpr size_t kMaxNodes = 1000000;

std::string LowerAscii(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// A part name as a key: no leading '/', ASCII case folded (the Open Packaging Conventions compare
// part names so).
std::string PartKey(std::string_view path) {
  while (!path.empty() && path.front() == '/') path.remove_prefix(1);
  return LowerAscii(path);
}

float SrgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::array<float, 4> LinearColor(const std::array<float, 4>& srgb) {
  return {SrgbToLinear(srgb[0]), SrgbToLinear(srgb[1]), SrgbToLinear(srgb[2]), srgb[3]};
}

// The root part from the package's relationships, or the conventional name.
Result<std::string> RootModelPath(const ZipArchive& zip, const std::string& name) {
  const ZipEntry* rels = zip.Find("_rels/.rels");
  if (rels != nullptr) {
    Result<std::vector<uint8_t>> bytes = zip.Read(*rels);
    if (!bytes.ok()) return bytes.status();
    XmlScanner xml(std::string_view(reinterpret_cast<const char*>(bytes.value().data()),
                                    bytes.value().size()));
    for (XmlScanner::Token t = xml.Next(); t != XmlScanner::Token::kDone; t = xml.Next()) {
      if (t == XmlScanner::Token::kError) {
        return Status(StatusCode::kParseError, name + ": _rels/.rels: line " +
                                                   std::to_string(xml.line()) +
                                                   ": malformed XML: " + xml.error());
      }
      if (t == XmlScanner::Token::kStart && XmlScanner::LocalName(xml.name()) == "Relationship" &&
          XmlScanner::Decode(xml.Attribute("Type")) == kModelRelationship) {
        return XmlScanner::Decode(xml.Attribute("Target"));
      }
    }
  }
  if (zip.Find("3D/3dmodel.model") != nullptr) return std::string("3D/3dmodel.model");
  return Status(StatusCode::kParseError,
                name + ": not a 3MF package: no 3D model part (_rels/.rels names none)");
}

class SceneBuilder {
 public:
  SceneBuilder(const ZipArchive& zip, const std::string& name) : zip_(zip), name_(name) {}

  Result<Scene> Build(const std::string& root_path) {
    Result<const ThreeMfModel*> root = Model(root_path);
    if (!root.ok()) return root.status();
    const ThreeMfModel& model = *root.value();
    const std::string root_key = PartKey(root_path);

    // The package's unit into metres, +Z up into +Y up: (x, y, z) -> s (x, z, -y).
    Node top;
    const size_t slash = name_.find_last_of("/\\");
    top.name = slash == std::string::npos ? name_ : name_.substr(slash + 1);
    const double s = model.metres_per_unit;
    top.local_transform = {s, 0, 0, 0, 0, 0, -s, 0, 0, s, 0, 0, 0, 0, 0, 1};
    scene_.nodes.push_back(std::move(top));

    std::vector<ThreeMfObjectRef> build = model.build;
    if (build.empty()) {
      // No build items: place every object that no component places.
      std::set<uint32_t> placed;
      for (const auto& [id, object] : model.objects) {
        for (const ThreeMfObjectRef& c : object.components) {
          if (c.path.empty()) placed.insert(c.object_id);
        }
      }
      for (const auto& [id, object] : model.objects) {
        if (placed.count(id) == 0) build.push_back(ThreeMfObjectRef{id, "", kIdentity});
      }
    }
    for (const ThreeMfObjectRef& item : build) {
      Status placed = Place(root_key, item, 0, 0);
      if (!placed.ok()) return placed;
    }
    if (support_objects_ > 0) {
      scene_.dropped.push_back(std::to_string(support_objects_) +
                               " support object(s) (3MF type support or solidsupport)");
    }
    for (const auto& [key, part] : models_) {
      for (const std::string& line : part->dropped) scene_.dropped.push_back(line);
    }
    return std::move(scene_);
  }

 private:
  Status Error(const std::string& what) const {
    return Status(StatusCode::kParseError, name_ + ": " + what);
  }
  // Where an object is, for messages: "object 4 in 3D/3dmodel.model".
  std::string ObjectName(uint32_t id, const std::string& key) const {
    const auto it = part_names_.find(key);
    return "object " + std::to_string(id) + " in " + (it == part_names_.end() ? key : it->second);
  }

  // The parsed model part at `path`, parsed on first use.
  Result<const ThreeMfModel*> Model(const std::string& path) {
    const std::string key = PartKey(path);
    if (auto it = models_.find(key); it != models_.end()) return it->second.get();
    const ZipEntry* entry = zip_.Find(key);
    if (entry == nullptr) return Error("the package has no model part '" + path + "'");
    Result<std::vector<uint8_t>> bytes = zip_.Read(*entry);
    if (!bytes.ok()) return bytes.status();
    Result<ThreeMfModel> model = ParseThreeMfModel(
        std::string_view(reinterpret_cast<const char*>(bytes.value().data()), bytes.value().size()),
        name_ + ": " + entry->name);
    if (!model.ok()) return model.status();
    auto stored = std::make_unique<ThreeMfModel>(std::move(model).value());
    const ThreeMfModel* pointer = stored.get();
    models_.emplace(key, std::move(stored));
    part_names_.emplace(key, entry->name);
    return pointer;
  }

  // Adds a node for `ref` (an object of part `part_key`, or of ref.path) under `parent`, and the
  // nodes of its components under it.
  Status Place(const std::string& part_key, const ThreeMfObjectRef& ref, int parent, size_t depth) {
    if (depth > kMaxComponentDepth) {
      return Error("components nest deeper than " + std::to_string(kMaxComponentDepth) +
                   " (a cycle?)");
    }
    if (scene_.nodes.size() >= kMaxNodes) {
      return Error("its components place more than " + std::to_string(kMaxNodes) + " objects");
    }
    const std::string key = ref.path.empty() ? part_key : PartKey(ref.path);
    Result<const ThreeMfModel*> model = Model(ref.path.empty() ? part_key : ref.path);
    if (!model.ok()) return model.status();
    const auto found = model.value()->objects.find(ref.object_id);
    if (found == model.value()->objects.end()) {
      return Error(ObjectName(ref.object_id, key) + " is referenced but not defined");
    }
    const ThreeMfObject& object = found->second;
    const bool support = object.type == "support" || object.type == "solidsupport";
    if (support) {
      ++support_objects_;
      return Status::Ok();
    }
    Node node;
    node.name = object.name.empty() ? "object " + std::to_string(ref.object_id) : object.name;
    node.parent = parent;
    node.local_transform = ref.transform;
    const int index = static_cast<int>(scene_.nodes.size());
    scene_.nodes.push_back(std::move(node));
    scene_.nodes[static_cast<size_t>(parent)].children.push_back(index);
    if (object.has_mesh && !object.triangles.empty()) {
      Result<int> mesh = MeshOf(key, *model.value(), ref.object_id, object);
      if (!mesh.ok()) return mesh.status();
      scene_.nodes[static_cast<size_t>(index)].meshes.push_back(mesh.value());
    }
    for (const ThreeMfObjectRef& component : object.components) {
      Status placed = Place(key, component, index, depth + 1);
      if (!placed.ok()) return placed;
    }
    return Status::Ok();
  }

  enum class Kind { kNone, kBase, kColor, kTexture };

  // The property kind of group `pid` of `model`, or an error naming the object.
  Result<Kind> KindOf(const ThreeMfModel& model, int64_t pid, size_t index, uint32_t object_id,
                      const std::string& key) {
    if (pid < 0) return Kind::kNone;
    const uint32_t id = static_cast<uint32_t>(pid);
    size_t size = 0;
    Kind kind = Kind::kNone;
    if (auto it = model.base_materials.find(id); it != model.base_materials.end()) {
      kind = Kind::kBase;
      size = it->second.size();
    } else if (auto c = model.color_groups.find(id); c != model.color_groups.end()) {
      kind = Kind::kColor;
      size = c->second.size();
    } else if (auto t = model.texture_groups.find(id); t != model.texture_groups.end()) {
      kind = Kind::kTexture;
      size = t->second.uvs.size() / 2;
    } else if (model.unsupported_groups.count(id) != 0) {
      return Kind::kNone;
    } else {
      return Error(ObjectName(object_id, key) + " refers to property group " + std::to_string(id) +
                   ", which the part does not define");
    }
    if (index >= size) {
      return Error(ObjectName(object_id, key) + " refers to entry " + std::to_string(index) +
                   " of property group " + std::to_string(id) + ", which has " +
                   std::to_string(size));
    }
    return kind;
  }

  int DefaultMaterial() {
    if (default_material_ < 0) {
      default_material_ = static_cast<int>(scene_.materials.size());
      Material m;
      m.name = "3MF default";
      m.metallic = 0;
      scene_.materials.push_back(m);
    }
    return default_material_;
  }

  int BaseMaterial(const std::string& key, const ThreeMfModel& model, uint32_t pid, size_t index) {
    const auto cache_key = std::make_tuple(key, pid, index);
    if (auto it = base_materials_.find(cache_key); it != base_materials_.end()) return it->second;
    const ThreeMfBaseMaterial& base = model.base_materials.at(pid)[index];
    Material m;
    m.name = base.name;
    m.base_color = LinearColor(base.srgb);
    m.metallic = 0;
    if (m.base_color[3] < 1) m.alpha_mode = AlphaMode::kBlend;
    const int material = static_cast<int>(scene_.materials.size());
    scene_.materials.push_back(m);
    base_materials_.emplace(cache_key, material);
    return material;
  }

  int TextureMaterial(const std::string& key, const ThreeMfModel& model, uint32_t pid) {
    const auto cache_key = std::make_pair(key, pid);
    if (auto it = texture_materials_.find(cache_key); it != texture_materials_.end())
      return it->second;
    Material m;
    m.name = "texture group " + std::to_string(pid);
    m.metallic = 0;
    const ThreeMfTextureGroup& group = model.texture_groups.at(pid);
    const auto texture = model.textures.find(group.texture_id);
    if (texture == model.textures.end()) {
      scene_.dropped.push_back("texture " + std::to_string(group.texture_id) + " of " +
                               part_names_[key] + " (not defined)");
    } else {
      const int image = ImageOf(texture->second);
      if (image >= 0) {
        m.base_color_texture.image = image;
        m.base_color_texture.sampler = texture->second.sampler;
      }
    }
    const int material = static_cast<int>(scene_.materials.size());
    scene_.materials.push_back(m);
    texture_materials_.emplace(cache_key, material);
    return material;
  }

  int ImageOf(const ThreeMfTexture& texture) {
    const std::string key = PartKey(texture.path);
    if (auto it = images_.find(key); it != images_.end()) return it->second;
    int image = -1;
    const ZipEntry* entry = zip_.Find(key);
    Result<std::vector<uint8_t>> bytes =
        entry ? zip_.Read(*entry) : Status(StatusCode::kParseError, "not in the package");
    if (!bytes.ok()) {
      scene_.dropped.push_back("texture '" + texture.path + "': " + bytes.status().message());
    } else {
      Image img;
      img.name = texture.path;
      img.mime_type = texture.content_type;
      img.bytes = std::move(bytes).value();
      image = static_cast<int>(scene_.images.size());
      scene_.images.push_back(std::move(img));
    }
    images_.emplace(key, image);
    return image;
  }

  // The scene mesh of an object: one vertex per distinct (vertex, colour, texture coordinate)
  // its triangles' corners use; a mesh without per-corner properties keeps the file's vertices.
  Result<int> MeshOf(const std::string& key, const ThreeMfModel& model, uint32_t id,
                     const ThreeMfObject& object) {
    const auto cache_key = std::make_pair(key, id);
    if (auto it = meshes_.find(cache_key); it != meshes_.end()) return it->second;
    const size_t vertex_count = object.positions.size() / 3;
    scene_.source_vertex_records += vertex_count;
    const size_t n = object.triangles.size();
    struct Corners {
      Kind kind;
      int64_t pid;
      std::array<size_t, 3> p;
    };
    std::vector<Corners> corners(n);
    bool any_color = false;
    bool any_texture = false;
    bool any_property = false;
    for (size_t t = 0; t < n; ++t) {
      const ThreeMfTriangle& tri = object.triangles[t];
      for (uint32_t v : tri.v) {
        if (v >= vertex_count) {
          return Error(ObjectName(id, key) + ": triangle " + std::to_string(t) +
                       " refers to vertex " + std::to_string(v) + ", but it has " +
                       std::to_string(vertex_count));
        }
      }
      Corners& c = corners[t];
      c.pid = tri.pid >= 0 ? tri.pid : object.pid;
      const int64_t first = tri.p[0] >= 0 ? tri.p[0] : (object.pindex >= 0 ? object.pindex : 0);
      c.p = {static_cast<size_t>(first), static_cast<size_t>(tri.p[1] >= 0 ? tri.p[1] : first),
             static_cast<size_t>(tri.p[2] >= 0 ? tri.p[2] : first)};
      const size_t largest = std::max(c.p[0], std::max(c.p[1], c.p[2]));
      Result<Kind> kind = KindOf(model, c.pid, largest, id, key);
      if (!kind.ok()) return kind.status();
      c.kind = kind.value();
      any_color |= c.kind == Kind::kColor;
      any_texture |= c.kind == Kind::kTexture;
      any_property |= c.kind != Kind::kNone;
    }

    Mesh mesh;
    mesh.name = object.name.empty() ? "object " + std::to_string(id) : object.name;
    if (any_property) mesh.material_ids.resize(n);
    for (size_t t = 0; t < n; ++t) {
      const Corners& c = corners[t];
      if (!any_property) break;
      const uint32_t pid = static_cast<uint32_t>(c.pid);
      int material = -1;
      if (c.kind == Kind::kBase && !any_color) material = BaseMaterial(key, model, pid, c.p[0]);
      if (c.kind == Kind::kTexture) material = TextureMaterial(key, model, pid);
      if (material < 0) material = DefaultMaterial();
      mesh.material_ids[t] = static_cast<uint32_t>(material);
    }
    if (!any_color && !any_texture) {
      mesh.positions = object.positions;
      mesh.indices.reserve(n * 3);
      for (const ThreeMfTriangle& tri : object.triangles) {
        mesh.indices.insert(mesh.indices.end(), tri.v.begin(), tri.v.end());
      }
    } else {
      // Corners that share a vertex and its properties share a scene vertex. In a coloured mesh a
      // base material's corners carry its colour and the default material, so that it is not
      // applied twice, and textured corners are white.
      std::unordered_map<uint64_t, uint32_t> vertex_of;
      std::map<std::pair<int64_t, size_t>, uint32_t> slot_of;  // (group, entry) -> slot
      std::vector<std::array<float, 4>> slot_color;
      std::vector<std::array<float, 2>> slot_uv;
      const uint32_t kNoSlot = 0xFFFFFFFFu;
      auto slot = [&](const Corners& c, size_t corner) -> uint32_t {
        if (c.kind == Kind::kNone) return kNoSlot;
        const auto k = std::make_pair(c.pid, c.p[corner]);
        if (auto it = slot_of.find(k); it != slot_of.end()) return it->second;
        const uint32_t pid = static_cast<uint32_t>(c.pid);
        std::array<float, 4> color = {1, 1, 1, 1};
        std::array<float, 2> uv = {0, 0};
        if (c.kind == Kind::kColor) color = LinearColor(model.color_groups.at(pid)[c.p[corner]]);
        if (c.kind == Kind::kBase)
          color = LinearColor(model.base_materials.at(pid)[c.p[corner]].srgb);
        if (c.kind == Kind::kTexture) {
          const std::vector<float>& uvs = model.texture_groups.at(pid).uvs;
          uv = {uvs[2 * c.p[corner]], 1.0f - uvs[2 * c.p[corner] + 1]};
        }
        const uint32_t s = static_cast<uint32_t>(slot_color.size());
        slot_color.push_back(color);
        slot_uv.push_back(uv);
        slot_of.emplace(k, s);
        return s;
      };
      if (any_texture) mesh.uv_sets.emplace_back();
      mesh.indices.reserve(n * 3);
      for (size_t t = 0; t < n; ++t) {
        for (size_t corner = 0; corner < 3; ++corner) {
          const uint32_t v = object.triangles[t].v[corner];
          const uint32_t s = slot(corners[t], corner);
          const uint64_t k = (static_cast<uint64_t>(v) << 32) | s;
          auto [it, added] = vertex_of.emplace(k, static_cast<uint32_t>(mesh.vertex_count()));
          if (added) {
            mesh.positions.insert(mesh.positions.end(), &object.positions[3 * v],
                                  &object.positions[3 * v] + 3);
            const std::array<float, 4> white = {1, 1, 1, 1};
            const std::array<float, 2> origin = {0, 0};
            const std::array<float, 4>& color = s == kNoSlot ? white : slot_color[s];
            const std::array<float, 2>& uv = s == kNoSlot ? origin : slot_uv[s];
            if (any_color) mesh.colors.insert(mesh.colors.end(), color.begin(), color.end());
            if (any_texture) mesh.uv_sets[0].insert(mesh.uv_sets[0].end(), uv.begin(), uv.end());
          }
          mesh.indices.push_back(it->second);
        }
      }
    }
    const int index = static_cast<int>(scene_.meshes.size());
    scene_.meshes.push_back(std::move(mesh));
    meshes_.emplace(cache_key, index);
    return index;
  }

  const ZipArchive& zip_;
  std::string name_;
  Scene scene_;
  std::map<std::string, std::unique_ptr<ThreeMfModel>> models_;
  std::map<std::string, std::string> part_names_;  // key -> the name as the package stores it
  std::map<std::pair<std::string, uint32_t>, int> meshes_;
  std::map<std::tuple<std::string, uint32_t, size_t>, int> base_materials_;
  std::map<std::pair<std::string, uint32_t>, int> texture_materials_;
  std::map<std::string, int> images_;
  int default_material_ = -1;
  size_t support_objects_ = 0;
};

}  // namespace

Result<Scene> Parse3mf(const uint8_t* data, size_t size, const std::string& name) {
  Result<ZipArchive> zip = ZipArchive::Open(data, size, name);
  if (!zip.ok()) return zip.status();
  Result<std::string> root = RootModelPath(zip.value(), name);
  if (!root.ok()) return root.status();
  return SceneBuilder(zip.value(), name).Build(root.value());
}

}  // namespace hullpack
