#include "io/threemf_model.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "io/xml_scanner.h"

namespace hullpack {
namespace {

constexpr std::string_view kCoreNamespace =
    "http://schemas.microsoft.com/3dmanufacturing/core/2015/02";
constexpr std::string_view kMaterialNamespace =
    "http://schemas.microsoft.com/3dmanufacturing/material/2015/02";
constexpr std::string_view kProductionNamespace =
    "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";

std::string_view Trim(std::string_view s) {
  while (!s.empty() &&
         (s.front() == ' ' || s.front() == '\t' || s.front() == '\n' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() &&
         (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool ParseDouble(std::string_view text, double* out) {
  text = Trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), *out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(*out);
}

bool ParseIndex(std::string_view text, uint32_t* out) {
  text = Trim(text);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), *out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && !text.empty();
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#RRGGBB" or "#RRGGBBAA", sRGB.
bool ParseColor(std::string_view text, std::array<float, 4>* out) {
  text = Trim(text);
  if ((text.size() != 7 && text.size() != 9) || text[0] != '#') return false;
  *out = {1, 1, 1, 1};
  for (size_t c = 0; c * 2 + 1 < text.size(); ++c) {
    const int hi = HexDigit(text[1 + 2 * c]);
    const int lo = HexDigit(text[2 + 2 * c]);
    if (hi < 0 || lo < 0) return false;
    (*out)[c] = static_cast<float>(hi * 16 + lo) / 255.0f;
  }
  return true;
}

// Twelve numbers, row by row of a 4x3 matrix that multiplies row vectors: its last row is the
// translation. As a column-major 4x4 matrix they are the same twelve in order, each triple
// followed by the homogeneous 0 (and 1 at the end).
bool ParseTransform(std::string_view text, Matrix4* out) {
  text = Trim(text);
  Matrix4 m = kIdentity;
  for (int i = 0; i < 12; ++i) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n' ||
                             text.front() == '\r'))
      text.remove_prefix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
    if (r.ec != std::errc() || !std::isfinite(value)) return false;
    text.remove_prefix(static_cast<size_t>(r.ptr - text.data()));
    m[static_cast<size_t>((i / 3) * 4 + i % 3)] = value;
  }
  if (!Trim(text).empty()) return false;
  *out = m;
  return true;
}

bool UnitScale(std::string_view unit, double* metres) {
  if (unit == "micron") {
    *metres = 1e-6;
  } else if (unit == "millimeter") {
    *metres = 1e-3;
  } else if (unit == "centimeter") {
    *metres = 1e-2;
  } else if (unit == "inch") {
    *metres = 0.0254;
  } else if (unit == "foot") {
    *metres = 0.3048;
  } else if (unit == "meter") {
    *metres = 1;
  } else {
    return false;
  }
  return true;
}

int WrapCode(std::string_view style) {
  if (style == "mirror") return 33648;
  if (style == "clamp" || style == "none") return 33071;
  return 10497;  // "wrap", the default
}

class ModelParser {
 public:
  ModelParser(std::string_view xml, const std::string& where) : xml_(xml), where_(where) {}

  Result<ThreeMfModel> Parse() {
    for (;;) {
      const XmlScanner::Token token = xml_.Next();
      if (token == XmlScanner::Token::kError) return XmlError(xml_.error());
      if (token == XmlScanner::Token::kDone) break;
      if (!error_.empty()) break;
      if (token == XmlScanner::Token::kStart) {
        Start();
      } else {
        End();
      }
      if (!error_.empty()) break;
    }
    if (!unsupported_.empty())
      return Status(StatusCode::kUnsupported, where_ + ": " + unsupported_);
    if (!error_.empty()) {
      return Status(StatusCode::kParseError,
                    where_ + ": line " + std::to_string(xml_.line()) + ": " + error_);
    }
    if (!seen_model_) return Status(StatusCode::kParseError, where_ + ": no <model> element");
    return std::move(model_);
  }

