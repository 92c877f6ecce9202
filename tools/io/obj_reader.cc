#include "io/obj_reader.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "common/block_vector.h"
#include "common/buckets.h"
#include "common/parallel.h"
#include "io/text_scanner.h"

namespace hullpack {
namespace {

// One face corner: 0-based indices into the file's v / vt / vn pools; -1 = absent. One per output
// vertex is kept until the end: 32 bits each (pools are limited to kMaxRecords).
struct Corner {
  int32_t v = -1, vt = -1, vn = -1;
  bool operator==(const Corner& o) const { return v == o.v && vt == o.vt && vn == o.vn; }
};

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr size_t kMaxRecords = INT32_MAX;  // v, vt and vn lines each

struct MeshBuilder {
  std::string name;
  // Output vertices by position: first_of_v[v - v_base] is the first vertex made from `v`,
  // next_same_v chains the others (other texture coordinates or normals). Most positions have one
  // or two, so a lookup is a short walk; the index costs 4 bytes per position of the range this
  // mesh uses (an `o` object usually uses its own run of `v` lines) and per vertex.
  std::vector<uint32_t> first_of_v;
  size_t v_base = 0;
  std::vector<uint32_t> next_same_v;
  // Kept in blocks: a large mesh is appended element by element (see BlockVector).
  BlockVector<Corner> corners;  // one per output vertex
  BlockVector<uint32_t> indices;
  std::vector<uint32_t> material_ids;

  // The output vertex of `c`, made on first use (so vertices are numbered in order of first use).
  uint32_t VertexOf(const Corner& c) {
    const size_t v = static_cast<size_t>(c.v);
    if (first_of_v.empty()) v_base = v;
    if (v < v_base) {  // grow downwards, with room for more
      const size_t grow = std::max(v_base - v, first_of_v.size());
      const size_t new_base = v_base > grow ? v_base - grow : 0;
      first_of_v.insert(first_of_v.begin(), v_base - new_base, kNone);
      v_base = new_base;
    }
    const size_t at = v - v_base;
    if (at >= first_of_v.size()) first_of_v.resize(std::max(at + 1, first_of_v.size() * 2), kNone);
    uint32_t* link = &first_of_v[at];
    while (*link != kNone) {
      if (corners[*link] == c) return *link;
      link = &next_same_v[*link];
    }
    const uint32_t id = static_cast<uint32_t>(corners.size());
    *link = id;
    corners.push_back(c);
    next_same_v.push_back(kNone);
    return id;
  }
};

// Statements of the OBJ specification that carry nothing the scene model holds.
bool IsIgnoredStatement(std::string_view k) {
  static const char* const kIgnored[] = {
      "s",     "g",     "vp",       "cstype",   "deg",    "bmat",       "step",      "curv",
      "curv2", "surf",  "parm",     "trim",     "hole",   "scrv",       "sp",        "end",
      "con",   "mg",    "lod",      "usemap",   "maplib", "shadow_obj", "trace_obj", "ctech",
      "stech", "bevel", "c_interp", "d_interp", "call",   "csh"};
  for (const char* s : kIgnored) {
    if (k == s) return true;
  }
  return false;
}

// A face corner as written: raw (1-based or negative) indices; kAbsent when not given.
constexpr int32_t kAbsent = INT32_MIN;

// The numbers of a `v`, `vt` or `vn` line, as ObjParser::ReadNumbers reads them; false where it
// would report an error.
bool ReadLineNumbers(TextScanner& s, double* out, int min_count, int max_count, int* count) {
  *count = 0;
  for (;;) {
    s.SkipBlanks();
    if (s.AtLineEnd()) break;
    double value;
    if (*count == max_count || !s.ParseDouble(&value)) return false;
    out[(*count)++] = value;
  }
  return *count >= min_count;
}

// The corners of an `f` line, as ObjParser::Face reads them, unresolved; false where it would
// report a malformed corner.
// Indices that do not fit 32 bits are left to the sequential pass too.
bool ReadFaceCorners(TextScanner& s, std::vector<int32_t>* raw, uint32_t* corners) {
  *corners = 0;
  for (;;) {
    s.SkipBlanks();
    if (s.AtLineEnd()) return true;
    int64_t v = kAbsent, vt = kAbsent, vn = kAbsent;  // kAbsent widened
    if (!s.ParseInt64(&v)) return false;
    if (s.Consume('/')) {
      if (s.Peek() != '/' && !s.ParseInt64(&vt)) return false;
      if (s.Consume('/') && !s.ParseInt64(&vn)) return false;
    }
    const char next = s.Peek();
    if (next != ' ' && next != '\t' && next != '\r' && next != '\n' && next != '#' && !s.AtEnd())
      return false;
    for (int64_t x : {v, vt, vn}) {
      if (x != kAbsent && (x <= INT32_MIN || x > INT32_MAX)) return false;
      raw->push_back(x == kAbsent ? kAbsent : static_cast<int32_t>(x));
    }
    ++*corners;
  }
}

// Where the text comes from: the caller's memory, or a file read part by part, so that a large
// file is never held whole (its parts are freed once parsed).
struct TextSource {
  const char* data = nullptr;
  const RandomAccessFile* file = nullptr;
  size_t size = 0;
};

// One part of the text (split at line starts), and the numbers of its `v`, `vt`, `vn` and `f`
// lines when they were read ahead on another thread; the sequential pass then takes them in order
// instead of reading the text again. A part with a line the read-ahead would not read as the
// sequential pass does (any malformed line) is left to the sequential pass, which reports the
// error.
struct TextPart {
  size_t offset = 0, length = 0;  // where in the text
  std::vector<char> own;          // the part's bytes, when read from a file
  const char* begin = nullptr;
  const char* end = nullptr;
  Status loaded = Status::Ok();
  bool has_nul = false;
  bool numbers_read = false;
  // The numbers of the v/vt/vn lines, in order: as the floats they become (v, vn), or as read
  // (vt: v is flipped in double first).
  std::vector<float> floats;
  std::vector<double> doubles;
  std::vector<uint8_t> counts;     // numbers per v/vt/vn line
  std::vector<int32_t> corners;    // 3 raw indices per face corner
  std::vector<uint32_t> per_face;  // corners per f line
  size_t next_line = 0, next_float = 0, next_double = 0, next_face = 0, next_corner = 0;

