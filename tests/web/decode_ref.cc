// web_decode_ref: decodes an o3dgc stream as a packed file's reader does (DecodePackedStream: the
// library's decoder and the format's skin-weight rule) and prints what the browser test
// compares against, as JSON on stdout:
//   {"vertices":N,"triangles":T,"normals":bool,"float_attributes":[{"semantic":s,"dimension":d}],
//    "int_attributes":[...],"min":[x,y,z],"max":[x,y,z],
//    "groups":[{"id":g,"vertices":n,"triangles":t,"min":[...],"max":[...]}]}
// "groups" lists each triangle group id present (ascending), with the vertices its triangles use.
//   web_decode_ref --time N STREAM.s3d
// instead decodes N times and prints {"cpu_ms": median CPU milliseconds per decode, "runs": N}
// (the native reference of tests/web/bench_cpu.mjs).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "o3dgc/o3dgc.h"
#include "packed/packed_glb_format.h"

namespace {

void PrintBox(const std::vector<float>& p, const std::set<uint32_t>* only) {
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool first = true;
  for (size_t v = 0; v < p.size() / 3; ++v) {
    if (only && !only->count(uint32_t(v))) continue;
    for (int c = 0; c < 3; ++c) {
      const float x = p[3 * v + c];
      if (first || x < lo[c]) lo[c] = x;
      if (first || x > hi[c]) hi[c] = x;
    }
    first = false;
  }
  std::printf("\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]", lo[0], lo[1], lo[2], hi[0],
              hi[1], hi[2]);
}

double CpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  int timed_runs = 0;
  if (argc == 4 && std::string(argv[1]) == "--time") timed_runs = std::atoi(argv[2]);
  if (argc != 2 && timed_runs <= 0) {
    std::fprintf(stderr, "usage: web_decode_ref [--time N] STREAM.s3d\n");
    return 2;
  }
  const char* path = argv[argc - 1];
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    std::fprintf(stderr, "cannot read %s\n", path);
    return 1;
  }
  const std::vector<uint8_t> data((std::istreambuf_iterator<char>(f)),
                                  std::istreambuf_iterator<char>());
  o3dgc::DecodedMesh m;
  const o3dgc::Status s = hullpack::DecodePackedStream(data.data(), data.size(), &m);
  if (s != o3dgc::Status::kOk) {
    std::fprintf(stderr, "decode failed: %s\n", o3dgc::StatusName(s));
    return 1;
  }
  if (timed_runs > 0) {
    std::vector<double> ms;
    for (int i = 0; i < timed_runs; ++i) {
      o3dgc::DecodedMesh r;
      const double t0 = CpuMs();
      if (hullpack::DecodePackedStream(data.data(), data.size(), &r) != o3dgc::Status::kOk)
        return 1;
      ms.push_back(CpuMs() - t0);
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    std::printf("{\"cpu_ms\":%.4f,\"runs\":%d}\n", ms[ms.size() / 2], timed_runs);
    return 0;
  }
  std::printf("{\"vertices\":%zu,\"triangles\":%zu,\"normals\":%s,", m.num_vertices(),
              m.num_triangles(), m.normals.empty() ? "false" : "true");
  std::printf("\"float_attributes\":[");
  for (size_t i = 0; i < m.float_attributes.size(); ++i) {
    std::printf("%s{\"semantic\":%d,\"dimension\":%u}", i ? "," : "",
                int(m.float_attributes[i].semantic), m.float_attributes[i].dimension);
  }
  std::printf("],\"int_attributes\":[");
  for (size_t i = 0; i < m.int_attributes.size(); ++i) {
    std::printf("%s{\"semantic\":%d,\"dimension\":%u}", i ? "," : "",
                int(m.int_attributes[i].semantic), m.int_attributes[i].dimension);
  }
  std::printf("],");
  PrintBox(m.positions, nullptr);
  std::printf(",\"groups\":[");
  std::map<uint32_t, std::pair<std::set<uint32_t>, size_t>> groups;
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    auto& g = groups[m.triangle_groups.empty() ? 0 : m.triangle_groups[t]];
    for (int c = 0; c < 3; ++c) g.first.insert(m.indices[3 * t + c]);
    ++g.second;
  }
  bool first = true;
  for (const auto& [id, g] : groups) {
    std::printf("%s{\"id\":%u,\"vertices\":%zu,\"triangles\":%zu,", first ? "" : ",", id,
                g.first.size(), g.second);
    PrintBox(m.positions, &g.first);
    std::printf("}");
    first = false;
  }
  std::printf("]}\n");
  return 0;
}