 private:
  Status XmlError(const std::string& what) const {
    return Status(StatusCode::kParseError,
                  where_ + ": line " + std::to_string(xml_.line()) + ": malformed XML: " + what);
  }

  void Fail(const std::string& what) {
    if (error_.empty()) error_ = what;
  }

  // The namespace of a qualified element name, from the model element's declarations.
  std::string_view NamespaceOf(std::string_view qualified) const {
    const std::string_view prefix = XmlScanner::Prefix(qualified);
    const auto it = namespaces_.find(std::string(prefix));
    return it == namespaces_.end() ? std::string_view() : std::string_view(it->second);
  }

  std::string_view Attr(std::string_view name, bool* found = nullptr) const {
    return xml_.Attribute(name, found);
  }
  // An attribute of the production extension (p:path), whatever its prefix is called.
  std::string_view ProductionAttr(std::string_view local) const {
    for (const auto& [key, value] : xml_.attributes()) {
      if (XmlScanner::LocalName(key) != local || XmlScanner::Prefix(key).empty()) continue;
      if (NamespaceOf(key) == kProductionNamespace) return value;
    }
    return {};
  }

  bool RequiredIndex(std::string_view attribute, uint32_t* out) {
    bool found = false;
    const std::string_view text = Attr(attribute, &found);
    if (!found) {
      Fail("<" + std::string(xml_.name()) + "> has no " + std::string(attribute));
      return false;
    }
    if (!ParseIndex(text, out)) {
      Fail("<" + std::string(xml_.name()) + "> " + std::string(attribute) + " '" +
           std::string(text) + "' is not a non-negative integer");
      return false;
    }
    return true;
  }
  // -1 when absent.
  int64_t OptionalIndex(std::string_view attribute) {
    bool found = false;
    const std::string_view text = Attr(attribute, &found);
    if (!found) return -1;
    uint32_t value = 0;
    if (!ParseIndex(text, &value)) {
      Fail("<" + std::string(xml_.name()) + "> " + std::string(attribute) + " '" +
           std::string(text) + "' is not a non-negative integer");
      return -1;
    }
    return value;
  }
  double RequiredNumber(std::string_view attribute) {
    bool found = false;
    const std::string_view text = Attr(attribute, &found);
    double value = 0;
    if (!found || !ParseDouble(text, &value)) {
      Fail("<" + std::string(xml_.name()) + "> " + std::string(attribute) +
           (found ? " '" + std::string(text) + "' is not a finite number" : " is missing"));
    }
    return value;
  }
  Matrix4 OptionalTransform() {
    bool found = false;
    const std::string_view text = Attr("transform", &found);
    Matrix4 m = kIdentity;
    if (found && !ParseTransform(text, &m)) {
      Fail("<" + std::string(xml_.name()) + "> transform '" + std::string(text) +
           "' is not 12 finite numbers");
    }
    return m;
  }

  void StartModel() {
    seen_model_ = true;
    for (const auto& [key, value] : xml_.attributes()) {
      if (key == "xmlns") namespaces_[""] = XmlScanner::Decode(value);
      if (key.substr(0, 6) == "xmlns:")
        namespaces_[std::string(key.substr(6))] = XmlScanner::Decode(value);
    }
    bool found = false;
    const std::string_view unit = Attr("unit", &found);
    if (found && !UnitScale(Trim(unit), &model_.metres_per_unit)) {
      Fail("unknown unit '" + std::string(unit) + "'");
    }
    std::string_view required = Attr("requiredextensions");
    while (!(required = Trim(required)).empty()) {
      const size_t space = required.find_first_of(" \t\r\n");
      const std::string prefix(required.substr(0, space));
      required = space == std::string_view::npos ? std::string_view() : required.substr(space);
      const auto it = namespaces_.find(prefix);
      const std::string ns = it == namespaces_.end() ? prefix : it->second;
      if (ns != kCoreNamespace && ns != kMaterialNamespace && ns != kProductionNamespace) {
        unsupported_ = "requires the 3MF extension " + ns +
                       ", which hullpack does not read (it reads the core specification and "
                       "the materials and production extensions)";
        Fail(unsupported_);
      }
    }
  }

