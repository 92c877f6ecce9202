#include "batch/batch_summary.h"

#include <algorithm>
#include <cstdio>

namespace hullpack {
namespace {

template <typename T>
T Get(const nlohmann::json& j, const char* key, T fallback) {
  if (!j.is_object() || !j.contains(key)) return fallback;
  const nlohmann::json& v = j[key];
  if constexpr (std::is_same_v<T, std::string>) {
    return v.is_string() ? v.get<std::string>() : fallback;
  } else if constexpr (std::is_same_v<T, bool>) {
    return v.is_boolean() ? v.get<bool>() : fallback;
  } else {
    return v.is_number() ? v.get<T>() : fallback;
  }
}

std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", v);
  return buffer;
}

}  // namespace

void FillFromReport(const nlohmann::json& report, AssetOutcome* out) {
  out->output_bytes = Get<uint64_t>(report, "output_bytes", 0);
  if (!report.is_object() || !report.contains("meshes") || !report["meshes"].is_array()) return;
  for (const nlohmann::json& m : report["meshes"]) {
    ++out->meshes;
    out->hulls += Get<size_t>(m, "hull_count", 0);
    out->geometry_bytes_before += Get<uint64_t>(m, "bytes_before", 0);
    out->geometry_bytes_after +=
        Get<uint64_t>(m, "bytes_after", 0) + Get<uint64_t>(m, "hull_bytes", 0);
    out->max_error_fraction =
        std::max(out->max_error_fraction, Get<double>(m, "max_error_fraction", 0));
    if (m.contains("hull_error"))
      out->hull_quantization_error =
          std::max(out->hull_quantization_error, Get<double>(m["hull_error"], "quantization", 0));
  }
}

size_t BatchSummary::Count(const char* status) const {
  return static_cast<size_t>(std::count_if(
      assets.begin(), assets.end(), [&](const AssetOutcome& a) { return a.status == status; }));
}

nlohmann::json SummaryToJson(const BatchSummary& s) {
  nlohmann::json assets = nlohmann::json::array();
  for (const AssetOutcome& a : s.assets) {
    nlohmann::json j = {{"index", a.index},
                        {"input", a.input},
                        {"output", a.output},
                        {"status", a.status},
                        {"cache_hit", a.cache_hit},
                        {"seconds", a.seconds},
                        {"input_bytes", a.input_bytes}};
    if (a.status == "failed" || a.status == "cancelled") {
      j["error"] = a.error;
    } else {
      j["output_bytes"] = a.output_bytes;
      j["geometry_bytes_before"] = a.geometry_bytes_before;
      j["geometry_bytes_after"] = a.geometry_bytes_after;
      j["meshes"] = a.meshes;
      j["hulls"] = a.hulls;
      j["max_error_fraction"] = a.max_error_fraction;
      j["hull_quantization_error"] = a.hull_quantization_error;
    }
    assets.push_back(std::move(j));
  }
  return {{"total_assets", s.total_assets},
          {"shard", {{"index", s.shard_index}, {"count", s.shard_count}}},
          {"counts",
           {{"packed", s.Count("packed")},
            {"cached", s.Count("cached")},
            {"failed", s.Count("failed")}}},
          {"seconds", s.seconds},
          {"assets", assets}};
}

