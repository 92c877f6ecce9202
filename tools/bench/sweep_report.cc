#include "bench/sweep_report.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>

#include "bench/svg_plot.h"
#include "common/file_util.h"

namespace hullpack {
namespace {

struct Column {
  const char* name;
  std::function<std::string(const SweepRow&)> text;
};

std::string Number(double v) {
  if (v < 0 || !std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

std::string CsvText(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

const std::vector<Column>& Columns() {
#define NUM(field)                                            \
  {                                                           \
#field, [](const SweepRow& r) { return Number(r.field); } \
  }
  static const std::vector<Column> columns = {
      {"mesh", [](const SweepRow& r) { return CsvText(r.mesh); }},
      {"stage", [](const SweepRow& r) { return r.stage; }},
      {"sweep", [](const SweepRow& r) { return r.sweep; }},
      {"status", [](const SweepRow& r) { return CsvText(r.status); }},
      {"triangles", [](const SweepRow& r) { return std::to_string(r.triangles); }},
      {"vertices", [](const SweepRow& r) { return std::to_string(r.vertices); }},
      {"closed", [](const SweepRow& r) { return std::string(r.closed ? "1" : "0"); }},
      NUM(resolution),
      NUM(concavity),
      NUM(max_hulls),
      NUM(position_bits),
      NUM(normal_bits),
      NUM(uv_bits),
      NUM(hull_count),
      NUM(hull_vertices),
      NUM(hausdorff_mesh_to_hulls),
      NUM(hausdorff_hulls_to_mesh),
      NUM(iou),
      NUM(coverage),
      NUM(hulls_to_mesh_in_solid),
      NUM(invalid_hulls),
      NUM(position_max_error),
      NUM(position_rms_error),
      NUM(normal_max_deg),
      NUM(normal_mean_deg),
      NUM(uv_max_error),
      NUM(same_values),
      NUM(bytes),
      NUM(bits_per_vertex),
      NUM(time_ms),
      NUM(cpu_ms),
      NUM(peak_mb),
      NUM(base_mb),
      NUM(decode_ms),
      NUM(decode_cpu_ms),
      NUM(decode_peak_mb),
  };
#undef NUM
  return columns;
}

bool OnSweep(const SweepRow& r, const std::string& sweep) {
  const std::string s = "+" + r.sweep + "+";
  return s.find("+" + sweep + "+") != std::string::npos;
}

bool Ok(const SweepRow& r) { return r.status == "ok"; }

double Median(std::vector<double> v) {
  v.erase(
      std::remove_if(v.begin(), v.end(), [](double x) { return !(x >= 0) || !std::isfinite(x); }),
      v.end());
  if (v.empty()) return -1;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double HausdorffMax(const SweepRow& r) {
  if (r.hausdorff_mesh_to_hulls < 0 || r.hausdorff_hulls_to_mesh < 0) return -1;
  return std::max(r.hausdorff_mesh_to_hulls, r.hausdorff_hulls_to_mesh);
}

// The parameter a sweep varies, as a sortable key (no hull budget sorts after every budget).
double SweepKey(const SweepRow& r, const std::string& sweep) {
  if (sweep == "resolution") return r.resolution;
  if (sweep == "concavity") return -r.concavity;  // coarse to fine
  if (sweep == "max_hulls") return r.max_hulls == 0 ? 1e18 : r.max_hulls;
  if (sweep == "position_bits") return r.position_bits;
  if (sweep == "normal_bits") return r.normal_bits;
  return r.uv_bits;
}

std::string SweepValue(const SweepRow& r, const std::string& sweep) {
  if (sweep == "max_hulls" && r.max_hulls == 0) return "no limit";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.10g",
                sweep == "concavity" ? r.concavity : std::fabs(SweepKey(r, sweep)));
  return buf;
}

// Rows of one stage and sweep, grouped by mesh (in mesh order), each sorted by the swept value.
std::vector<std::pair<std::string, std::vector<const SweepRow*>>> ByMesh(const SweepResult& result,
                                                                         const std::string& stage,
                                                                         const std::string& sweep) {
  std::vector<std::pair<std::string, std::vector<const SweepRow*>>> out;
  for (const SweepMesh& m : result.meshes) {
    std::vector<const SweepRow*> rows;
    for (const SweepRow& r : result.rows) {
      if (r.mesh == m.name && r.stage == stage && Ok(r) && OnSweep(r, sweep)) rows.push_back(&r);
    }
    std::sort(rows.begin(), rows.end(), [&](const SweepRow* a, const SweepRow* b) {
      return SweepKey(*a, sweep) < SweepKey(*b, sweep);
    });
    if (!rows.empty()) out.push_back({m.name, rows});
  }
  return out;
}

// The swept values present, sorted, each with the rows (all meshes) at that value.
std::vector<std::pair<double, std::vector<const SweepRow*>>> ByValue(const SweepResult& result,
                                                                     const std::string& stage,
                                                                     const std::string& sweep) {
  std::map<double, std::vector<const SweepRow*>> groups;
  for (const SweepRow& r : result.rows) {
    if (r.stage == stage && Ok(r) && OnSweep(r, sweep)) groups[SweepKey(r, sweep)].push_back(&r);
  }
  return {groups.begin(), groups.end()};
}

template <typename F>
double MedianOf(const std::vector<const SweepRow*>& rows, F&& field) {
  std::vector<double> v;
  for (const SweepRow* r : rows) v.push_back(field(*r));
  return Median(v);
}

Plot PerMeshPlot(const SweepResult& result, const std::string& stage, const std::string& sweep,
                 const std::function<double(const SweepRow&)>& x,
                 const std::function<double(const SweepRow&)>& y) {
  Plot p;
  for (const auto& [mesh, rows] : ByMesh(result, stage, sweep)) {
    PlotSeries s;
    s.name = mesh;
    // One colour per mesh in every plot.
    for (size_t m = 0; m < result.meshes.size(); ++m) {
      if (result.meshes[m].name == mesh) s.colour = static_cast<int>(m);
    }
    // Every plotted quantity is >= 0; -1 is "not measured" (a mesh without normals, ...).
    for (const SweepRow* r : rows) {
      if (x(*r) >= 0 && y(*r) >= 0) s.points.push_back({x(*r), y(*r)});
    }
    if (!s.points.empty()) p.series.push_back(s);
  }
  return p;
}

size_t PointCount(const Plot& p) {
  size_t n = 0;
  for (const PlotSeries& s : p.series) n += s.points.size();
  return n;
}

std::string Cell(double v, const char* format = "%.3g") {
  if (v < 0 || !std::isfinite(v)) return "–";
  char buf[48];
  std::snprintf(buf, sizeof(buf), format, v);
  return buf;
}

std::string GridText(const std::vector<double>& values) {
  std::string s;
  for (double v : values) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.10g", v);
    s += (s.empty() ? "" : ", ") + std::string(buf);
  }
  return s;
}

template <typename T>
std::vector<double> AsDoubles(const std::vector<T>& v) {
  return std::vector<double>(v.begin(), v.end());
}

// The first swept bit count at which the maximum position error stops roughly halving per bit
// (it shrinks by less than a quarter); -1 when it halves across the whole sweep.
int FlatteningBits(const std::vector<const SweepRow*>& rows) {
  for (size_t i = 1; i < rows.size(); ++i) {
    const SweepRow& a = *rows[i - 1];
    const SweepRow& b = *rows[i];
    if (b.position_bits != a.position_bits + 1 || !(a.position_max_error > 0)) continue;
    if (b.position_max_error > 0.75 * a.position_max_error)
      return static_cast<int>(b.position_bits);
  }
  return -1;
}

}  // namespace

const std::vector<std::string>& SweepCsvColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Column& c : Columns()) n.push_back(c.name);
    return n;
  }();
  return names;
}