  void Start() {
    const std::string_view qualified = xml_.name();
    const std::string_view ns = NamespaceOf(qualified);
    const std::string_view name = XmlScanner::LocalName(qualified);
    if (!seen_model_) {
      if (name != "model") {
        Fail("the document element is <" + std::string(qualified) + ">, not <model>");
        return;
      }
      StartModel();
      return;
    }
    if (!IsReadNamespace(ns)) {
      if (name == "beamlattice" || name == "slicestack") NoteDropped(name);
      return;  // an extension this reader does not read, and the file does not require
    }
    if (name == "object") {
      object_ = ThreeMfObject();
      in_object_ = RequiredIndex("id", &object_id_);
      object_.name = XmlScanner::Decode(Attr("name"));
      bool found = false;
      const std::string_view type = Attr("type", &found);
      if (found) object_.type = std::string(Trim(type));
      object_.pid = OptionalIndex("pid");
      object_.pindex = OptionalIndex("pindex");
    } else if (name == "mesh") {
      if (in_object_) object_.has_mesh = true;
    } else if (name == "vertex") {
      if (!in_object_) return Fail("<vertex> outside an object");
      for (const char* axis : {"x", "y", "z"}) {
        const double value = RequiredNumber(axis);
        if (std::fabs(value) > std::numeric_limits<float>::max()) {
          return Fail("vertex coordinate out of range");
        }
        object_.positions.push_back(static_cast<float>(value));
      }
    } else if (name == "triangle") {
      if (!in_object_) return Fail("<triangle> outside an object");
      ThreeMfTriangle t;
      if (!RequiredIndex("v1", &t.v[0]) || !RequiredIndex("v2", &t.v[1]) ||
          !RequiredIndex("v3", &t.v[2]))
        return;
      t.pid = OptionalIndex("pid");
      t.p = {OptionalIndex("p1"), OptionalIndex("p2"), OptionalIndex("p3")};
      object_.triangles.push_back(t);
    } else if (name == "component") {
      if (!in_object_) return Fail("<component> outside an object");
      ThreeMfObjectRef ref;
      if (!RequiredIndex("objectid", &ref.object_id)) return;
      ref.transform = OptionalTransform();
      ref.path = XmlScanner::Decode(ProductionAttr("path"));
      object_.components.push_back(std::move(ref));
    } else if (name == "item") {
      ThreeMfObjectRef ref;
      if (!RequiredIndex("objectid", &ref.object_id)) return;
      ref.transform = OptionalTransform();
      ref.path = XmlScanner::Decode(ProductionAttr("path"));
      model_.build.push_back(std::move(ref));
    } else if (name == "basematerials") {
      if (!RequiredIndex("id", &group_id_)) return;
      CheckUnique(group_id_);
      model_.base_materials[group_id_];
      open_group_ = Group::kBase;
    } else if (name == "base") {
      ThreeMfBaseMaterial base;
      base.name = XmlScanner::Decode(Attr("name"));
      bool found = false;
      const std::string_view color = Attr("displaycolor", &found);
      if (found && !ParseColor(color, &base.srgb)) {
        return Fail("displaycolor '" + std::string(color) + "' is not #RRGGBB or #RRGGBBAA");
      }
      if (open_group_ == Group::kBase) model_.base_materials[group_id_].push_back(std::move(base));
    } else if (name == "colorgroup") {
      if (!RequiredIndex("id", &group_id_)) return;
      CheckUnique(group_id_);
      model_.color_groups[group_id_];
      open_group_ = Group::kColor;
    } else if (name == "color") {
      std::array<float, 4> srgb;
      const std::string_view color = Attr("color");
      if (!ParseColor(color, &srgb)) {
        return Fail("color '" + std::string(color) + "' is not #RRGGBB or #RRGGBBAA");
      }
      if (open_group_ == Group::kColor) model_.color_groups[group_id_].push_back(srgb);
    } else if (name == "texture2d") {
      uint32_t id = 0;
      if (!RequiredIndex("id", &id)) return;
      ThreeMfTexture texture;
      texture.path = XmlScanner::Decode(Attr("path"));
      texture.content_type = std::string(Trim(Attr("contenttype")));
      texture.sampler.wrap_s = WrapCode(Trim(Attr("tilestyleu")));
      texture.sampler.wrap_t = WrapCode(Trim(Attr("tilestylev")));
      const std::string_view filter = Trim(Attr("filter"));
      if (filter == "nearest") texture.sampler.mag_filter = texture.sampler.min_filter = 9728;
      if (filter == "linear") texture.sampler.mag_filter = texture.sampler.min_filter = 9729;
      CheckUnique(id);
      model_.textures.emplace(id, std::move(texture));
    } else if (name == "texture2dgroup") {
      ThreeMfTextureGroup group;
      if (!RequiredIndex("id", &group_id_) || !RequiredIndex("texid", &group.texture_id)) return;
      CheckUnique(group_id_);
      model_.texture_groups.emplace(group_id_, std::move(group));
      open_group_ = Group::kTexture;
    } else if (name == "tex2coord") {
      const double u = RequiredNumber("u");
      const double v = RequiredNumber("v");
      if (open_group_ == Group::kTexture) {
        std::vector<float>& uvs = model_.texture_groups[group_id_].uvs;
        uvs.push_back(static_cast<float>(u));
        uvs.push_back(static_cast<float>(v));
      }
    } else if (name == "compositematerials" || name == "multiproperties") {
      uint32_t id = 0;
      if (RequiredIndex("id", &id)) {
        CheckUnique(id);
        model_.unsupported_groups.insert(id);
        NoteDropped(name);
      }
    }
  }

