#include "batch/asset_cache.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <nlohmann/json.hpp>
#include <sstream>

#include "batch/sha256.h"
#include "common/file_util.h"
#include "common/version.h"
#include "gltf/glb_reader.h"

namespace hullpack {
namespace {

// Bumped whenever the layout or the key recipe changes.
constexpr char kCacheLayout[] = "hullpack-cache 1";

std::string NameOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A glTF's external buffer URIs (GLB: from its JSON chunk), as relative paths.
void GltfBuffers(const std::vector<uint8_t>& bytes, std::vector<std::string>* out) {
  std::string json_text;
  if (bytes.size() >= 20 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF")) {
    const size_t length = size_t(bytes[12]) | size_t(bytes[13]) << 8 | size_t(bytes[14]) << 16 |
                          size_t(bytes[15]) << 24;
    if (length > bytes.size() - 20) return;
    json_text.assign(bytes.begin() + 20, bytes.begin() + 20 + static_cast<long>(length));
  } else {
    json_text.assign(bytes.begin(), bytes.end());
  }
  const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("buffers") ||
      !doc["buffers"].is_array())
    return;
  for (const nlohmann::json& buffer : doc["buffers"]) {
    if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string()) continue;
    const std::string uri = buffer["uri"].get<std::string>();
    std::string path, error;
    if (uri.compare(0, 5, "data:") != 0 && RelativePathFromUri(uri, &path, &error))
      out->push_back(path);
  }
}

// An OBJ's `mtllib` names (several may share one line), as the OBJ reader resolves them.
void ObjMaterialLibraries(const std::vector<uint8_t>& bytes, std::vector<std::string>* out) {
  std::istringstream lines(std::string(bytes.begin(), bytes.end()));
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string key, name;
    if (!(words >> key) || key != "mtllib") continue;
    while (words >> name) out->push_back(name);
  }
}

// "missing" or the SHA-256 of the file's bytes.
std::string FileHash(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
  if (!bytes.ok()) return "missing";
  return Sha256Hex(bytes->data(), bytes->size());
}

std::string Text(const std::vector<uint8_t>& bytes) {
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

AssetCache::AssetCache(std::string dir, std::string salt)
    : dir_(std::move(dir)), salt_(std::move(salt)) {
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
}

namespace {

// Removes "NAME.tmp-..." files older than `max_age_seconds` in `folder` and its sub-folders.
void RemoveOldTemporaries(const std::string& folder, double max_age_seconds, int depth) {
  DIR* dir = opendir(folder.c_str());
  if (!dir) return;
  const time_t now = time(nullptr);
  while (dirent* e = readdir(dir)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    const std::string path = folder + "/" + name;
    struct stat st;
    if (lstat(path.c_str(), &st) != 0) continue;
    if (S_ISDIR(st.st_mode)) {
      if (depth > 0) RemoveOldTemporaries(path, max_age_seconds, depth - 1);
    } else if (name.find(".tmp-") != std::string::npos &&
               difftime(now, st.st_mtime) > max_age_seconds) {
      unlink(path.c_str());
    }
  }
  closedir(dir);
}

}  // namespace

Status AssetCache::Prepare() const {
  for (const char* kind : {"", "/inputs", "/objects"}) {
    Status s = MakeDirectories(dir_ + kind);
    if (!s.ok()) return s;
  }
  RemoveOldTemporaries(dir_, 3600.0, 2);
  return Status::Ok();
}

std::string AssetCache::PathOf(const char* kind, const std::string& key, const char* ext) const {
  return dir_ + "/" + kind + "/" + key.substr(0, 2) + "/" + key + ext;
}

std::string AssetCache::EntryKey(const std::string& input_key, const std::string& input_dir,
                                 const std::vector<std::string>& referenced) const {
  Sha256 h;
  h.UpdateField(input_key);
  for (const std::string& path : referenced) {
    h.UpdateField(path);
    h.UpdateField(FileHash(input_dir + "/" + path));
  }
  return h.HexDigest();
}

Result<CacheProbe> AssetCache::Lookup(const std::string& input) const {
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(input);
  if (!bytes.ok()) return bytes.status();
  CacheProbe probe;
  Sha256 h;
  h.UpdateField(salt_);
  h.UpdateField(NameOf(input));
  h.Update(bytes->data(), bytes->size());
  probe.input_key = h.HexDigest();

  Result<std::vector<uint8_t>> record = ReadFileBytes(PathOf("inputs", probe.input_key, ".json"));
  if (!record.ok()) return probe;
  const nlohmann::json list = nlohmann::json::parse(Text(record.value()), nullptr, false);
  if (list.is_discarded() || !list.is_array()) return probe;
  std::vector<std::string> referenced;
  for (const nlohmann::json& path : list) {
    if (!path.is_string()) return probe;
    referenced.push_back(path.get<std::string>());
  }
  const std::string key = EntryKey(probe.input_key, FolderOf(input), referenced);
  Result<std::vector<uint8_t>> meta = ReadFileBytes(PathOf("objects", key, ".json"));
  if (!meta.ok()) return probe;
  Result<std::vector<uint8_t>> glb = ReadFileBytes(PathOf("objects", key, ".glb"));
  if (!glb.ok()) return probe;
  probe.hit = true;
  probe.glb = std::move(glb.value());
  probe.meta = Text(meta.value());
  return probe;
}

Status AssetCache::Store(const std::string& input, const std::string& input_key,
                         const std::vector<std::string>& referenced,
                         const std::vector<uint8_t>& glb, const std::string& meta) const {
  const std::string key = EntryKey(input_key, FolderOf(input), referenced);
  for (const std::string& dir :
       {dir_ + "/objects/" + key.substr(0, 2), dir_ + "/inputs/" + input_key.substr(0, 2)}) {
    Status s = MakeDirectories(dir);
    if (!s.ok()) return s;
  }
  // The output, then its report (the entry exists from now on), then the record that leads there.
  Status s = WriteFileAtomically(PathOf("objects", key, ".glb"), glb);
  if (s.ok()) s = WriteFileAtomically(PathOf("objects", key, ".json"), meta.data(), meta.size());
  if (s.ok()) {
    const std::string list = nlohmann::json(referenced).dump();
    s = WriteFileAtomically(PathOf("inputs", input_key, ".json"), list.data(), list.size());
  }
  return s;
}

std::string CacheSalt(const std::vector<std::string>& output_args) {
  static const std::string tool = [] {
    return std::string(HULLPACK_VERSION) + " " + FileHash("/proc/self/exe");
  }();
  Sha256 h;
  h.UpdateField(kCacheLayout);
  h.UpdateField(tool);
  for (const std::string& a : output_args) h.UpdateField(a);
  return h.HexDigest();
}

std::vector<std::string> ReferencedFiles(const std::string& input,
                                         const std::vector<std::string>& image_uris) {
  std::vector<std::string> out;
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(input);
  const std::string ext = LowerExtension(input);
  if (bytes.ok() && (ext == "gltf" || ext == "glb")) GltfBuffers(bytes.value(), &out);
  if (bytes.ok() && ext == "obj") ObjMaterialLibraries(bytes.value(), &out);
  for (const std::string& uri : image_uris) {
    std::string path, error;
    if (RelativePathFromUri(uri, &path, &error)) out.push_back(path);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace hullpack