Result<BatchSummary> SummaryFromJson(const std::string& text, const std::string& name) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  auto bad = [&](const std::string& why) {
    return Status(StatusCode::kInvalidArgument, name + ": " + why);
  };
  if (j.is_discarded() || !j.is_object()) return bad("not a batch summary (not a JSON object)");
  if (!j.contains("assets") || !j["assets"].is_array()) return bad("has no assets array");
  BatchSummary s;
  s.total_assets = Get<size_t>(j, "total_assets", 0);
  if (j.contains("shard")) {
    s.shard_index = Get<size_t>(j["shard"], "index", 0);
    s.shard_count = Get<size_t>(j["shard"], "count", 1);
  }
  s.seconds = Get<double>(j, "seconds", 0);
  for (const nlohmann::json& a : j["assets"]) {
    if (!a.is_object() || !a.contains("index") || !a.contains("status"))
      return bad("an asset lacks its index or status");
    AssetOutcome o;
    o.index = Get<size_t>(a, "index", 0);
    o.input = Get<std::string>(a, "input", "");
    o.output = Get<std::string>(a, "output", "");
    o.status = Get<std::string>(a, "status", "");
    o.error = Get<std::string>(a, "error", "");
    o.cache_hit = Get<bool>(a, "cache_hit", false);
    o.seconds = Get<double>(a, "seconds", 0);
    o.input_bytes = Get<uint64_t>(a, "input_bytes", 0);
    o.output_bytes = Get<uint64_t>(a, "output_bytes", 0);
    o.geometry_bytes_before = Get<uint64_t>(a, "geometry_bytes_before", 0);
    o.geometry_bytes_after = Get<uint64_t>(a, "geometry_bytes_after", 0);
    o.meshes = Get<size_t>(a, "meshes", 0);
    o.hulls = Get<size_t>(a, "hulls", 0);
    o.max_error_fraction = Get<double>(a, "max_error_fraction", 0);
    o.hull_quantization_error = Get<double>(a, "hull_quantization_error", 0);
    s.assets.push_back(std::move(o));
  }
  return s;
}

std::string SummaryToCsv(const BatchSummary& s) {
  std::string out =
      "index,input,output,status,cache_hit,error,input_bytes,output_bytes,geometry_bytes_before,"
      "geometry_bytes_after,meshes,hulls,max_error_fraction,hull_quantization_error,seconds\n";
  for (const AssetOutcome& a : s.assets) {
    const bool ok = a.status == "packed" || a.status == "cached";
    out += std::to_string(a.index) + "," + CsvField(a.input) + "," + CsvField(a.output) + "," +
           a.status + "," + (a.cache_hit ? "1" : "0") + "," + CsvField(a.error) + "," +
           std::to_string(a.input_bytes) + "," + (ok ? std::to_string(a.output_bytes) : "") + "," +
           (ok ? std::to_string(a.geometry_bytes_before) : "") + "," +
           (ok ? std::to_string(a.geometry_bytes_after) : "") + "," +
           (ok ? std::to_string(a.meshes) : "") + "," + (ok ? std::to_string(a.hulls) : "") + "," +
           (ok ? Number(a.max_error_fraction) : "") + "," +
           (ok ? Number(a.hull_quantization_error) : "") + "," + Number(a.seconds) + "\n";
  }
  return out;
}

Result<BatchSummary> MergeSummaries(const std::vector<BatchSummary>& shards) {
  BatchSummary merged;
  if (shards.empty()) return Status(StatusCode::kInvalidArgument, "no shard summaries");
  merged.total_assets = shards[0].total_assets;
  merged.shard_count = 1;
  for (size_t k = 0; k < shards.size(); ++k) {
    const BatchSummary& s = shards[k];
    if (s.shard_index != k || s.shard_count != shards.size() ||
        s.total_assets != merged.total_assets) {
      return Status(StatusCode::kInvalidArgument,
                    "shard " + std::to_string(k) + " of " + std::to_string(shards.size()) +
                        ": its summary belongs to another batch (shard " +
                        std::to_string(s.shard_index) + " of " + std::to_string(s.shard_count) +
                        ", " + std::to_string(s.total_assets) + " assets)");
    }
    merged.seconds = std::max(merged.seconds, s.seconds);
    merged.assets.insert(merged.assets.end(), s.assets.begin(), s.assets.end());
  }
  std::sort(merged.assets.begin(), merged.assets.end(),
            [](const AssetOutcome& a, const AssetOutcome& b) { return a.index < b.index; });
  for (size_t i = 0; i < merged.assets.size(); ++i) {
    if (merged.assets[i].index != i)
      return Status(StatusCode::kInvalidArgument,
                    "the shard summaries do not list asset " + std::to_string(i));
  }
  if (merged.assets.size() != merged.total_assets)
    return Status(StatusCode::kInvalidArgument,
                  "the shard summaries list " + std::to_string(merged.assets.size()) + " of " +
                      std::to_string(merged.total_assets) + " assets");
  return merged;
}

}  // namespace hullpack
