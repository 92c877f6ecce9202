// The IVHACD facade: converts the blog's arrays and callbacks to vhacd::Decompose and back.
#include <atomic>
#include <limits>
#include <vector>

#include "vhacd/ivhacd.h"

namespace VHACD {
namespace {

class Adapter : public vhacd::Observer {
 public:
  Adapter(IVHACD::IUserCallback* cb, IVHACD::IUserLogger* logger, const std::atomic<bool>* cancel)
      : cb_(cb), logger_(logger), cancel_(cancel) {}
  void OnProgress(double overall, double stage, double operation, const char* stage_name,
                  const char* operation_name) override {
    if (cb_ != nullptr) cb_->Update(overall, stage, operation, stage_name, operation_name);
  }
  void OnLog(const char* message) override {
    if (logger_ != nullptr) logger_->Log(message);
  }
  bool IsCancelled() override { return cancel_->load(); }

 private:
  IVHACD::IUserCallback* cb_;
  IVHACD::IUserLogger* logger_;
  const std::atomic<bool>* cancel_;
};

class VHACDImpl : public IVHACD {
 public:
  void Cancel() override { cancel_.store(true); }

  bool Compute(const float* const points, const unsigned int stridePoints,
               const unsigned int countPoints, const int* const triangles,
               const unsigned int strideTriangles, const unsigned int countTriangles,
               const Parameters& params) override {
    vhacd::MeshView view;
    view.points_f = points;
    return Run(view, stridePoints, countPoints, triangles, strideTriangles, countTriangles, params);
  }
  bool Compute(const double* const points, const unsigned int stridePoints,
               const unsigned int countPoints, const int* const triangles,
               const unsigned int strideTriangles, const unsigned int countTriangles,
               const Parameters& params) override {
    vhacd::MeshView view;
    view.points_d = points;
    return Run(view, stridePoints, countPoints, triangles, strideTriangles, countTriangles, params);
  }

  unsigned int GetNConvexHulls() const override {
    return static_cast<unsigned int>(result_.hulls.size());
  }

  void GetConvexHull(const unsigned int index, ConvexHull& ch) const override {
    ch = ConvexHull();
    if (index >= result_.hulls.size()) return;
    const vhacd::ConvexHull& h = result_.hulls[index];
    ch.m_points = const_cast<double*>(h.points.data());
    ch.m_nPoints = static_cast<unsigned int>(h.vertex_count());
    ch.m_triangles = const_cast<int*>(triangles_[index].data());
    ch.m_nTriangles = static_cast<unsigned int>(h.triangle_count());
    ch.m_volume = h.volume;
    for (int k = 0; k < 3; ++k) ch.m_center[k] = h.center[k];
  }

  void Clean() override {
    result_ = vhacd::Result();
    triangles_.clear();
  }
  void Release() override {
    Clean();
    delete this;
  }
  vhacd::Status GetStatus() const override { return result_.status; }
  const char* GetMessage() const override { return result_.message.c_str(); }
  const vhacd::Report& GetReport() const override { return result_.report; }

 private:
  bool Run(vhacd::MeshView view, unsigned int stridePoints, unsigned int countPoints,
           const int* triangles, unsigned int strideTriangles, unsigned int countTriangles,
           const Parameters& p) {
    Clean();
    cancel_.store(false);
    view.point_count = countPoints;
    view.point_stride = stridePoints;
    view.triangle_count = countTriangles;
    view.triangle_stride = 3;
    // The blog's indices are signed: convert, mapping negatives to an out-of-range index.
    std::vector<uint32_t> indices;
    if (triangles != nullptr && strideTriangles >= 3) {
      indices.resize(static_cast<size_t>(countTriangles) * 3);
      for (size_t t = 0; t < countTriangles; ++t)
        for (int k = 0; k < 3; ++k) {
          const int v = triangles[t * strideTriangles + k];
          indices[t * 3 + k] =
              v < 0 ? std::numeric_limits<uint32_t>::max() : static_cast<uint32_t>(v);
        }
      view.indices = indices.data();
    } else if (strideTriangles < 3) {
      view.triangle_stride = strideTriangles;
    }
    vhacd::Parameters q;
    q.resolution = p.m_resolution;
    q.depth = p.m_depth;
    q.concavity = p.m_concavity;
    q.plane_downsampling = p.m_planeDownsampling;
    q.convexhull_downsampling = p.m_convexhullDownsampling;
    q.alpha = p.m_alpha;
    q.beta = p.m_beta;
    q.gamma = p.m_gamma;
    if (p.m_pca > 1 || p.m_mode > 1) {
      result_.status = vhacd::Status::kInvalidParameter;
      result_.message = "pca and mode must be 0 or 1";
      return false;
    }
    q.pca = p.m_pca != 0;
    q.mode = static_cast<vhacd::Mode>(p.m_mode);
    q.max_vertices_per_hull = p.m_maxNumVerticesPerCH;
    q.min_volume_per_hull = p.m_minVolumePerCH;
    q.max_convex_hulls = p.m_maxConvexHulls;
    q.num_threads = p.m_numThreads;
    Adapter adapter(p.m_callback, p.m_logger, &cancel_);
    result_ = vhacd::Decompose(view, q, &adapter);
    for (const vhacd::ConvexHull& h : result_.hulls)
      triangles_.emplace_back(h.triangles.begin(), h.triangles.end());
    return result_.ok();
  }

  std::atomic<bool> cancel_{false};
  vhacd::Result result_;
  std::vector<std::vector<int>> triangles_;
};

}  // namespace

IVHACD* CreateVHACD() { return new VHACDImpl(); }

}  // namespace VHACD
