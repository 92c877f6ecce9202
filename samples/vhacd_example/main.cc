// The V-HACD 2.0 library example from the author's blog, on the IVHACD facade:
//   vhacd_example [input.obj] [log.txt]
// Without an input it decomposes a torus built in code. Prints the hulls' points and triangles
// and returns 0 when the decomposition succeeded.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vhacd/ivhacd.h"

using VHACD::IVHACD;

class MyCallback : public IVHACD::IUserCallback {
 public:
  void Update(const double overallProgress, const double stageProgress,
              const double operationProgress, const char* const stage,
              const char* const operation) override {
    std::cout << std::setfill(' ') << std::setw(3) << static_cast<int>(overallProgress + 0.5)
              << "% "
              << "[ " << stage << " " << std::setw(3) << static_cast<int>(stageProgress + 0.5)
              << "% ] " << operation << " " << std::setw(3)
              << static_cast<int>(operationProgress + 0.5) << "%" << std::endl;
  }
};

class MyLogger : public IVHACD::IUserLogger {
 public:
  explicit MyLogger(const std::string& file_name) {
    if (!file_name.empty()) file_.open(file_name.c_str());
  }
  void Log(const char* const msg) override {
    if (file_.is_open()) {
      file_ << msg << "\n";
      file_.flush();
    }
  }

 private:
  std::ofstream file_;
};

// A minimal OBJ reader: `v x y z` and polygonal `f` lines (1-based or negative indices).
static bool LoadObj(const char* path, std::vector<float>* points, std::vector<int>* triangles) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      float x = 0, y = 0, z = 0;
      s >> x >> y >> z;
      points->insert(points->end(), {x, y, z});
    } else if (tag == "f") {
      std::vector<int> face;
      std::string tok;
      while (s >> tok) {
        long v = std::strtol(tok.c_str(), nullptr, 10);
        if (v < 0) v += static_cast<long>(points->size() / 3) + 1;
        face.push_back(static_cast<int>(v - 1));
      }
      for (size_t k = 1; k + 1 < face.size(); ++k)
        triangles->insert(triangles->end(), {face[0], face[k], face[k + 1]});
    }
  }
  return true;
}

static void MakeTorus(std::vector<float>* points, std::vector<int>* triangles) {
  const int nu = 48, nv = 24;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      points->push_back(static_cast<float>((1.0 + 0.3 * std::cos(v)) * std::cos(u)));
      points->push_back(static_cast<float>((1.0 + 0.3 * std::cos(v)) * std::sin(u)));
      points->push_back(static_cast<float>(0.3 * std::sin(v)));
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      triangles->insert(triangles->end(), {a, b, c, a, c, d});
    }
}

// The example links the vhacd library alone, so it answers --help and --version by hand, in the
// form every hullpack program uses (tools/common/cli_args.h).
int HelpOrVersion(int argc, char* argv[]) {
  if (argc < 2) return -1;
  const std::string a = argv[1];
  if (a == "-h" || a == "--help") {
    std::cout << "usage: vhacd_example [MESH.obj [LOG.txt]]\n"
                 "The V-HACD 2.0 library example on the IVHACD facade: decomposes MESH.obj (or a "
                 "torus built\nin code) and prints the hulls' points and triangles.\n"
                 "options:\n"
                 "  -h, --help                print this help and exit\n"
                 "  --version                 print the version and exit\n";
    return 0;
  }
  if (a == "--version") {
    std::cout << "vhacd_example (hullpack) " << HULLPACK_VERSION << "\n";
    return 0;
  }
  if (argc > 3 || (a.size() > 1 && a[0] == '-')) {
    std::cerr << "vhacd_example: unknown option or extra argument (usage: vhacd_example "
                 "[MESH.obj [LOG.txt]]; see --help)\n";
    return 64;
  }
  return -1;
}

int main(int argc, char* argv[]) {
  if (const int exit_code = HelpOrVersion(argc, argv); exit_code >= 0) return exit_code;
  std::vector<float> points;   // array of coordinates
  std::vector<int> triangles;  // array of indexes
  // load the mesh
  if (argc > 1) {
    if (!LoadObj(argv[1], &points, &triangles)) {
      std::cerr << "cannot read " << argv[1] << "\n";
      return 1;
    }
  } else {
    MakeTorus(&points, &triangles);
  }
  const unsigned int nPoints = static_cast<unsigned int>(points.size() / 3);
  const unsigned int nTriangles = static_cast<unsigned int>(triangles.size() / 3);

  IVHACD::Parameters params;                      // V-HACD parameters
  IVHACD* interfaceVHACD = VHACD::CreateVHACD();  // create interface
  MyCallback myCallback;
  MyLogger myLogger(argc > 2 ? argv[2] : "");
  params.m_logger = &myLogger;
  params.m_callback = &myCallback;

  // compute approximate convex decomposition
  const bool res =
      interfaceVHACD->Compute(points.data(), 3, nPoints, triangles.data(), 3, nTriangles, params);
  if (!res) {
    std::cerr << "decomposition failed: " << interfaceVHACD->GetMessage() << "\n";
    interfaceVHACD->Release();
    return 1;
  }

  // read results
  const unsigned int nConvexHulls =
      interfaceVHACD->GetNConvexHulls();  // Get the number of convex-hulls
  IVHACD::ConvexHull ch;
  for (unsigned int p = 0; p < nConvexHulls; ++p) {
    interfaceVHACD->GetConvexHull(p, ch);  // get the p-th convex-hull information
    std::printf("hull %u: %u points, %u triangles, volume %g\n", p, ch.m_nPoints, ch.m_nTriangles,
                ch.m_volume);
    for (unsigned int v = 0, idx = 0; v < ch.m_nPoints; ++v, idx += 3)
      std::printf("x=%f, y=%f, z=%f\n", ch.m_points[idx], ch.m_points[idx + 1],
                  ch.m_points[idx + 2]);
    for (unsigned int t = 0, idx = 0; t < ch.m_nTriangles; ++t, idx += 3)
      std::printf("i=%d, j=%d, k=%d\n", ch.m_triangles[idx], ch.m_triangles[idx + 1],
                  ch.m_triangles[idx + 2]);
  }

  // release memory
  interfaceVHACD->Clean();
  interfaceVHACD->Release();
  return nConvexHulls > 0 ? 0 : 1;
}