std::string SweepCsv(const std::vector<SweepRow>& rows) {
  std::string text;
  for (const Column& c : Columns()) text += (text.empty() ? "" : ",") + std::string(c.name);
  text += "\n";
  for (const SweepRow& r : rows) {
    std::string line;
    bool first = true;
    for (const Column& c : Columns()) {
      line += (first ? "" : ",") + c.text(r);
      first = false;
    }
    text += line + "\n";
  }
  return text;
}

std::vector<std::pair<std::string, std::string>> SweepPlots(const SweepResult& result,
                                                            const SweepOptions& o) {
  std::vector<std::pair<std::string, std::string>> out;
  auto add = [&](const std::string& name, const Plot& p) {
    if (PointCount(p) > 0) out.push_back({name, RenderSvg(p)});
  };
  const auto cpu_s = [](const SweepRow& r) { return r.cpu_ms / 1000.0; };
  const std::string hausdorff_label = "Hausdorff error (max both ways) / bbox diagonal";
  const std::string time_label =
      "decomposition CPU time (s), median of " + std::to_string(o.decompose_repeats) + " run(s)";
  char base[160];
  std::snprintf(base, sizeof(base), "base point: resolution %u, concavity %g, %s",
                o.base.resolution, o.base.concavity,
                o.base.max_convex_hulls
                    ? ("at most " + std::to_string(o.base.max_convex_hulls) + " hulls").c_str()
                    : "no hull budget");

  {
    Plot p = PerMeshPlot(result, "decompose", "resolution", cpu_s, HausdorffMax);
    p.title = "Decomposition: error against run time over the voxel resolution";
    p.x = {time_label, true};
    p.y = {hausdorff_label, true};
    p.note = "one point per resolution (" + GridText(AsDoubles(o.grid.resolutions)) +
             "), one curve per mesh; " + base;
    add("decompose_resolution.svg", p);
  }
  {
    Plot p = PerMeshPlot(result, "decompose", "concavity", cpu_s, HausdorffMax);
    p.title = "Decomposition: error against run time over the concavity threshold";
    p.x = {time_label, true};
    p.y = {hausdorff_label, true};
    p.note = "one point per concavity (" + GridText(o.grid.concavities) +
             "), one curve per mesh; " + base;
    add("decompose_concavity.svg", p);
  }
  {
    Plot p = PerMeshPlot(result, "decompose", "max_hulls", HausdorffMax,
                         [](const SweepRow& r) { return r.bytes; });
    p.title = "Decomposition: hull bytes against error over the hull budget";
    p.x = {hausdorff_label, true};
    p.y = {"hull stream bytes (as hullpack pack stores them)", true};
    p.note = "one point per max hull count (" + GridText(AsDoubles(o.grid.max_hulls)) +
             "; 0 = no limit); " + base;
    add("decompose_max_hulls.svg", p);
  }
  {
    Plot p;
    for (const char* sweep : {"resolution", "concavity", "max_hulls"}) {
      PlotSeries s;
      s.name = std::string(sweep) + " sweep";
      for (const auto& [key, rows] : ByValue(result, "decompose", sweep)) {
        s.points.push_back({MedianOf(rows, cpu_s), MedianOf(rows, HausdorffMax)});
      }
      p.series.push_back(s);
    }
    p.title = "Decomposition: median over meshes, error against run time";
    p.x = {"median " + time_label, true};
    p.y = {"median " + hausdorff_label, true};
    p.note = "each point: one parameter value, medians over the meshes; " + std::string(base);
    add("decompose_median.svg", p);
  }
  const auto position_error = [](const SweepRow& r) { return r.position_max_error; };
  const auto bpv = [](const SweepRow& r) { return r.bits_per_vertex; };
  char codec_base[96];
  std::snprintf(codec_base, sizeof(codec_base), "base point %d/%d/%d bits (position/normal/UV)",
                o.base_position_bits, o.base_normal_bits, o.base_uv_bits);
  {
    Plot p = PerMeshPlot(result, "codec", "position_bits", position_error, bpv);
    p.title = "Codec: size against position error over the position bits";
    p.x = {"max position error (fraction of bbox diagonal)", true};
    p.y = {"stream size (bits per vertex)", false};
    p.note = "one point per position bit count (" + GridText(AsDoubles(o.grid.position_bits)) +
             "), one curve per mesh; " + codec_base;
    add("codec_position_size.svg", p);
  }
  {
    Plot p = PerMeshPlot(
        result, "codec", "position_bits",
        [](const SweepRow& r) { return r.cpu_ms + r.decode_cpu_ms; }, position_error);
    p.title = "Codec: position error against run time";
    p.x = {"encode + decode CPU time (ms), medians of " + std::to_string(o.repeats) + " run(s)",
           true};
    p.y = {"max position error (fraction of bbox diagonal)", true};
    p.note = std::string("one point per position bit count, one curve per mesh; ") + codec_base;
    add("codec_position_time.svg", p);
  }
  {
    Plot p = PerMeshPlot(
        result, "codec", "position_bits", [](const SweepRow& r) { return r.position_bits; },
        position_error);
    if (!p.series.empty()) {
      PlotSeries bound;
      bound.name = "bound: half a cell diagonal";
      bound.dashed = true;
      bound.markers = false;
      for (int b : o.grid.position_bits)
        bound.points.push_back({double(b), std::sqrt(3.0) / 2 / (std::ldexp(1.0, b) - 1)});
      p.series.push_back(bound);
    }
    p.title = "Codec: max position error against position bits";
    p.x = {"position bits", false};
    p.y = {"max position error (fraction of bbox diagonal)", true};
    p.note =
        "bound: sqrt(3)/2 of a cell of side diagonal/(2^bits - 1) (the cube side is at most the "
        "diagonal); " +
        std::string(codec_base);
    add("codec_position_bits.svg", p);
  }
  {
    Plot p = PerMeshPlot(
        result, "codec", "normal_bits", [](const SweepRow& r) { return r.normal_max_deg; }, bpv);
    p.title = "Codec: size against normal error over the normal bits";
    p.x = {"max normal angle error (degrees)", true};
    p.y = {"stream size (bits per vertex)", false};
    p.note = "meshes with normals; one point per normal bit count (" +
             GridText(AsDoubles(o.grid.normal_bits)) + "); " + codec_base;
    add("codec_normal_size.svg", p);
  }
  {
    Plot p = PerMeshPlot(
        result, "codec", "uv_bits", [](const SweepRow& r) { return r.uv_max_error; }, bpv);
    p.title = "Codec: size against UV error over the UV bits";
    p.x = {"max UV error (UV units)", true};
    p.y = {"stream size (bits per vertex)", false};
    p.note = "meshes with UVs; one point per UV bit count (" + GridText(AsDoubles(o.grid.uv_bits)) +
             "); " + codec_base;
    add("codec_uv_size.svg", p);
  }
  return out;
}