  Status Load(const TextSource& source) {
    if (source.file != nullptr) {
      own.resize(length);
      Status s = source.file->ReadAt(offset, length, own.data());
      if (!s.ok()) return s;
      begin = own.data();
    } else {
      begin = source.data + offset;
    }
    end = begin + length;
    has_nul = std::memchr(begin, '\0', length) != nullptr;
    return Status::Ok();
  }

  void Read() {
    TextScanner s(begin, end);
    bool ok = true;
    while (ok && !s.AtEnd()) {
      s.SkipBlanks();
      if (s.AtLineEnd()) {
        s.SkipLine();
        continue;
      }
      const std::string_view key = s.Word();
      double n[7];
      int count = 0;
      uint32_t face_corners = 0;
      if (key == "v" || key == "vt" || key == "vn") {
        const int lo = key == "vt" ? 1 : 3, hi = key == "v" ? 7 : 3;
        ok = ReadLineNumbers(s, n, lo, hi, &count);
        if (key == "vt") {
          doubles.insert(doubles.end(), n, n + count);
        } else {
          for (int k = 0; k < count; ++k) floats.push_back(static_cast<float>(n[k]));
        }
        counts.push_back(static_cast<uint8_t>(count));
      } else if (key == "f" || key == "fo") {
        ok = ReadFaceCorners(s, &corners, &face_corners);
        per_face.push_back(face_corners);
      }
      s.SkipLine();
    }
    numbers_read = ok;
  }
};

// Texts at least this large are read ahead in parallel.
constexpr size_t kReadAheadBytes = size_t(1) << 20;
// A file is read in parts of at most this size, at most a few per thread at a time.
constexpr size_t kMaxPartBytes = size_t(8) << 20;

class ObjParser {
 public:
  ObjParser(const TextSource& source, const std::string& name, const ObjParseOptions& options)
      : scan_(nullptr, nullptr), source_(source), name_(name), options_(options) {}

