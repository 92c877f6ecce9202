#include "bench/sweep.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/sweep_report.h"

namespace hullpack {
namespace {

class TempFolder {
 public:
  TempFolder() {
    char name[] = "/tmp/sweep_test_XXXXXX";
    path_ = mkdtemp(name) ? name : "";
  }
  ~TempFolder() {
    if (!path_.empty()) std::system(("rm -rf '" + path_ + "'").c_str());
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
}

std::string ReadText(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A closed 2 x 1 x 1 box, a 4 x 4 grid per face (faces not welded by index, only by position).
std::string ClosedBoxObj() {
  std::string obj;
  const int n = 4;
  const double size[3] = {2, 1, 1};
  int count = 0;
  char line[128];
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int base = count + 1;
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          double p[3];
          p[axis] = side ? size[axis] : 0.0;
          p[u] = size[u] * i / n;
          p[v] = size[v] * j / n;
          std::snprintf(line, sizeof(line), "v %.6f %.6f %.6f\n", p[0], p[1], p[2]);
          obj += line;
          ++count;
        }
      }
      // (i, j) -> (i + 1, j) -> (i + 1, j + 1) turns from u to v: counter-clockwise seen from
      // +axis.
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          const int a = base + i * (n + 1) + j, b = a + n + 1, c = b + 1, d = a + 1;
          if (side) {
            std::snprintf(line, sizeof(line), "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
          } else {
            std::snprintf(line, sizeof(line), "f %d %d %d\nf %d %d %d\n", a, c, b, a, d, c);
          }
          obj += line;
        }
      }
    }
  }
  return obj;
}

// An open height field with normals and UVs.
std::string WavySheetObj() {
  std::string obj;
  char line[160];
  const int n = 10;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n,
                   z = 0.2 * std::sin(6 * x) * std::cos(4 * y);
      const double dx = 1.2 * std::cos(6 * x) * std::cos(4 * y),
                   dy = -0.8 * std::sin(6 * x) * std::sin(4 * y);
      const double len = std::sqrt(dx * dx + dy * dy + 1);
      std::snprintf(line, sizeof(line), "v %.6f %.6f %.6f\nvt %.6f %.6f\nvn %.6f %.6f %.6f\n", x, y,
                    z, x, y, -dx / len, -dy / len, 1 / len);
      obj += line;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j + 1, b = a + n + 1, c = b + 1, d = a + 1;
      std::snprintf(line, sizeof(line),
                    "f %d/%d/%d %d/%d/%d %d/%d/%d\nf %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, b, b,
                    b, c, c, c, a, a, a, c, c, c, d, d, d);
      obj += line;
    }
  }
  return obj;
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  out.push_back(cell);
  return out;
}

SweepOptions TinySweep() {
  SweepOptions o;
  o.base.resolution = 10000;
  o.base.concavity = 0.0025;
  o.base.max_convex_hulls = 0;
  o.base.num_threads = 1;
  o.grid.resolutions = {10000, 20000};
  o.grid.concavities = {0.0025};
  o.grid.max_hulls = {0, 2};
  o.base_position_bits = 12;
  o.base_normal_bits = 8;
  o.base_uv_bits = 10;
  o.grid.position_bits = {8, 12};
  o.grid.normal_bits = {6, 8};
  o.grid.uv_bits = {10, 12};
  o.repeats = 1;
  o.metrics.mesh_samples = o.metrics.hull_samples = 2000;
  o.metrics.solid_points = 20000;
  o.metrics.threads = 1;
  o.timeout_seconds = 300;
  o.log = nullptr;
  return o;
}

