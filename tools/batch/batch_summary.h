// The per-asset outcome of a batch run, written as JSON and CSV, and the merge of shard summaries.
#ifndef HULLPACK_TOOLS_BATCH_BATCH_SUMMARY_H_
#define HULLPACK_TOOLS_BATCH_BATCH_SUMMARY_H_

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct AssetOutcome {
  size_t index = 0;
  std::string input, output;  // output relative to the batch's output folder
  // "packed", "cached", "failed", or "cancelled" (the run was stopped before it finished)
  std::string status;
  std::string error;  // why it failed or was not finished
  uint64_t input_bytes = 0, output_bytes = 0;
  uint64_t geometry_bytes_before = 0, geometry_bytes_after = 0;  // meshes + hulls, as in --report
  size_t meshes = 0, hulls = 0;
  double max_error_fraction = 0;  // largest position error reached over the meshes, of diagonal
  double hull_quantization_error = 0;  // largest hull vertex error, fraction of the diagonal
  double seconds = 0;                  // this run's time for the asset
  bool cache_hit = false;
};

// Fills the size and error columns from a `pack --report` object of one file.
void FillFromReport(const nlohmann::json& report, AssetOutcome* out);

struct BatchSummary {
  size_t total_assets = 0;  // in the whole batch (every shard)
  size_t shard_index = 0, shard_count = 1;
  double seconds = 0;
  std::vector<AssetOutcome> assets;  // sorted by index

  size_t Count(const char* status) const;
};

nlohmann::json SummaryToJson(const BatchSummary& summary);
Result<BatchSummary> SummaryFromJson(const std::string& text, const std::string& name);
// One header line, then one line per asset (RFC 4180 quoting).
std::string SummaryToCsv(const BatchSummary& summary);

// The summaries of shards 0..N-1 as one. Errors name the shard that is missing or inconsistent.
Result<BatchSummary> MergeSummaries(const std::vector<BatchSummary>& shards);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BATCH_BATCH_SUMMARY_H_