  Result<Scene> Parse() {
    const bool read_ahead = source_.size >= kReadAheadBytes && options_.threads != 1;
    Status split = SplitIntoParts(read_ahead ? ThreadCount(options_.threads) : 1);
    if (!split.ok()) return split;
    builders_.emplace_back();
    if (read_ahead) StartReadAhead();
    // Progress about every 1 % of the text (checked every 4096 lines).
    const size_t step = std::max<size_t>(source_.size / 100, 1);
    size_t lines = 0, reported = 0, first_line = 1;
    for (size_t k = 0; k < parts_.size(); ++k) {
      TextPart& part = parts_[k];
      if (readers_.empty()) {
        part.loaded = part.Load(source_);
      } else {
        WaitUntilRead(k);
      }
      if (!part.loaded.ok()) return part.loaded;
      scan_ = TextScanner(part.begin, part.end, first_line);
      // Not tied to a line: the same error wherever in the text the byte is.
      if (part.has_nul)
        return Status(StatusCode::kParseError, name_ + ": binary data (NUL byte): not an OBJ file");
      ahead_ = part.numbers_read ? &part : nullptr;
      while (!scan_.AtEnd()) {
        if (options_.progress && (++lines & 4095) == 0) {
          const size_t at = part.offset + static_cast<size_t>(scan_.position() - part.begin);
          if (at >= reported + step) {
            reported = at;
            options_.progress(static_cast<double>(at) / static_cast<double>(source_.size));
          }
        }
        scan_.SkipBlanks();
        if (scan_.AtLineEnd()) {
          scan_.SkipLine();
          continue;
        }
        const std::string_view key = scan_.Word();
        Status s = Statement(key);
        if (!s.ok()) return s;
        scan_.SkipLine();
      }
      first_line = scan_.line();
      ahead_ = nullptr;
      part = TextPart();  // its text and numbers are no longer needed
      std::lock_guard<std::mutex> lock(ready_mutex_);
      consumed_ = k + 1;
      ready_changed_.notify_all();
    }
    StopReadAhead();
    parts_.clear();
    return Finish();
  }
  ~ObjParser() { StopReadAhead(); }

 private:
  // Splits the text at line starts: a few parts per reading thread, and a file into parts of at
  // most kMaxPartBytes (never held whole).
  Status SplitIntoParts(int threads) {
    const size_t size = source_.size;
    size_t count = threads > 1 ? static_cast<size_t>(threads) * 16 : 1;
    if (source_.file != nullptr)
      count = std::max(count, (size + kMaxPartBytes - 1) / kMaxPartBytes);
    size_t begin = 0;
    for (size_t k = 0; k < count && begin < size; ++k) {
      size_t stop = k + 1 == count ? size : std::max(begin, size * (k + 1) / count);
      Status s = LineStartAtOrAfter(&stop);
      if (!s.ok()) return s;
      parts_.emplace_back();
      parts_.back().offset = begin;
      parts_.back().length = stop - begin;
      begin = stop;
    }
    ready_.assign(parts_.size(), 0);
    return Status::Ok();
  }

  // Moves *at to just past the first newline at or after it (or to the end of the text).
  Status LineStartAtOrAfter(size_t* at) const {
    const size_t size = source_.size;
    if (source_.file == nullptr) {
      const void* nl = std::memchr(source_.data + *at, '\n', size - *at);
      *at = nl ? static_cast<size_t>(static_cast<const char*>(nl) - source_.data) + 1 : size;
      return Status::Ok();
    }
    char window[4096];
    while (*at < size) {
      const size_t n = std::min(sizeof(window), size - *at);
      Status s = source_.file->ReadAt(*at, n, window);
      if (!s.ok()) return s;
      if (const void* nl = std::memchr(window, '\n', n)) {
        *at += static_cast<size_t>(static_cast<const char*>(nl) - window) + 1;
        return Status::Ok();
      }
      *at += n;
    }
    return Status::Ok();
  }

  // Starts reading the parts and their numbers ahead, in order, at most a few parts ahead of the
  // sequential pass (their text and numbers take memory).
  void StartReadAhead() {
    const int threads = ThreadCount(options_.threads);
    const size_t window = 2 * static_cast<size_t>(threads);
    for (int t = 0; t < threads; ++t) {
      readers_.emplace_back([this, window] {
        for (size_t k; (k = next_to_read_.fetch_add(1)) < parts_.size();) {
          {
            std::unique_lock<std::mutex> lock(ready_mutex_);
            ready_changed_.wait(lock, [&] { return stopping_ || k < consumed_ + window; });
            if (stopping_) return;
          }
          TextPart& part = parts_[k];
          part.loaded = part.Load(source_);
          if (part.loaded.ok()) part.Read();
          std::lock_guard<std::mutex> lock(ready_mutex_);
          ready_[k] = 1;
          ready_changed_.notify_all();
        }
      });
    }
  }

  void StopReadAhead() {
    {
      std::lock_guard<std::mutex> lock(ready_mutex_);
      stopping_ = true;
      ready_changed_.notify_all();
    }
    for (std::thread& t : readers_) t.join();
    readers_.clear();
  }

  void WaitUntilRead(size_t part) {
    std::unique_lock<std::mutex> lock(ready_mutex_);
    ready_changed_.wait(lock, [&] { return ready_[part] != 0; });
  }

