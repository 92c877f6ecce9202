#include "batch/batch_summary.h"

#include <gtest/gtest.h>

namespace hullpack {
namespace {

AssetOutcome Asset(size_t index, const char* status) {
  AssetOutcome a;
  a.index = index;
  a.input = "/in/a" + std::to_string(index) + ".obj";
  a.output = "a" + std::to_string(index) + ".packed.glb";
  a.status = status;
  if (a.status == "failed") a.error = "/in/a.obj: bad, \"quoted\"";
  return a;
}

TEST(BatchSummary, FillsColumnsFromAPackReport) {
  const nlohmann::json report = nlohmann::json::parse(R"({"output_bytes": 900, "meshes": [
      {"bytes_before": 100, "bytes_after": 40, "hull_bytes": 10, "hull_count": 3,
       "max_error_fraction": 0.0004, "hull_error": {"quantization": 0.001}},
      {"bytes_before": 50, "bytes_after": 20, "hull_bytes": 0, "hull_count": 0,
       "max_error_fraction": 0.0002}]})");
  AssetOutcome a;
  FillFromReport(report, &a);
  EXPECT_EQ(a.output_bytes, 900u);
  EXPECT_EQ(a.geometry_bytes_before, 150u);
  EXPECT_EQ(a.geometry_bytes_after, 70u);
  EXPECT_EQ(a.meshes, 2u);
  EXPECT_EQ(a.hulls, 3u);
  EXPECT_DOUBLE_EQ(a.max_error_fraction, 0.0004);
  EXPECT_DOUBLE_EQ(a.hull_quantization_error, 0.001);
}

TEST(BatchSummary, JsonRoundTripAndCsvQuoting) {
  BatchSummary s;
  s.total_assets = 2;
  s.assets = {Asset(0, "packed"), Asset(1, "failed")};
  s.assets[0].output_bytes = 1234;
  s.assets[0].cache_hit = false;
  auto back = SummaryFromJson(SummaryToJson(s).dump(), "s.json");
  ASSERT_TRUE(back.ok());
  ASSERT_EQ(back->assets.size(), 2u);
  EXPECT_EQ(back->assets[0].output_bytes, 1234u);
  EXPECT_EQ(back->assets[1].error, s.assets[1].error);
  EXPECT_EQ(back->Count("failed"), 1u);
  const std::string csv = SummaryToCsv(s);
  EXPECT_NE(csv.find("\"/in/a.obj: bad, \"\"quoted\"\"\""), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_FALSE(SummaryFromJson("[1, 2]", "x.json").ok());
  EXPECT_FALSE(SummaryFromJson("{\"assets\": [{}]}", "x.json").ok());
}

TEST(BatchSummary, MergeOrdersAndChecksCompleteness) {
  std::vector<BatchSummary> shards(2);
  for (size_t k = 0; k < 2; ++k) {
    shards[k].total_assets = 5;
    shards[k].shard_index = k;
    shards[k].shard_count = 2;
    for (size_t i = k; i < 5; i += 2) shards[k].assets.push_back(Asset(i, "cached"));
  }
  auto merged = MergeSummaries(shards);
  ASSERT_TRUE(merged.ok()) << merged.status().message();
  ASSERT_EQ(merged->assets.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(merged->assets[i].index, i);

  shards[1].assets.pop_back();  // asset 3 lost
  EXPECT_FALSE(MergeSummaries(shards).ok());
  shards[1].shard_index = 0;  // a summary of the wrong shard
  EXPECT_FALSE(MergeSummaries(shards).ok());
}

}  // namespace
}  // namespace hullpack
