#include "io/ply_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/text_scanner.h"

namespace hullpack {
namespace {

enum class Type : uint8_t { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

bool TypeNamed(std::string_view w, Type* t) {
  static constexpr std::pair<std::string_view, Type> kNames[] = {
      {"char", Type::kInt8},      {"int8", Type::kInt8},       {"uchar", Type::kUint8},
      {"uint8", Type::kUint8},    {"short", Type::kInt16},     {"int16", Type::kInt16},
      {"ushort", Type::kUint16},  {"uint16", Type::kUint16},   {"int", Type::kInt32},
      {"int32", Type::kInt32},    {"uint", Type::kUint32},     {"uint32", Type::kUint32},
      {"float", Type::kFloat32},  {"float32", Type::kFloat32}, {"double", Type::kFloat64},
      {"float64", Type::kFloat64}};
  for (const auto& [n, type] : kNames) {
    if (w == n) {
      *t = type;
      return true;
    }
  }
  return false;
}

size_t SizeOf(Type t) {
  switch (t) {
    case Type::kInt8:
    case Type::kUint8:
      return 1;
    case Type::kInt16:
    case Type::kUint16:
      return 2;
    case Type::kInt32:
    case Type::kUint32:
    case Type::kFloat32:
      return 4;
    case Type::kFloat64:
      return 8;
  }
  return 1;
}

bool IsFloat(Type t) { return t == Type::kFloat32 || t == Type::kFloat64; }

struct Property {
  std::string name;
  Type type = Type::kFloat32;
  bool list = false;
  Type count_type = Type::kUint8;  // lists only
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  size_t body = 0;           // offset of the first byte after end_header's line
  size_t lines = 0;          // lines of the header (for ASCII messages)
  std::string texture_file;  // MeshLab's "comment TextureFile NAME"
  size_t unknown_lines = 0;  // header lines of no keyword, read past
};

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

Result<Header> ParseHeader(const uint8_t* data, size_t size, const std::string& name) {
  Header h;
  auto error = [&](const std::string& what) {
    return Status(StatusCode::kParseError,
                  name + ": PLY header line " + std::to_string(h.lines) + ": " + what);
  };
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  size_t at = 0;
  bool format = false;
  while (true) {
    if (at >= text.size()) {
      ++h.lines;
      return error("no end_header (truncated file, or not a PLY file)");
    }
    const size_t nl = text.find('\n', at);
    const std::string_view line = text.substr(at, nl == std::string_view::npos ? nl : nl - at);
    at = nl == std::string_view::npos ? text.size() : nl + 1;
    ++h.lines;
    const std::vector<std::string_view> w = Words(line);
    if (h.lines == 1) {
      if (w.size() != 1 || w[0] != "ply") return error("the file does not start with 'ply'");
      continue;
    }
    if (w.size() >= 3 && w[0] == "comment" && w[1] == "TextureFile" && h.texture_file.empty()) {
      const size_t from = line.find("TextureFile") + std::strlen("TextureFile");
      std::string_view file = line.substr(from);
      while (!file.empty() && (file.front() == ' ' || file.front() == '\t')) file.remove_prefix(1);
      while (!file.empty() && (file.back() == ' ' || file.back() == '\t' || file.back() == '\r'))
        file.remove_suffix(1);
      h.texture_file = std::string(file);
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") return error("expected 'format <encoding> 1.0'");
      if (w[1] == "ascii") {
        h.encoding = Encoding::kAscii;
      } else if (w[1] == "binary_little_endian") {
        h.encoding = Encoding::kLittleEndian;
      } else if (w[1] == "binary_big_endian") {
        h.encoding = Encoding::kBigEndian;
      } else {
        return error("unknown encoding '" + std::string(w[1]) + "'");
      }
      format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) return error("expected 'element <name> <count>'");
      Element e;
      e.name = std::string(w[1]);
      const auto r = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (r.ec != std::errc() || r.ptr != w[2].data() + w[2].size())
        return error("element '" + e.name + "': count '" + std::string(w[2]) + "' is not a number");
      h.elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (h.elements.empty()) return error("a property before any element");
      Property p;
      if (w.size() == 5 && w[1] == "list") {
        p.list = true;
        if (!TypeNamed(w[2], &p.count_type) || IsFloat(p.count_type) || !TypeNamed(w[3], &p.type))
          return error("unknown or non-integer list count type in '" + std::string(line) + "'");
        p.name = std::string(w[4]);
      } else if (w.size() == 3 && TypeNamed(w[1], &p.type)) {
        p.name = std::string(w[2]);
      } else {
        return error("cannot read '" + std::string(line.substr(0, 80)) + "'");
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      // Lines of no keyword are read past as comments: old exporters wrote their name bare
      // ("Created by Blender3D 247").
      ++h.unknown_lines;
    }
  }
  if (!format) return error("no format line");
  h.body = at;
  return h;
}

// Values of a binary body, bounds-checked; false once past the end.
class BinaryCursor {
 public:
  BinaryCursor(const uint8_t* p, const uint8_t* end, bool big_endian)
      : p_(p), end_(end), big_(big_endian) {}
  bool Read(Type t, double* out) {
    const size_t n = SizeOf(t);
    if (static_cast<size_t>(end_ - p_) < n) return false;
    uint8_t b[8];
    std::memcpy(b, p_, n);
    if (big_) std::reverse(b, b + n);
    p_ += n;
    switch (t) {
      case Type::kInt8:
        *out = static_cast<int8_t>(b[0]);
        break;
      case Type::kUint8:
        *out = b[0];
        break;
      case Type::kInt16:
        *out = Load<int16_t>(b);
        break;
      case Type::kUint16:
        *out = Load<uint16_t>(b);
        break;
      case Type::kInt32:
        *out = Load<int32_t>(b);
        break;
      case Type::kUint32:
        *out = Load<uint32_t>(b);
        break;
      case Type::kFloat32:
        *out = Load<float>(b);
        break;
      case Type::kFloat64:
        *out = Load<double>(b);
        break;
    }
    return true;
  }
  size_t left() const { return static_cast<size_t>(end_ - p_); }
  std::string Where() const { return "truncated file"; }