  // The next read-ahead v/vt/vn line's numbers.
  int TakeNumbers(TextPart& a, bool as_double, double* out) {
    const int count = a.counts[a.next_line++];
    for (int k = 0; k < count; ++k)
      out[k] = as_double ? a.doubles[a.next_double++] : a.floats[a.next_float++];
    scan_.SkipToLineEnd();
    return count;
  }

  Status Error(const std::string& what) const {
    return Status(StatusCode::kParseError,
                  name_ + ": line " + std::to_string(scan_.line()) + ": " + what);
  }

  Status ReadNumbers(double* out, int min_count, int max_count, int* count, const char* what) {
    *count = 0;
    for (;;) {
      scan_.SkipBlanks();
      if (scan_.AtLineEnd()) break;
      double value;
      if (*count == max_count || !scan_.ParseDouble(&value)) {
        return Error(std::string("malformed ") + what + " (expected " + std::to_string(min_count) +
                     (min_count == max_count ? "" : " to " + std::to_string(max_count)) +
                     " numbers)");
      }
      out[(*count)++] = value;
    }
    if (*count < min_count)
      return Error(std::string(what) + " needs at least " + std::to_string(min_count) + " numbers");
    return Status::Ok();
  }

  Status Statement(std::string_view key) {
    double n[7];
    int count = 0;
    TextPart* const ahead = ahead_;  // read ahead; only v, vt, vn, f and fo lines take from it
    // Corners index the pools in 32 bits.
    auto too_many = [&](const char* what) {
      return Error("more than " + std::to_string(kMaxRecords) + " '" + what + "' lines");
    };
    if (key == "v") {
      if (positions_.size() == kMaxRecords) return too_many("v");
      if (ahead) {
        count = TakeNumbers(*ahead, false, n);
      } else {
        Status s = ReadNumbers(n, 3, 7, &count, "vertex");
        if (!s.ok()) return s;
      }
      positions_.push_back({float(n[0]), float(n[1]), float(n[2])});
      if (count >= 6) {  // `v x y z r g b`; a 4-number line is `v x y z w`
        if (colors_.empty() && positions_.size() > 1)
          colors_.resize(positions_.size() - 1, {1, 1, 1});
        colors_.push_back({float(n[3]), float(n[4]), float(n[5])});
      } else if (!colors_.empty()) {
        colors_.push_back({1, 1, 1});
      }
      return Status::Ok();
    }
    if (key == "vt") {
      if (texcoords_.size() == kMaxRecords) return too_many("vt");
      if (ahead) {
        count = TakeNumbers(*ahead, true, n);
      } else {
        Status s = ReadNumbers(n, 1, 3, &count, "texture coordinate");
        if (!s.ok()) return s;
      }
      texcoords_.push_back({n[0], count > 1 ? n[1] : 0.0});
      return Status::Ok();
    }
    if (key == "vn") {
      if (normals_.size() == kMaxRecords) return too_many("vn");
      if (ahead) {
        count = TakeNumbers(*ahead, false, n);
      } else {
        Status s = ReadNumbers(n, 3, 3, &count, "normal");
        if (!s.ok()) return s;
      }
      normals_.push_back({float(n[0]), float(n[1]), float(n[2])});
      return Status::Ok();
    }
    if (key == "f" || key == "fo") return ahead ? FaceReadAhead(*ahead) : Face();
    if (key == "o") {
      StartMesh(std::string(scan_.RestOfLine()));
      return Status::Ok();
    }
    if (key == "usemtl") {
      current_material_ = MaterialIndex(std::string(scan_.RestOfLine()));
      return Status::Ok();
    }
    if (key == "mtllib") return MaterialLibraries(scan_.RestOfLine());
    if (key == "l") {
      ++dropped_lines_;
      return Status::Ok();
    }
    if (key == "p") {
      ++dropped_points_;
      return Status::Ok();
    }
    if (IsIgnoredStatement(key)) return Status::Ok();
    std::string shown(key.substr(0, 32));
    for (char& c : shown) {
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    }
    return Error("unknown statement '" + shown + "'");
  }

  void StartMesh(std::string mesh_name) {
    if (builders_.back().indices.empty() && builders_.back().corners.empty()) {
      builders_.back().name = std::move(mesh_name);
      return;
    }
    builders_.emplace_back();
    builders_.back().name = std::move(mesh_name);
  }