std::string SweepSummary(const SweepResult& result, const SweepOptions& o,
                         const std::string& command, const std::vector<std::string>& plots) {
  std::string md;
  char line[1024];
  md += "# Error against run time: sweep summary\n\n";
  md += "Made by:\n\n```sh\n" + command + "\n```\n\n";
  std::snprintf(line, sizeof(line), "%zu meshes, %zu points, %.0f s in all.", result.meshes.size(),
                result.rows.size(), result.seconds);
  md += line;
  md +=
      " Every measured step runs in a forked child process. *time* is the median wall time of its "
      "runs,"
      " *CPU* the median CPU time of the process (all threads) per run, which other load on a "
      "shared machine"
      " disturbs much less (the plots use it); *peak MB* is the child's `ru_maxrss` from `wait4`, "
      "which starts at"
      " the parent's resident size at the fork (the loaded mesh included; CSV column base_mb).\n\n";
  auto plot_link = [&](const std::string& name, const std::string& alt) {
    if (std::find(plots.begin(), plots.end(), name) != plots.end())
      md += "![" + alt + "](" + name + ")\n\n";
  };
  auto failures = [&](const std::string& stage) {
    std::string s;
    for (const SweepRow& r : result.rows) {
      if (r.stage != stage || Ok(r)) continue;
      char buf[400];
      std::snprintf(buf, sizeof(buf),
                    "- %s (resolution %s, concavity %s, max hulls %s, bits %s/%s/%s): %s\n",
                    r.mesh.c_str(), Number(r.resolution).c_str(), Number(r.concavity).c_str(),
                    Number(r.max_hulls).c_str(), Number(r.position_bits).c_str(),
                    Number(r.normal_bits).c_str(), Number(r.uv_bits).c_str(), r.status.c_str());
      s += buf;
    }
    if (!s.empty()) md += "Points that failed:\n\n" + s + "\n";
  };

  const bool any_decompose = std::any_of(result.rows.begin(), result.rows.end(),
                                         [](const SweepRow& r) { return r.stage == "decompose"; });
  if (any_decompose) {
    md += "## Decomposition\n\n";
    std::snprintf(
        line, sizeof(line),
        "Grid, one parameter at a time around the base point (resolution %u, concavity %g, %s, max "
        "distance "
        "%g, %u thread(s), %d run(s) per point): resolution %s; concavity %s; max hulls %s (0 = no "
        "limit).\n\n",
        o.base.resolution, o.base.concavity,
        o.base.max_convex_hulls ? ("max hulls " + std::to_string(o.base.max_convex_hulls)).c_str()
                                : "no hull budget",
        o.base.max_distance, o.base.num_threads, o.decompose_repeats,
        GridText(AsDoubles(o.grid.resolutions)).c_str(), GridText(o.grid.concavities).c_str(),
        GridText(AsDoubles(o.grid.max_hulls)).c_str());
    md += line;
    std::snprintf(line, sizeof(line),
                  "Error, measured by `hull_metrics` (as `vhacd_bench` measures) on the input "
                  "triangles and the hulls,"
                  " not by vhacd's own voxel report, as fractions of the bounding-box diagonal: H "
                  "mesh→hulls = largest"
                  " distance from the mesh surface to the union of hulls (0 inside a hull); H "
                  "hulls→mesh = largest"
                  " distance from the boundary of the union of hulls to the mesh surface (hull "
                  "points within %g of"
                  " another hull are inside the union); each sampled at the vertices and %zu "
                  "random surface points;"
                  " IoU of the solid and the union of hulls for closed meshes (%zu lattice "
                  "points). A hulls→mesh"
                  " maximum that lies inside the mesh solid is a crack between hulls, not a hull "
                  "sticking out (CSV"
                  " column hulls_to_mesh_in_solid; marked * below). Hull bytes: the hulls as "
                  "`hullpack pack` stores"
                  " them (one o3dgc stream, positions to %g of the diagonal).\n\n",
                  o.metrics.gap, o.metrics.mesh_samples, o.metrics.solid_points, o.hull_error);
    md += line;
    md += "### Base point, per mesh\n\n";
    md +=
        "| mesh | triangles | closed | hulls | H mesh→hulls | H hulls→mesh | IoU | time s | CPU s "
        "| peak MB | hull bytes |\n";
    md += "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const SweepRow& r : result.rows) {
      if (r.stage != "decompose" || !OnSweep(r, "resolution") || !OnSweep(r, "concavity") ||
          !OnSweep(r, "max_hulls"))
        continue;
      std::snprintf(
          line, sizeof(line), "| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
          r.mesh.c_str(), r.triangles, r.closed ? "yes" : "no",
          Ok(r) ? Cell(r.hull_count, "%.0f").c_str() : r.status.c_str(),
          Cell(r.hausdorff_mesh_to_hulls, "%.4f").c_str(),
          (Cell(r.hausdorff_hulls_to_mesh, "%.4f") + (r.hulls_to_mesh_in_solid == 1 ? "*" : ""))
              .c_str(),
          Cell(r.iou, "%.3f").c_str(), Cell(r.time_ms / 1000, "%.2f").c_str(),
          Cell(r.cpu_ms / 1000, "%.2f").c_str(), Cell(r.peak_mb, "%.0f").c_str(),
          Cell(r.bytes, "%.0f").c_str());
      md += line;
    }
    md += "\n";
    const std::pair<const char*, const char*> decompose_sweeps[] = {
        {"resolution", "Resolution"}, {"concavity", "Concavity"}, {"max_hulls", "Max hulls"}};
    for (const auto& [sweep, title] : decompose_sweeps) {
      md += std::string("### ") + title + " sweep, medians over meshes\n\n";
      md += std::string("| ") + sweep +
            " | meshes | hulls | H mesh→hulls | H hulls→mesh | IoU (closed) | time s | CPU s | "
            "peak MB | hull bytes |\n";
      md += "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      for (const auto& [key, rows] : ByValue(result, "decompose", sweep)) {
        std::snprintf(
            line, sizeof(line), "| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s |\n",
            SweepValue(*rows[0], sweep).c_str(), rows.size(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.hull_count; }), "%.1f").c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.hausdorff_mesh_to_hulls; }),
                 "%.4f")
                .c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.hausdorff_hulls_to_mesh; }),
                 "%.4f")
                .c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.iou; }), "%.3f").c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.time_ms / 1000; }), "%.2f")
                .c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.cpu_ms / 1000; }), "%.2f").c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.peak_mb; }), "%.0f").c_str(),
            Cell(MedianOf(rows, [](const SweepRow& r) { return r.bytes; }), "%.0f").c_str());
        md += line;
      }
      md += "\n";
    }
    plot_link("decompose_median.svg", "decomposition, medians: error against run time");
    plot_link("decompose_resolution.svg", "decomposition: error against run time over resolution");
    plot_link("decompose_concavity.svg", "decomposition: error against run time over concavity");
    plot_link("decompose_max_hulls.svg",
              "decomposition: hull bytes against error over the hull budget");
    failures("decompose");
  }

  const bool any_codec = std::any_of(result.rows.begin(), result.rows.end(),
                                     [](const SweepRow& r) { return r.stage == "codec"; });
  if (any_codec) {
    md += "## Codec\n\n";
    std::snprintf(
        line, sizeof(line),
        "Grid, one attribute at a time around %d/%d/%d bits (position/normal/UV): position bits "
        "%s; normal"
        " bits %s (meshes with normals); UV bits %s (meshes with UVs). Times are medians of %d "
        "runs."
        " Position error: max and RMS over the vertices of |decoded − original|, fractions of the"
        " bounding-box diagonal; normal error: angle between original and decoded normal; UV error:"
        " Euclidean distance in UV units. Errors are measured vertex by vertex on a keep-order "
        "stream after"
        " checking that the (smaller, reordered) stream whose size is reported decodes to the same "
        "vertex"
        " values (CSV column same_values).\n\n",
        o.base_position_bits, o.base_normal_bits, o.base_uv_bits,
        GridText(AsDoubles(o.grid.position_bits)).c_str(),
        GridText(AsDoubles(o.grid.normal_bits)).c_str(),
        GridText(AsDoubles(o.grid.uv_bits)).c_str(), o.repeats);
    md += line;
    md += "### Base point, per mesh\n\n";
    md +=
        "| mesh | vertices | bytes | bits/vertex | position max | position RMS | normal max ° | "
        "normal mean ° | UV max |"
        " encode ms wall / CPU | decode ms wall / CPU | encode peak MB | decode peak MB |\n";
    md += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const SweepRow& r : result.rows) {
      if (r.stage != "codec" || !OnSweep(r, "position_bits") || !OnSweep(r, "normal_bits") ||
          !OnSweep(r, "uv_bits"))
        continue;
      if (!Ok(r)) {
        md += "| " + r.mesh + " | " + r.status + " |||||||||||\n";
        continue;
      }
      std::snprintf(
          line, sizeof(line),
          "| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.mesh.c_str(),
          r.vertices, Cell(r.bytes, "%.0f").c_str(), Cell(r.bits_per_vertex, "%.2f").c_str(),
          Cell(r.position_max_error, "%.3g").c_str(), Cell(r.position_rms_error, "%.3g").c_str(),
          Cell(r.normal_max_deg, "%.3g").c_str(), Cell(r.normal_mean_deg, "%.3g").c_str(),
          Cell(r.uv_max_error, "%.3g").c_str(),
          (Cell(r.time_ms, "%.2f") + " / " + Cell(r.cpu_ms, "%.2f")).c_str(),
          (Cell(r.decode_ms, "%.2f") + " / " + Cell(r.decode_cpu_ms, "%.2f")).c_str(),
          Cell(r.peak_mb, "%.0f").c_str(), Cell(r.decode_peak_mb, "%.0f").c_str());
      md += line;
    }
    md += "\n";
    struct CodecSweep {
      const char* name;
      const char* title;
      const char* error_header;
      std::function<double(const SweepRow&)> error1, error2;
    };
    const CodecSweep sweeps[] = {
        {"position_bits", "Position bits", "position max | position RMS",
         [](const SweepRow& r) { return r.position_max_error; },
         [](const SweepRow& r) { return r.position_rms_error; }},
        {"normal_bits", "Normal bits", "normal max ° | normal mean °",
         [](const SweepRow& r) { return r.normal_max_deg; },
         [](const SweepRow& r) { return r.normal_mean_deg; }},
        {"uv_bits", "UV bits", "UV max", [](const SweepRow& r) { return r.uv_max_error; }, nullptr},
    };
    for (const CodecSweep& s : sweeps) {
      const auto groups = ByValue(result, "codec", s.name);
      if (groups.empty()) continue;
      md += std::string("### ") + s.title + " sweep, medians over meshes\n\n";
      md += std::string("| bits | meshes | bits/vertex | ") + s.error_header +
            " | encode ms | decode ms | encode CPU ms | decode CPU ms |\n";
      md += s.error2 ? "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
                     : "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      for (const auto& [key, rows] : groups) {
        // Only meshes that have the attribute say something about its bits.
        std::vector<const SweepRow*> with;
        for (const SweepRow* r : rows) {
          if (s.error1(*r) >= 0) with.push_back(r);
        }
        if (with.empty()) continue;
        const std::string errors =
            Cell(MedianOf(with, s.error1), "%.3g") +
            (s.error2 ? " | " + Cell(MedianOf(with, s.error2), "%.3g") : std::string());
        std::snprintf(
            line, sizeof(line), "| %s | %zu | %s | %s | %s | %s | %s | %s |\n",
            SweepValue(*with[0], s.name).c_str(), with.size(),
            Cell(MedianOf(with, [](const SweepRow& r) { return r.bits_per_vertex; }), "%.2f")
                .c_str(),
            errors.c_str(),
            Cell(MedianOf(with, [](const SweepRow& r) { return r.time_ms; }), "%.2f").c_str(),
            Cell(MedianOf(with, [](const SweepRow& r) { return r.decode_ms; }), "%.2f").c_str(),
            Cell(MedianOf(with, [](const SweepRow& r) { return r.cpu_ms; }), "%.2f").c_str(),
            Cell(MedianOf(with, [](const SweepRow& r) { return r.decode_cpu_ms; }), "%.2f")
                .c_str());
        md += line;
      }
      md += "\n";
    }
    // Where the position error stops halving.
    const auto per_mesh = ByMesh(result, "codec", "position_bits");
    if (!per_mesh.empty()) {
      md += "### Where the position error stops halving per bit\n\n";
      md +=
          "The first swept bit count at which the maximum position error shrinks by less than a "
          "quarter (instead of"
          " halving); `–` when it halves across the sweep.\n\n";
      md +=
          "| mesh | max error at the fewest bits | at the base bits | at the most bits | stops "
          "halving at |\n";
      md += "|---|---:|---:|---:|---:|\n";
      for (const auto& [mesh, rows] : per_mesh) {
        const SweepRow* at_base = nullptr;
        for (const SweepRow* r : rows) {
          if (r->position_bits == o.base_position_bits) at_base = r;
        }
        const int flat = FlatteningBits(rows);
        std::snprintf(
            line, sizeof(line), "| %s | %s (%g bits) | %s | %s (%g bits) | %s |\n", mesh.c_str(),
            Cell(rows.front()->position_max_error, "%.3g").c_str(), rows.front()->position_bits,
            at_base ? Cell(at_base->position_max_error, "%.3g").c_str() : "–",
            Cell(rows.back()->position_max_error, "%.3g").c_str(), rows.back()->position_bits,
            flat > 0 ? (std::to_string(flat) + " bits").c_str() : "–");
        md += line;
      }
      md += "\n";
    }
    plot_link("codec_position_size.svg", "codec: size against position error");
    plot_link("codec_position_time.svg", "codec: position error against run time");
    plot_link("codec_position_bits.svg", "codec: position error against bits");
    plot_link("codec_normal_size.svg", "codec: size against normal error");
    plot_link("codec_uv_size.svg", "codec: size against UV error");
    failures("codec");
  }
  if (!result.skipped.empty()) {
    md += "## Not measured\n\n";
    for (const std::string& s : result.skipped) md += "- " + s + "\n";
    md += "\n";
  }
  return md;
}

Status WriteSweepOutputs(const SweepResult& result, const SweepOptions& options,
                         const std::string& folder, const std::string& command) {
  if (mkdir(folder.c_str(), 0777) != 0 && errno != EEXIST) {
    return Status(StatusCode::kIoError,
                  folder + ": cannot create the folder: " + std::strerror(errno));
  }
  const std::string csv = SweepCsv(result.rows);
  Status s = WriteFileAtomically(folder + "/sweep.csv", csv.data(), csv.size());
  if (!s.ok()) return s;
  std::vector<std::string> names;
  for (const auto& [name, svg] : SweepPlots(result, options)) {
    s = WriteFileAtomically(folder + "/" + name, svg.data(), svg.size());
    if (!s.ok()) return s;
    names.push_back(name);
  }
  const std::string md = SweepSummary(result, options, command, names);
  return WriteFileAtomically(folder + "/summary.md", md.data(), md.size());
}

}  // namespace hullpack