  void End() {
    const std::string_view qualified = xml_.name();
    if (!IsReadNamespace(NamespaceOf(qualified))) return;
    const std::string_view name = XmlScanner::LocalName(qualified);
    if (name == "basematerials" || name == "colorgroup" || name == "texture2dgroup") {
      open_group_ = Group::kNone;
    } else if (name == "object" && in_object_) {
      in_object_ = false;
      CheckUnique(object_id_);
      model_.objects.emplace(object_id_, std::move(object_));
    }
  }

  // Files that declare no namespace are read as the core specification.
  static bool IsReadNamespace(std::string_view ns) {
    return ns.empty() || ns == kCoreNamespace || ns == kMaterialNamespace ||
           ns == kProductionNamespace;
  }
  // Objects and property groups share one id space per model part.
  void CheckUnique(uint32_t id) {
    if (!ids_.insert(id).second) DuplicateId(id);
  }
  void DuplicateId(uint32_t id) { Fail("resource id " + std::to_string(id) + " is used twice"); }

  void NoteDropped(std::string_view element) {
    if (dropped_kinds_.insert(std::string(element)).second) {
      model_.dropped.push_back(where_ + ": <" + std::string(element) +
                               "> elements are not kept (3MF extension not read)");
    }
  }

  XmlScanner xml_;
  std::string where_;
  ThreeMfModel model_;
  std::map<std::string, std::string> namespaces_;
  std::set<uint32_t> ids_;
  std::set<std::string> dropped_kinds_;
  std::string error_;
  std::string unsupported_;
  enum class Group { kNone, kBase, kColor, kTexture };
  Group open_group_ = Group::kNone;
  bool seen_model_ = false;
  bool in_object_ = false;
  uint32_t object_id_ = 0;
  uint32_t group_id_ = 0;
  ThreeMfObject object_;
};

}  // namespace

Result<ThreeMfModel> ParseThreeMfModel(std::string_view xml, const std::string& where) {
  return ModelParser(xml, where).Parse();
}

}  // namespace hullpack