  // Resolves a 1-based or negative OBJ index against a pool of `pool_size` entries.
  bool Resolve(int64_t raw, size_t pool_size, int32_t* out) const {
    const int64_t size = static_cast<int64_t>(pool_size);
    if (raw > 0 && raw <= size) {
      *out = static_cast<int32_t>(raw - 1);
      return true;
    }
    if (raw < 0 && -raw <= size) {
      *out = static_cast<int32_t>(size + raw);
      return true;
    }
    return false;
  }

  Status ParseCorner(Corner* c) {
    int64_t raw;
    if (!scan_.ParseInt64(&raw)) return Error("malformed face corner");
    if (!Resolve(raw, positions_.size(), &c->v)) {
      return Error("face refers to vertex " + std::to_string(raw) + " but only " +
                   std::to_string(positions_.size()) + " are defined");
    }
    if (!scan_.Consume('/')) return Status::Ok();
    if (scan_.Peek() != '/') {
      if (!scan_.ParseInt64(&raw)) return Error("malformed texture index in face corner");
      if (!Resolve(raw, texcoords_.size(), &c->vt)) {
        return Error("face refers to texture coordinate " + std::to_string(raw) + " but only " +
                     std::to_string(texcoords_.size()) + " are defined");
      }
    }
    if (!scan_.Consume('/')) return Status::Ok();
    if (!scan_.ParseInt64(&raw)) return Error("malformed normal index in face corner");
    if (!Resolve(raw, normals_.size(), &c->vn)) {
      return Error("face refers to normal " + std::to_string(raw) + " but only " +
                   std::to_string(normals_.size()) + " are defined");
    }
    return Status::Ok();
  }

  Status Face() {
    polygon_.clear();
    for (;;) {
      scan_.SkipBlanks();
      if (scan_.AtLineEnd()) break;
      Corner c;
      Status s = ParseCorner(&c);
      if (!s.ok()) return s;
      const char next = scan_.Peek();
      if (next != ' ' && next != '\t' && next != '\r' && next != '\n' && next != '#' &&
          !scan_.AtEnd()) {
        return Error("malformed face corner");
      }
      polygon_.push_back(c);
    }
    return AddPolygon();
  }

  // The next read-ahead face, its indices resolved as ParseCorner resolves them.
  Status FaceReadAhead(TextPart& a) {
    polygon_.clear();
    const uint32_t n = a.per_face[a.next_face++];
    for (uint32_t k = 0; k < n; ++k) {
      const int32_t* raw = &a.corners[(a.next_corner++) * 3];
      Corner c;
      if (!Resolve(raw[0], positions_.size(), &c.v)) {
        return Error("face refers to vertex " + std::to_string(raw[0]) + " but only " +
                     std::to_string(positions_.size()) + " are defined");
      }
      if (raw[1] != kAbsent && !Resolve(raw[1], texcoords_.size(), &c.vt)) {
        return Error("face refers to texture coordinate " + std::to_string(raw[1]) + " but only " +
                     std::to_string(texcoords_.size()) + " are defined");
      }
      if (raw[2] != kAbsent && !Resolve(raw[2], normals_.size(), &c.vn)) {
        return Error("face refers to normal " + std::to_string(raw[2]) + " but only " +
                     std::to_string(normals_.size()) + " are defined");
      }
      polygon_.push_back(c);
    }
    scan_.SkipToLineEnd();
    return AddPolygon();
  }

  // polygon_, fan-triangulated into the current mesh.
  Status AddPolygon() {
    if (polygon_.size() < 3) {
      ++dropped_short_faces_;
      return Status::Ok();
    }
    MeshBuilder& b = builders_.back();
    uint32_t ids[3];
    auto vertex = [&](const Corner& c) { return b.VertexOf(c); };
    ids[0] = vertex(polygon_[0]);
    for (size_t i = 1; i + 1 < polygon_.size(); ++i) {  // fan triangulation
      ids[1] = vertex(polygon_[i]);
      ids[2] = vertex(polygon_[i + 1]);
      for (const uint32_t id : ids) b.indices.push_back(id);
      // Material ids only once a `usemtl` was seen (most large scans have none); the faces
      // before it get kNoMaterial then.
      if (current_material_ != kNoMaterial || !b.material_ids.empty()) {
        b.material_ids.resize(b.indices.size() / 3 - 1, kNoMaterial);
        b.material_ids.push_back(current_material_);
      }
    }
    if (polygon_.size() > 3) ++polygons_triangulated_;
    return Status::Ok();
  }