TEST(Sweep, TwoMeshFolderGivesTheExpectedRowsAndColumns) {
  TempFolder in, out;
  ASSERT_FALSE(in.path().empty());
  WriteText(in.path() + "/box.obj", ClosedBoxObj());
  WriteText(in.path() + "/sheet.obj", WavySheetObj());
  WriteText(in.path() + "/notes.txt", "not a mesh");
  const SweepOptions o = TinySweep();
  Result<SweepResult> result = RunSweep(in.path(), o);
  ASSERT_TRUE(result.ok()) << result.status().message();
  ASSERT_EQ(result->meshes.size(), 2u);
  EXPECT_EQ(result->meshes[0].name, "box");
  EXPECT_TRUE(result->meshes[0].closed);
  EXPECT_FALSE(result->meshes[1].closed);
  EXPECT_TRUE(result->meshes[1].normals);
  EXPECT_TRUE(result->meshes[1].uvs);
  const std::string out_dir = out.path() + "/report";
  ASSERT_TRUE(WriteSweepOutputs(result.value(), o, out_dir, "sweep_bench IN -o OUT").ok());

  // Decomposition: (10000, base), (20000, base), (10000, max 2 hulls) for each mesh. Codec: bits
  // 8/8/10 and 12/8/10 for both; the sheet (normals, UVs) also 12/6/10 and 12/8/12.
  const std::string csv = ReadText(out_dir + "/sweep.csv");
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) rows.push_back(SplitCsvLine(line));
  ASSERT_EQ(rows.size(), 1u + 2 * 3 + 2 + 4);
  EXPECT_EQ(rows[0], SweepCsvColumns());
  std::map<std::string, size_t> column;
  for (size_t c = 0; c < rows[0].size(); ++c) column[rows[0][c]] = c;
  for (const char* name : {"mesh",
                           "stage",
                           "sweep",
                           "status",
                           "resolution",
                           "concavity",
                           "max_hulls",
                           "position_bits",
                           "normal_bits",
                           "uv_bits",
                           "hausdorff_mesh_to_hulls",
                           "hausdorff_hulls_to_mesh",
                           "iou",
                           "hull_count",
                           "coverage",
                           "invalid_hulls",
                           "position_max_error",
                           "position_rms_error",
                           "normal_max_deg",
                           "normal_mean_deg",
                           "uv_max_error",
                           "bytes",
                           "bits_per_vertex",
                           "time_ms",
                           "cpu_ms",
                           "peak_mb",
                           "decode_ms",
                           "decode_peak_mb"}) {
    EXPECT_TRUE(column.count(name)) << name;
  }
  std::map<std::string, int> per_mesh_stage;
  for (size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    ASSERT_EQ(row.size(), rows[0].size()) << "row " << r;
    EXPECT_EQ(row[column["status"]], "ok") << "row " << r;
    ++per_mesh_stage[row[column["mesh"]] + "/" + row[column["stage"]]];
    const double bytes = std::stod(row[column["bytes"]]);
    EXPECT_GT(bytes, 0);
    EXPECT_GT(std::stod(row[column["peak_mb"]]), 0);
    if (row[column["stage"]] == "decompose") {
      EXPECT_GE(std::stod(row[column["hull_count"]]), 1);
      EXPECT_EQ(row[column["invalid_hulls"]], "0");
      EXPECT_GT(std::stod(row[column["hull_vertices"]]), 3);
      EXPECT_LE(std::stod(row[column["hausdorff_mesh_to_hulls"]]), 0.2);
      EXPECT_LE(std::stod(row[column["hausdorff_hulls_to_mesh"]]), 0.2);
      if (row[column["max_hulls"]] == "2") {
        EXPECT_LE(std::stod(row[column["hull_count"]]), 2);
      }
      // IoU only for the closed mesh.
      EXPECT_EQ(row[column["iou"]].empty(), row[column["mesh"]] == "sheet");
      if (row[column["mesh"]] == "box") {
        EXPECT_GT(std::stod(row[column["iou"]]), 0.8);
      }
    } else {
      const int qp = std::stoi(row[column["position_bits"]]);
      // Within half a cell per axis (cell = largest extent / (2^bits - 1), the extent <= diagonal).
      EXPECT_LE(std::stod(row[column["position_max_error"]]),
                0.5 * std::sqrt(3.0) / ((1 << qp) - 1) + 1e-6);
      EXPECT_EQ(row[column["same_values"]], "1");
      EXPECT_EQ(row[column["normal_max_deg"]].empty(), row[column["mesh"]] == "box");
      EXPECT_EQ(row[column["uv_max_error"]].empty(), row[column["mesh"]] == "box");
      EXPECT_GT(std::stod(row[column["time_ms"]]), 0);
      EXPECT_GT(std::stod(row[column["decode_ms"]]), 0);
    }
  }
  EXPECT_EQ(per_mesh_stage["box/decompose"], 3);
  EXPECT_EQ(per_mesh_stage["sheet/decompose"], 3);
  EXPECT_EQ(per_mesh_stage["box/codec"], 2);
  EXPECT_EQ(per_mesh_stage["sheet/codec"], 4);

  // Plots and summary.
  for (const char* svg :
       {"decompose_resolution.svg", "decompose_median.svg", "codec_position_size.svg",
        "codec_position_time.svg", "codec_normal_size.svg", "codec_uv_size.svg"}) {
    const std::string text = ReadText(out_dir + "/" + svg);
    EXPECT_EQ(text.compare(0, 5, "<?xml"), 0) << svg;
    EXPECT_NE(text.find("</svg>"), std::string::npos) << svg;
  }
  const std::string md = ReadText(out_dir + "/summary.md");
  EXPECT_NE(md.find("sweep_bench IN -o OUT"), std::string::npos);
  EXPECT_NE(md.find("| box |"), std::string::npos);
  EXPECT_NE(md.find("| sheet |"), std::string::npos);
  EXPECT_NE(md.find("![codec: size against position error](codec_position_size.svg)"),
            std::string::npos);
}

TEST(Sweep, MissingFolderIsAnError) {
  EXPECT_FALSE(RunSweep("/nonexistent/folder/for/sweep", TinySweep()).ok());
}

TEST(Sweep, SweepMembership) {
  const SweepOptions o = TinySweep();
  EXPECT_EQ(DecomposeSweeps(o, 10000, 0.0025, 0), "resolution+concavity+max_hulls");
  EXPECT_EQ(DecomposeSweeps(o, 20000, 0.0025, 0), "resolution");
  EXPECT_EQ(DecomposeSweeps(o, 10000, 0.0025, 2), "max_hulls");
  EXPECT_EQ(DecomposeSweeps(o, 20000, 0.0025, 2), "");
  EXPECT_EQ(CodecSweeps(o, 8, 8, 10), "position_bits");
  EXPECT_EQ(CodecSweeps(o, 12, 6, 10), "normal_bits");
  EXPECT_EQ(CodecSweeps(o, 12, 8, 10), "position_bits+normal_bits+uv_bits");
}

}  // namespace
}  // namespace hullpack
