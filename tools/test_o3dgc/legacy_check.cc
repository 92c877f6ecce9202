// o3dgc_legacy_check: decodes every *.s3d of a folder (streams of the original Open3DGC tool) with
// o3dgc::Decode and compares the result with the OBJ the original decoder wrote beside it
// (<name>_dec.obj): triangles must be identical and in the same order; positions, normals and
// texture coordinates must print the same with 6 significant digits (the original's precision)
// or, failing that, differ by at most one unit in the 6th digit.
//
//   o3dgc_legacy_check /work/shared/vectors/o3dgc
//
// Prints one line per stream (pass/fail, counts, values printed differently, largest error in
// 6th-digit units) and exits with the number of failures.
#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "o3dgc/o3dgc.h"

namespace {

struct Obj {
  std::vector<std::string> v, vn, vt;  // value tokens as printed
  std::vector<uint32_t> f;             // 0-based, 3 per triangle
};

bool ReadObj(const std::string& path, Obj* obj) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag, tok;
    s >> tag;
    std::vector<std::string>* dst = tag == "v"    ? &obj->v
                                    : tag == "vn" ? &obj->vn
                                    : tag == "vt" ? &obj->vt
                                                  : nullptr;
    if (dst) {
      while (s >> tok) dst->push_back(tok);
    } else if (tag == "f") {
      int corners = 0;
      while (s >> tok) {
        obj->f.push_back(uint32_t(std::strtoul(tok.c_str(), nullptr, 10) - 1));  // v of v/vt/vn
        ++corners;
      }
      if (corners != 3) return false;
    }
  }
  return true;
}

struct Compare {
  size_t values = 0, reprinted = 0;
  double max_units = 0;  // largest |ours - printed| in units of the printed 6th significant digit
  bool count_ok = true;
};

void CompareValues(const std::vector<float>& ours, const std::vector<std::string>& printed,
                   Compare* c) {
  if (ours.size() != printed.size()) {
    c->count_ok = false;
    return;
  }
  for (size_t i = 0; i < ours.size(); ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", double(ours[i]));  // what std::ostream prints by default
    ++c->values;
    if (printed[i] == buf) continue;
    ++c->reprinted;
    const double p = std::strtod(printed[i].c_str(), nullptr);
    const double unit = p == 0 ? 1e-6 : std::pow(10.0, std::floor(std::log10(std::fabs(p))) - 5);
    c->max_units = std::max(c->max_units, std::fabs(double(ours[i]) - p) / unit);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> folders;
  hullpack::CliArgs cli("o3dgc_legacy_check", "FOLDER",
                        "Decodes every *.s3d of FOLDER (streams of the original Open3DGC tool) and "
                        "compares each\nwith the OBJ the original decoder wrote beside it "
                        "(NAME_dec.obj). Exit status: the\nnumber of streams that differ.");
  cli.VersionDetail("reads original Open3DGC (2013) streams");
  cli.Positional("FOLDER", &folders, 1, 1);
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  const std::string dir = folders[0];
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".s3d") == 0) names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  int failures = 0;
  std::printf("%-36s %-6s %7s %9s %9s %7s %8s %9s %s\n", "stream", "format", "bytes", "triangles",
              "vertices", "normals", "texcoord", "reprinted", "max err (6th digit units)");
  for (const std::string& name : names) {
    const std::string stem = name.substr(0, name.size() - 4);
    std::ifstream in(dir + "/" + name, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    Obj obj;
    const bool have_obj = ReadObj(dir + "/" + stem + "_dec.obj", &obj);
    o3dgc::DecodedMesh m;
    o3dgc::StreamInfo info;
    const o3dgc::Status s =
        o3dgc::Decode(bytes.data(), bytes.size(), o3dgc::DecodeOptions(), &m, &info);
    if (s != o3dgc::Status::kOk || !have_obj) {
      std::printf("%-36s FAIL: %s\n", name.c_str(),
                  have_obj ? o3dgc::StatusName(s) : "no readable _dec.obj");
      ++failures;
      continue;
    }
    const std::vector<float>* uv = nullptr;
    for (const auto& a : m.float_attributes) {
      if (a.semantic == o3dgc::Semantic::kTexCoord && a.dimension == 2) uv = &a.values;
    }
    Compare c;
    CompareValues(m.positions, obj.v, &c);
    CompareValues(m.normals, obj.vn, &c);
    CompareValues(uv ? *uv : std::vector<float>(), obj.vt, &c);
    const bool triangles_ok = m.indices == obj.f;
    const bool ok = triangles_ok && c.count_ok && c.max_units <= 1.0 &&
                    info.format == o3dgc::StreamFormat::kOpen3dgc2013;
    if (!ok) ++failures;
    std::printf("%-36s %-6s %7zu %9zu %9zu %7zu %8zu %9zu %.3g%s%s%s\n", name.c_str(),
                info.stream_type == o3dgc::StreamType::kAscii ? "ascii" : "binary", bytes.size(),
                m.num_triangles(), m.num_vertices(), m.normals.size() / 3, uv ? uv->size() / 2 : 0,
                c.reprinted, c.max_units, ok ? "  pass" : "  FAIL",
                triangles_ok ? "" : " (triangles differ)",
                c.count_ok ? "" : " (value counts differ)");
  }
  std::printf("%zu streams, %d failed\n", names.size(), failures);
  return failures;
}
