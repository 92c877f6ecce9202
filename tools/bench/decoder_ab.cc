// decoder_ab: two builds of the o3dgc decoder in one process, timed against each other. Build it
// with decoder_ab.sh, which compiles build A as namespace o3dgc and build B as o3dgc_alt.
//
//   decoder_ab N A.s3d [B.s3d] [A2.s3d [B2.s3d] ...]   (--pairs: every A stream followed by its B)
//
// On a shared machine two processes timed one after the other differ by 5-10 % from run to run,
// more than most decoder changes. Here the two builds decode alternately (A then B, then B then A,
// so that neither always runs on the caches the other left), N pairs after 2 warm-up pairs, and
// the figure is the median of the per-pair ratios B / A (an A/A build gave 0.996; repeats of one
// comparison agree within about 1 % with 31-41 pairs, 2 % with 15).
// Without --pairs both builds decode the same stream (a change that keeps the format); with
// --pairs, build B decodes its own encoding of the mesh (a change of the format).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "o3dgc/o3dgc.h"
// The same header again, for build B's namespace.
#undef O3DGC_O3DGC_H_
#define o3dgc o3dgc_alt
#include "o3dgc/o3dgc.h"
#undef o3dgc

namespace {

double CpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

bool Read(const char* path, std::vector<uint8_t>* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

// CPU ms of one decode with build A's or build B's Decode (its DecodedMesh, DecodeOptions and
// Status types passed along), -1 if it fails.
template <typename Mesh, typename Options, typename StatusT, typename DecodeFn>
double TimeDecode(DecodeFn decode, const std::vector<uint8_t>& s, StatusT ok) {
  const double t0 = CpuMs();
  Mesh m;
  return decode(s.data(), s.size(), Options(), &m, nullptr) == ok ? CpuMs() - t0 : -1.0;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  bool pairs = false;
  std::vector<std::string> operands;
  hullpack::CliArgs cli("decoder_ab", "[--pairs] N STREAM...",
                        "Two builds of the o3dgc decoder (A and B, see decoder_ab.sh) decode each "
                        "STREAM\nalternately, N timed pairs after 2 warm-up pairs; prints the "
                        "median ratio B/A.");
  cli.Positional("N STREAM...", &operands, 2);
  cli.Flag("--pairs", &pairs, "the STREAMs are pairs A.s3d B.s3d: build B decodes its own stream");
  if (std::optional<int> exit_code = cli.Parse(argc, argv)) return *exit_code;
  long long pair_count = 0;
  const std::string why = hullpack::CliArgs::ParseWholeNumber(operands[0], 1, 100000, &pair_count);
  if (!why.empty()) return cli.UsageError("N " + why);
  if (pairs && operands.size() % 2 != 1) return cli.UsageError("--pairs needs A.s3d B.s3d pairs");
  const int n = static_cast<int>(pair_count);
  std::vector<char*> streams;
  for (size_t i = 1; i < operands.size(); ++i) streams.push_back(&operands[i][0]);
  const int count = static_cast<int>(streams.size());
  for (int arg = 0; arg < count; arg += pairs ? 2 : 1) {
    std::vector<uint8_t> a, b;
    const char* path_b = pairs ? streams[arg + 1] : streams[arg];
    if (!Read(streams[arg], &a) || !Read(path_b, &b)) {
      std::fprintf(stderr, "decoder_ab: cannot read %s or %s\n", streams[arg], path_b);
      return 1;
    }
    auto run_a = [&] {
      return TimeDecode<o3dgc::DecodedMesh, o3dgc::DecodeOptions>(o3dgc::Decode, a,
                                                                  o3dgc::Status::kOk);
    };
    auto run_b = [&] {
      return TimeDecode<o3dgc_alt::DecodedMesh, o3dgc_alt::DecodeOptions>(o3dgc_alt::Decode, b,
                                                                          o3dgc_alt::Status::kOk);
    };
    std::vector<double> ta, tb, ratio;
    for (int i = 0; i < n + 2; ++i) {
      double x, y;
      if (i & 1) {
        y = run_b();
        x = run_a();
      } else {
        x = run_a();
        y = run_b();
      }
      if (x < 0 || y < 0) {
        std::fprintf(stderr, "decoder_ab: %s: build %s cannot decode it\n",
                     x < 0 ? streams[arg] : path_b, x < 0 ? "A" : "B");
        return 1;
      }
      if (i < 2) continue;  // warm-up
      ta.push_back(x);
      tb.push_back(y);
      ratio.push_back(y / x);
    }
    std::printf(
        "%s: A min %.3f median %.3f ms | B min %.3f median %.3f ms | B/A %.4f (median of %d "
        "pairs)\n",
        streams[arg], *std::min_element(ta.begin(), ta.end()), Median(ta),
        *std::min_element(tb.begin(), tb.end()), Median(tb), Median(ratio), n);
  }
  return 0;
}