 private:
  template <typename T>
  static T Load(const uint8_t* b) {  // the bytes are in this host's (little-endian) order now
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }
  const uint8_t* p_;
  const uint8_t* end_;
  bool big_;
};

// Values of an ASCII body, separated by any white space.
class AsciiCursor {
 public:
  AsciiCursor(const char* p, const char* end, size_t first_line) : s_(p, end, first_line) {}
  bool Read(Type t, double* out) {
    s_.SkipWhitespace(false);
    if (!s_.ParseDouble(out)) return false;
    return IsFloat(t) || *out == std::floor(*out);  // an integer may be written "3.0"
  }
  size_t left() const { return 0; }
  std::string Where() const { return "line " + std::to_string(s_.line()); }

 private:
  TextScanner s_;
};

// `v` as a float: beyond the float range it is an infinity (which the mesh checks then report), not
// the undefined conversion.
float ToFloat(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

// An index read from the file, for a message: any double, integral or not, huge or not.
std::string IndexText(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.15g", v);
  return text;
}

std::string Join(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

// Where each vertex property goes.
enum Slot { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kRed, kGreen, kBlue, kAlpha, kSlots, kNone };

Slot SlotOf(const std::string& n) {
  static const std::pair<const char*, Slot> kNames[] = {{"x", kX},
                                                        {"y", kY},
                                                        {"z", kZ},
                                                        {"nx", kNx},
                                                        {"ny", kNy},
                                                        {"nz", kNz},
                                                        {"s", kU},
                                                        {"t", kV},
                                                        {"u", kU},
                                                        {"v", kV},
                                                        {"texture_u", kU},
                                                        {"texture_v", kV},
                                                        {"texture_s", kU},
                                                        {"texture_t", kV},
                                                        {"red", kRed},
                                                        {"green", kGreen},
                                                        {"blue", kBlue},
                                                        {"alpha", kAlpha},
                                                        {"diffuse_red", kRed},
                                                        {"diffuse_green", kGreen},
                                                        {"diffuse_blue", kBlue}};
  for (const auto& [name, slot] : kNames) {
    if (n == name) return slot;
  }
  return kNone;
}

// A colour channel's value in 0..1: integers span their type's range, floats are kept.
double ColorUnit(Type t, double v) {
  switch (t) {
    case Type::kUint8:
    case Type::kInt8:
      return v / 255.0;
    case Type::kUint16:
    case Type::kInt16:
      return v / 65535.0;
    case Type::kFloat32:
    case Type::kFloat64:
      return v;
    default:
      return v / 255.0;
  }
}

// `mesh` with a vertex per triangle corner, each with its corner's texture coordinates (`uvs`, two
// per corner) and its vertex's other attributes.
Mesh SplitCorners(Mesh mesh, std::vector<float> uvs) {
  Mesh out;
  const size_t corners = mesh.indices.size();
  out.positions.resize(3 * corners);
  if (!mesh.normals.empty()) out.normals.resize(3 * corners);
  if (!mesh.colors.empty()) out.colors.resize(4 * corners);
  for (size_t i = 0; i < corners; ++i) {
    const size_t v = mesh.indices[i];
    std::copy_n(&mesh.positions[3 * v], 3, &out.positions[3 * i]);
    if (!mesh.normals.empty()) std::copy_n(&mesh.normals[3 * v], 3, &out.normals[3 * i]);
    if (!mesh.colors.empty()) std::copy_n(&mesh.colors[4 * v], 4, &out.colors[4 * i]);
    out.indices.push_back(static_cast<uint32_t>(i));
  }
  out.uv_sets.assign(1, std::move(uvs));
  return out;
}

template <typename Cursor>
Result<Scene> ReadBody(Cursor& c, const Header& h, size_t body_bytes, const std::string& name) {
  Scene scene;
  Mesh mesh;
  auto error = [&](const std::string& what) {
    return Status(StatusCode::kParseError, name + ": " + what);
  };
  const bool binary = h.encoding != Encoding::kAscii;
  std::vector<std::string> not_kept;
  bool have_vertices = false, have_faces = false;
  size_t nv = 0, short_faces = 0;
  std::vector<uint32_t> polygon;
  std::vector<float> corner_uvs;  // one face's texcoord list
  std::vector<float> wedge_uvs;   // per triangle corner, when the faces carry texcoord lists
  size_t faces_without_uvs = 0;
  for (const Element& e : h.elements) {
    // Each record takes at least this many bytes: bound every allocation by the file.
    size_t least = 0;
    for (const Property& p : e.properties)
      least += binary ? SizeOf(p.list ? p.count_type : p.type) : 2;
    if (least > 0 && e.count > body_bytes / least) {
      return error("element '" + e.name + "': " + std::to_string(e.count) +
                   " records do not fit in the " + std::to_string(body_bytes) +
                   " bytes after the header");
    }
    const bool vertices = e.name == "vertex" && !have_vertices;
    const bool faces = e.name == "face" && !have_faces;
    std::vector<Slot> slots(e.properties.size(), kNone);
    int face_list = -1, face_uvs = -1;
    bool has[kSlots] = {};
    std::vector<std::string> skipped;
    for (size_t k = 0; k < e.properties.size(); ++k) {
      const Property& p = e.properties[k];
      if (vertices && !p.list) slots[k] = SlotOf(p.name);
      if (faces && p.list && face_list < 0 &&
          (p.name == "vertex_indices" || p.name == "vertex_index") && !IsFloat(p.type))
        face_list = static_cast<int>(k);
      if (faces && p.list && face_uvs < 0 && p.name == "texcoord" && IsFloat(p.type))
        face_uvs = static_cast<int>(k);
      if (slots[k] != kNone) {
        if (has[slots[k]])
          slots[k] = kNone;  // a second property of one meaning: the first counts
        else
          has[slots[k]] = true;
      }
      if ((vertices || faces) && slots[k] == kNone && static_cast<int>(k) != face_list &&
          static_cast<int>(k) != face_uvs)
        skipped.push_back(p.name);
    }
    if (vertices) {
      if (!has[kX] || !has[kY] || !has[kZ])
        return error("element 'vertex' has no x, y and z properties");
      if (e.count > std::numeric_limits<uint32_t>::max())
        return error("more than 2^32 - 1 vertices");
      nv = static_cast<size_t>(e.count);
      mesh.positions.assign(3 * nv, 0.0f);
      if (has[kNx] && has[kNy] && has[kNz]) mesh.normals.assign(3 * nv, 0.0f);
      if (has[kU] && has[kV]) mesh.uv_sets.assign(1, std::vector<float>(2 * nv, 0.0f));
      if (has[kRed] && has[kGreen] && has[kBlue]) mesh.colors.assign(4 * nv, 1.0f);
      have_vertices = true;
      if (!skipped.empty()) not_kept.push_back("vertex properties not kept: " + Join(skipped));
    } else if (faces) {
      if (face_list < 0) return error("element 'face' has no vertex_indices list");
      if (!have_vertices) return error("element 'face' comes before element 'vertex'");
      // As many triangles as the bytes left can hold (a triangle's record takes at least its count
      // and three indices); a polygon of many corners grows the array as it is read.
      const Property& corners = e.properties[static_cast<size_t>(face_list)];
      const size_t per_triangle =
          binary ? SizeOf(corners.count_type) + 3 * SizeOf(corners.type) : 8;
      mesh.indices.reserve(
          3 * std::min<size_t>(static_cast<size_t>(e.count), body_bytes / per_triangle));
      have_faces = true;
      if (!skipped.empty()) not_kept.push_back("face properties not kept: " + Join(skipped));
    } else if (e.count > 0) {
      not_kept.push_back(std::to_string(e.count) + " '" + e.name + "' records not kept");
    }
    if (e.properties.empty()) continue;  // nothing to read, however many records
    for (uint64_t r = 0; r < e.count; ++r) {
      polygon.clear();
      corner_uvs.clear();
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        double v = 0;
        if (!p.list) {
          if (!c.Read(p.type, &v))
            return error("element '" + e.name + "' record " + std::to_string(r) + " of " +
                         std::to_string(e.count) + ": '" + p.name + "' is malformed or missing (" +
                         c.Where() + ")");
          if (!vertices || slots[k] == kNone) continue;
          const size_t i = static_cast<size_t>(r);
          const Slot s = slots[k];
          if (s <= kZ) {
            mesh.positions[3 * i + s] = ToFloat(v);
          } else if (s <= kNz) {
            if (!mesh.normals.empty()) mesh.normals[3 * i + (s - kNx)] = ToFloat(v);
          } else if (s <= kV) {
            // PLY's t is up (as in OBJ); the scene model's v is down (as in glTF).
            if (!mesh.uv_sets.empty())
              mesh.uv_sets[0][2 * i + (s - kU)] = ToFloat(s == kV ? 1.0 - v : v);
          } else if (!mesh.colors.empty()) {
            mesh.colors[4 * i + (s - kRed)] = ToFloat(ColorUnit(p.type, v));
          }
          continue;
        }
        double count = 0;
        if (!c.Read(p.count_type, &count) || count < 0)
          return error("element '" + e.name + "' record " + std::to_string(r) + ": list '" +
                       p.name + "' has a malformed length (" + c.Where() + ")");
        if (binary && count * static_cast<double>(SizeOf(p.type)) > static_cast<double>(c.left()))
          return error("element '" + e.name + "' record " + std::to_string(r) + ": list '" +
                       p.name + "' runs past the end of the file");
        const bool corners = faces && static_cast<int>(k) == face_list;
        const bool uvs = faces && static_cast<int>(k) == face_uvs;
        for (double j = 0; j < count; ++j) {
          if (!c.Read(p.type, &v))
            return error("element '" + e.name + "' record " + std::to_string(r) + ": list '" +
                         p.name + "' is truncated (" + c.Where() + ")");
          if (uvs) corner_uvs.push_back(ToFloat(v));
          if (!corners) continue;
          if (!(v >= 0 && v < static_cast<double>(nv)))
            return error("face " + std::to_string(r) + " refers to vertex " + IndexText(v) +
                         " of " + std::to_string(nv));
          polygon.push_back(static_cast<uint32_t>(v));
        }
      }
      if (!faces) continue;
      if (polygon.size() < 3) {
        ++short_faces;
        continue;
      }
      const bool corner_uvs_fit = corner_uvs.size() == 2 * polygon.size();
      if (face_uvs >= 0 && !corner_uvs_fit) ++faces_without_uvs;
      for (size_t j = 1; j + 1 < polygon.size(); ++j) {
        mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[j], polygon[j + 1]});
        if (face_uvs < 0) continue;
        for (size_t corner : {size_t{0}, j, j + 1}) {
          wedge_uvs.push_back(corner_uvs_fit ? corner_uvs[2 * corner] : 0.0f);
          wedge_uvs.push_back(corner_uvs_fit ? 1.0f - corner_uvs[2 * corner + 1] : 0.0f);
        }
      }
    }
  }
  if (!have_vertices) return error("no 'vertex' element");
  if (short_faces > 0)
    not_kept.push_back(std::to_string(short_faces) + " faces with fewer than 3 corners not kept");
  if (h.unknown_lines > 0)
    not_kept.push_back(std::to_string(h.unknown_lines) +
                       " header lines of no PLY keyword read past as comments");
  if (!wedge_uvs.empty()) {
    // Texture coordinates per face corner (MeshLab's wedge texcoords): a vertex per corner, which
    // the repairs weld back where the corners agree.
    if (faces_without_uvs > 0)
      not_kept.push_back(std::to_string(faces_without_uvs) +
                         " faces without a texture coordinate per corner: given (0, 1)");
    mesh = SplitCorners(std::move(mesh), std::move(wedge_uvs));
  }
  if (!h.texture_file.empty() && !mesh.uv_sets.empty()) {
    // MeshLab's "comment TextureFile": the base colour image of the mesh's one material.
    Image image;
    image.name = h.texture_file;
    image.uri = h.texture_file;
    scene.images.push_back(std::move(image));
    Material material;
    material.name = "texture";
    material.base_color_texture.image = 0;
    scene.materials.push_back(std::move(material));
    mesh.material_ids.assign(mesh.triangle_count(), 0);
  } else if (!h.texture_file.empty()) {
    not_kept.push_back("texture file '" + h.texture_file + "' not kept: no texture coordinates");
  }
  for (std::string& line : not_kept) scene.dropped.push_back(std::move(line));
  scene.source_vertex_records = nv;
  scene.meshes.push_back(std::move(mesh));
  AddRootNodeForAllMeshes(scene, name);
  return scene;
}

}  // namespace

Result<Scene> ParsePly(const uint8_t* data, size_t size, const std::string& name) {
  Result<Header> h = ParseHeader(data, size, name);
  if (!h.ok()) return h.status();
  const size_t body_bytes = size - h->body;
  if (h->encoding == Encoding::kAscii) {
    const char* text = reinterpret_cast<const char*>(data);
    AsciiCursor c(text + h->body, text + size, h->lines + 1);
    return ReadBody(c, h.value(), body_bytes, name);
  }
  BinaryCursor c(data + h->body, data + size, h->encoding == Encoding::kBigEndian);
  return ReadBody(c, h.value(), body_bytes, name);
}

}  // namespace hullpack
