#include "batch/batch_plan.h"

#include <unistd.h>

#include <cstdlib>
#include <map>
#include <sstream>

#include "common/file_util.h"

namespace hullpack {

std::string AbsolutePath(const std::string& path) {
  std::string full = path;
  if (full.empty() || full[0] != '/') {
    char buffer[4096];
    const char* cwd = getcwd(buffer, sizeof(buffer));
    full = std::string(cwd ? cwd : ".") + "/" + path;
  }
  std::vector<std::string> parts;
  std::istringstream segments(full);
  std::string part;
  while (std::getline(segments, part, '/')) {
    if (part.empty() || part == ".") continue;
    if (part == "..") {
      if (!parts.empty()) parts.pop_back();
      continue;
    }
    parts.push_back(part);
  }
  std::string out;
  for (const std::string& p : parts) out += "/" + p;
  return out.empty() ? "/" : out;
}

Result<std::vector<std::string>> ReadManifest(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  const std::string base = AbsolutePath(path);
  const std::string folder = base.substr(0, base.find_last_of('/') + 1);
  std::vector<std::string> inputs;
  std::istringstream lines(std::string(bytes->begin(), bytes->end()));
  std::string line;
  size_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    line = line.substr(start);
    if (line.find('\0') != std::string::npos) {
      return Status(StatusCode::kInvalidArgument,
                    path + ":" + std::to_string(number) + ": not a path (NUL byte)");
    }
    inputs.push_back(AbsolutePath(line[0] == '/' ? line : folder + line));
  }
  return inputs;
}

Result<std::vector<BatchAsset>> PlanBatch(const std::vector<std::string>& inputs) {
  if (inputs.empty()) return Status(StatusCode::kInvalidArgument, "no inputs");
  std::vector<BatchAsset> assets(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    assets[i].index = i;
    assets[i].input = AbsolutePath(inputs[i]);
  }
  // The deepest folder every input lies in.
  std::string common = assets[0].input.substr(0, assets[0].input.find_last_of('/') + 1);
  for (const BatchAsset& a : assets) {
    while (!common.empty() && a.input.compare(0, common.size(), common) != 0) {
      common.pop_back();
      common = common.substr(0, common.find_last_of('/') + 1);
    }
  }
  std::map<std::string, size_t> by_output;
  for (BatchAsset& a : assets) {
    std::string rel = a.input.substr(common.size());
    const size_t slash = rel.find_last_of('/');
    const size_t dot = rel.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash + 1))
      rel = rel.substr(0, dot);
    a.output = rel + ".packed.glb";
    auto [it, added] = by_output.emplace(a.output, a.index);
    if (!added) {
      const std::string& other = assets[it->second].input;
      return Status(StatusCode::kInvalidArgument,
                    other == a.input ? a.input + ": listed twice"
                                     : other + " and " + a.input + " would both write " + a.output);
    }
  }
  return assets;
}

bool ParseShard(const std::string& text, Shard* out) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 >= text.size()) return false;
  char* end = nullptr;
  const std::string k = text.substr(0, slash), n = text.substr(slash + 1);
  const long index = std::strtol(k.c_str(), &end, 10);
  if (*end != '\0' || k.find_first_not_of("0123456789") != std::string::npos) return false;
  const long count = std::strtol(n.c_str(), &end, 10);
  if (*end != '\0' || n.find_first_not_of("0123456789") != std::string::npos) return false;
  if (count < 1 || count > 100000 || index < 0 || index >= count) return false;
  out->index = static_cast<size_t>(index);
  out->count = static_cast<size_t>(count);
  return true;
}

std::vector<BatchAsset> SelectShard(const std::vector<BatchAsset>& assets, const Shard& shard) {
  std::vector<BatchAsset> out;
  for (size_t i = shard.index; i < assets.size(); i += shard.count) out.push_back(assets[i]);
  return out;
}

}  // namespace hullpack