  uint32_t MaterialIndex(const std::string& material_name) {
    auto it = material_index_.find(material_name);
    if (it != material_index_.end()) return it->second;
    const uint32_t id = static_cast<uint32_t>(materials_.size());
    Material m;
    m.name = material_name;
    materials_.push_back(m);
    material_index_.emplace(material_name, id);
    return id;
  }

  Status MaterialLibraries(std::string_view names) {
    // Several libraries may be named on one line.
    size_t pos = 0;
    while (pos < names.size()) {
      while (pos < names.size() && (names[pos] == ' ' || names[pos] == '\t')) ++pos;
      size_t end = pos;
      while (end < names.size() && names[end] != ' ' && names[end] != '\t') ++end;
      if (end > pos) {
        const std::string lib(names.substr(pos, end - pos));
        if (!options_.load_material_library) {
          dropped_.push_back("material library '" + lib + "' not read (no file access)");
        } else {
          Result<std::string> text = options_.load_material_library(lib);
          if (!text.ok()) {
            dropped_.push_back("material library '" + lib +
                               "' not found: material colours and textures not kept");
          } else {
            ParseMtl(text.value());
          }
        }
      }
      pos = end;
    }
    return Status::Ok();
  }

  int ImageIndex(const std::string& uri) {
    for (size_t i = 0; i < images_.size(); ++i) {
      if (images_[i].uri == uri) return static_cast<int>(i);
    }
    Image image;
    image.uri = uri;
    image.name = uri;
    images_.push_back(image);
    return static_cast<int>(images_.size() - 1);
  }

  // A partly transparent material blends. An opacity of 0 is taken as opaque: exporters that write
  // `Tr` with the meaning of `d` write 0 for opaque, and a material nobody can see is never meant.
  static void SetOpacity(Material& m, double opacity) {
    const bool partial = opacity > 0 && opacity < 1;
    m.base_color[3] = partial ? static_cast<float>(opacity) : 1.0f;
    m.alpha_mode = partial ? AlphaMode::kBlend : AlphaMode::kOpaque;
  }

  // MTL is parsed leniently: what it cannot understand it skips (materials are optional data).
  void ParseMtl(const std::string& text) {
    TextScanner s(text.data(), text.data() + text.size());
    Material* current = nullptr;
    while (!s.AtEnd()) {
      s.SkipBlanks();
      if (s.AtLineEnd()) {
        s.SkipLine();
        continue;
      }
      const std::string_view key = s.Word();
      double v[3];
      auto numbers = [&](int n) {
        for (int i = 0; i < n; ++i) {
          s.SkipBlanks();
          if (!s.ParseDouble(&v[i])) return false;
        }
        return true;
      };
      if (key == "newmtl") {
        current = &materials_[MaterialIndex(std::string(s.RestOfLine()))];
      } else if (current && key == "Kd" && numbers(3)) {
        for (int i = 0; i < 3; ++i) current->base_color[i] = static_cast<float>(v[i]);
      } else if (current && key == "Ke" && numbers(3)) {
        for (int i = 0; i < 3; ++i) current->emissive[i] = static_cast<float>(v[i]);
      } else if (current && key == "d" && numbers(1)) {
        SetOpacity(*current, v[0]);
      } else if (current && key == "Tr" && numbers(1)) {
        SetOpacity(*current, 1.0 - v[0]);
      } else if (current &&
                 (key == "map_Kd" || key == "map_Bump" || key == "bump" || key == "norm")) {
        // The file name is the last word; options such as `-bm 1` come before it.
        std::string_view rest = s.RestOfLine();
        const size_t space = rest.find_last_of(" \t");
        const std::string file(space == std::string_view::npos ? rest : rest.substr(space + 1));
        if (!file.empty()) {
          TextureRef& slot =
              key == "map_Kd" ? current->base_color_texture : current->normal_texture;
          slot.image = ImageIndex(file);
        }
      }
      s.SkipLine();
    }
  }

