// IVHACD: the V-HACD 2.0 style interface from the author's blog, implemented on vhacd::Decompose.
//
//   IVHACD::Parameters params;
//   IVHACD* v = CreateVHACD();
//   bool ok = v->Compute(points, 3, nPoints, triangles, 3, nTriangles, params);
//   for (unsigned p = 0; p < v->GetNConvexHulls(); ++p) { IVHACD::ConvexHull ch;
//   v->GetConvexHull(p, ch); } v->Clean(); v->Release();
//
// Compute() returns false on any error (see GetStatus()/GetMessage() for why) and on cancellation.
// Cancel() may be called from any thread while Compute() runs (a Cancel() before Compute() starts
// is forgotten: Compute() clears the flag). Strides are in elements (>= 3).
#ifndef VHACD_IVHACD_H_
#define VHACD_IVHACD_H_

#include "vhacd/vhacd.h"

namespace VHACD {

class IVHACD {
 public:
  class IUserCallback {
   public:
    virtual ~IUserCallback() {}
    // Percentages in [0, 100].
    virtual void Update(const double overallProgress, const double stageProgress,
                        const double operationProgress, const char* const stage,
                        const char* const operation) = 0;
  };

  class IUserLogger {
   public:
    virtual ~IUserLogger() {}
    virtual void Log(const char* const msg) = 0;
  };

  // Valid while the IVHACD object lives and until the next Compute() or Clean().
  class ConvexHull {
   public:
    double* m_points = nullptr;
    int* m_triangles = nullptr;
    unsigned int m_nPoints = 0;
    unsigned int m_nTriangles = 0;
    double m_volume = 0.0;
    double m_center[3] = {0.0, 0.0, 0.0};
  };

  class Parameters {
   public:
    Parameters() { Init(); }
    void Init() {
      m_resolution = 100000;
      m_depth = 20;
      m_concavity = 0.0025;
      m_planeDownsampling = 4;
      m_convexhullDownsampling = 4;
      m_alpha = 0.05;
      m_beta = 0.05;
      m_gamma = 0.00125;
      m_pca = 0;
      m_mode = 0;
      m_maxNumVerticesPerCH = 64;
      m_minVolumePerCH = 0.0001;
      m_maxConvexHulls = 0;
      m_numThreads = 0;
      m_callback = nullptr;
      m_logger = nullptr;
    }
    double m_concavity, m_alpha, m_beta, m_gamma, m_minVolumePerCH;
    IUserCallback* m_callback;
    IUserLogger* m_logger;
    unsigned int m_resolution, m_maxNumVerticesPerCH, m_depth, m_planeDownsampling,
        m_convexhullDownsampling, m_pca, m_mode, m_maxConvexHulls, m_numThreads;
  };

  virtual void Cancel() = 0;
  virtual bool Compute(const float* const points, const unsigned int stridePoints,
                       const unsigned int countPoints, const int* const triangles,
                       const unsigned int strideTriangles, const unsigned int countTriangles,
                       const Parameters& params) = 0;
  virtual bool Compute(const double* const points, const unsigned int stridePoints,
                       const unsigned int countPoints, const int* const triangles,
                       const unsigned int strideTriangles, const unsigned int countTriangles,
                       const Parameters& params) = 0;
  virtual unsigned int GetNConvexHulls() const = 0;
  // Fills `ch`; leaves it empty when index is out of range.
  virtual void GetConvexHull(const unsigned int index, ConvexHull& ch) const = 0;
  virtual void Clean() = 0;    // frees the results
  virtual void Release() = 0;  // destroys the object (calls Clean)
  virtual vhacd::Status GetStatus() const = 0;
  virtual const char* GetMessage() const = 0;
  virtual const vhacd::Report& GetReport() const = 0;

 protected:
  virtual ~IVHACD() {}
};

IVHACD* CreateVHACD();

}  // namespace VHACD

#endif  // VHACD_IVHACD_H_