  Result<Scene> Finish() {
    Scene scene;
    scene.materials = std::move(materials_);
    scene.images = std::move(images_);
    scene.source_vertex_records = positions_.size();
    std::vector<uint8_t> referenced(positions_.size(), 0);
    size_t missing_uv = 0, missing_normal = 0;
    for (MeshBuilder& b : builders_) {
      if (b.indices.empty()) continue;
      b.first_of_v = std::vector<uint32_t>();
      b.next_same_v = std::vector<uint32_t>();
      const std::vector<uint32_t> order = KeepFileOrder(b);
      Mesh m;
      m.name = b.name;
      m.indices = b.indices.TakeAll();  // before the vertex arrays: the blocks are freed first
      const size_t n = order.size();
      bool has_uv = false, has_normal = false;
      for (const uint32_t id : order) {
        const Corner& c = b.corners[id];
        has_uv |= c.vt >= 0;
        has_normal |= c.vn >= 0;
      }
      m.positions.resize(n * 3);
      if (has_uv) m.uv_sets.emplace_back(n * 2, 0.0f);
      if (has_normal) m.normals.resize(n * 3, 0.0f);
      if (!colors_.empty()) m.colors.resize(n * 4, 1.0f);
      std::vector<uint8_t> lacks_normal;
      for (size_t i = 0; i < n; ++i) {
        const Corner& c = b.corners[order[i]];
        referenced[static_cast<size_t>(c.v)] = 1;
        for (int k = 0; k < 3; ++k) m.positions[i * 3 + k] = static_cast<float>(positions_[c.v][k]);
        if (!colors_.empty()) {
          for (int k = 0; k < 3; ++k) m.colors[i * 4 + k] = static_cast<float>(colors_[c.v][k]);
        }
        if (has_uv) {
          if (c.vt >= 0) {
            m.uv_sets[0][i * 2] = static_cast<float>(texcoords_[c.vt][0]);
            m.uv_sets[0][i * 2 + 1] = static_cast<float>(1.0 - texcoords_[c.vt][1]);
          } else {
            ++missing_uv;
          }
        }
        if (has_normal) {
          if (c.vn >= 0) {
            for (int k = 0; k < 3; ++k)
              m.normals[i * 3 + k] = static_cast<float>(normals_[c.vn][k]);
          } else {
            if (lacks_normal.empty()) lacks_normal.resize(n, 0);
            lacks_normal[i] = 1;
            ++missing_normal;
          }
        }
      }
      if (!lacks_normal.empty()) FillNormalsFromFaces(m, lacks_normal);
      b.corners = BlockVector<Corner>();
      // Grown face by face: down to their size, the mesh lives through the whole pipeline.
      m.material_ids = std::move(b.material_ids);
      m.material_ids.shrink_to_fit();
      scene.meshes.push_back(std::move(m));
    }
    // Faces before the first `usemtl` carry kNoMaterial: without any material in the file the ids
    // say nothing and are dropped; otherwise those faces get a material of their own.
    const bool file_has_materials = !scene.materials.empty();
    uint32_t fallback = kNoMaterial;
    for (Mesh& m : scene.meshes) {
      if (!file_has_materials) {
        m.material_ids = std::vector<uint32_t>();
        continue;
      }
      m.material_ids.resize(m.triangle_count(), kNoMaterial);
      for (uint32_t& id : m.material_ids) {
        if (id != kNoMaterial) continue;
        if (fallback == kNoMaterial) {
          fallback = static_cast<uint32_t>(scene.materials.size());
          Material none;
          none.name = "(no material)";
          scene.materials.push_back(none);
        }
        id = fallback;
      }
    }
    size_t unreferenced = 0;
    for (uint8_t r : referenced) unreferenced += r == 0;
    auto note = [&](size_t count, const std::string& what) {
      if (count) scene.dropped.push_back(std::to_string(count) + " " + what);
    };
    note(unreferenced, "unreferenced vertices not kept");
    note(dropped_lines_, "line elements (`l`) not kept: meshes hold triangles only");
    note(dropped_points_, "point elements (`p`) not kept: meshes hold triangles only");
    note(dropped_short_faces_, "faces with fewer than 3 corners not kept");
    note(missing_uv, "face corners without a texture coordinate given (0, 0)");
    note(missing_normal, "face corners without a normal given the area-weighted face normal");
    for (std::string& d : dropped_) scene.dropped.push_back(std::move(d));
    AddRootNodeForAllMeshes(scene, name_);
    return scene;
  }

  // Vertices were numbered in order of first use; renumber them in the order of their (v, vt, vn)
  // triples so that a file's vertex order survives (a positions-only file keeps its `v` order):
  // returns the corner ids in that order and renumbers b.indices. Corners are distinct, so the
  // order is total. A mesh usually uses its own run of `v` lines: then its corners are bucketed by
  // v (a position has one corner, or a few with other texture coordinates or normals) and each
  // bucket sorted by (vt, vn); a mesh whose positions are spread over the file is sorted whole.
  static std::vector<uint32_t> KeepFileOrder(MeshBuilder& b) {
    const size_t n = b.corners.size();
    std::vector<uint32_t> order;
    auto less = [&b](uint32_t x, uint32_t y) {
      const Corner& a = b.corners[x];
      const Corner& c = b.corners[y];
      if (a.v != c.v) return a.v < c.v;
      if (a.vt != c.vt) return a.vt < c.vt;
      return a.vn != c.vn ? a.vn < c.vn : x < y;
    };
    int32_t lo = INT32_MAX, hi = 0;
    for (size_t i = 0; i < n; ++i) {
      lo = std::min(lo, b.corners[i].v);
      hi = std::max(hi, b.corners[i].v);
    }
    const size_t range = n == 0 ? 0 : static_cast<size_t>(hi - lo) + 1;
    if (range > 2 * n + 1024) {
      order.resize(n);
      for (uint32_t i = 0; i < n; ++i) order[i] = i;
      std::sort(order.begin(), order.end(), less);
    } else {
      Buckets by_v =
          BucketBy(n, range, [&](size_t i) { return static_cast<uint32_t>(b.corners[i].v - lo); });
      order = std::move(by_v.ids);
      for (size_t v = 0; v < range; ++v) {
        const uint32_t first = by_v.start[v], last = by_v.start[v + 1];
        if (last - first < 2) continue;
        std::sort(order.begin() + first, order.begin() + last, less);
      }
    }
    std::vector<uint32_t> new_index(n);
    for (uint32_t i = 0; i < n; ++i) new_index[order[i]] = i;
    b.indices.ForEach([&](uint32_t& index) { index = new_index[index]; });
    return order;
  }

  static void FillNormalsFromFaces(Mesh& m, const std::vector<uint8_t>& lacks_normal) {
    std::vector<double> acc(m.normals.size(), 0.0);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const float* a = &m.positions[m.indices[t] * 3];
      const float* b = &m.positions[m.indices[t + 1] * 3];
      const float* c = &m.positions[m.indices[t + 2] * 3];
      const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
      const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
      for (int k = 0; k < 3; ++k) {
        for (int j = 0; j < 3; ++j) acc[m.indices[t + k] * 3 + j] += n[j];
      }
    }
    for (size_t i = 0; i < lacks_normal.size(); ++i) {
      if (!lacks_normal[i]) continue;
      const double len = std::sqrt(acc[i * 3] * acc[i * 3] + acc[i * 3 + 1] * acc[i * 3 + 1] +
                                   acc[i * 3 + 2] * acc[i * 3 + 2]);
      for (int j = 0; j < 3; ++j) {
        m.normals[i * 3 + j] = len > 0 && std::isfinite(len)
                                   ? static_cast<float>(acc[i * 3 + j] / len)
                                   : (j == 2 ? 1.0f : 0.0f);
      }
    }
  }

  TextScanner scan_;
  std::vector<TextPart> parts_;
  TextPart* ahead_ = nullptr;  // the part being parsed, when its numbers were read ahead
  std::vector<std::thread> readers_;
  std::atomic<size_t> next_to_read_{0};
  // Guarded by ready_mutex_: per part, read; the parts the sequential pass is done with; stop.
  std::vector<char> ready_;
  size_t consumed_ = 0;
  bool stopping_ = false;
  std::mutex ready_mutex_;
  std::condition_variable ready_changed_;
  const TextSource source_;
  const std::string& name_;
  const ObjParseOptions& options_;
  // Kept as the floats the meshes get (texture coordinates stay double: v is flipped first).
  BlockVector<std::array<float, 3>> positions_, normals_;
  std::vector<std::array<float, 3>> colors_;
  BlockVector<std::array<double, 2>> texcoords_;
  std::vector<MeshBuilder> builders_;
  std::vector<Corner> polygon_;
  std::vector<Material> materials_;
  std::unordered_map<std::string, uint32_t> material_index_;
  std::vector<Image> images_;
  static constexpr uint32_t kNoMaterial = 0xFFFFFFFFu;
  uint32_t current_material_ = kNoMaterial;
  size_t dropped_lines_ = 0, dropped_points_ = 0, dropped_short_faces_ = 0,
         polygons_triangulated_ = 0;
  std::vector<std::string> dropped_;
};

}  // namespace

Result<Scene> ParseObj(const char* data, size_t size, const std::string& name,
                       const ObjParseOptions& options) {
  TextSource source;
  source.data = data;
  source.size = size;
  return ObjParser(source, name, options).Parse();
}

Result<Scene> ParseObjFile(const RandomAccessFile& file, const std::string& name,
                           const ObjParseOptions& options) {
  TextSource source;
  source.file = &file;
  source.size = file.size();
  return ObjParser(source, name, options).Parse();
}

}  // namespace hullpack
