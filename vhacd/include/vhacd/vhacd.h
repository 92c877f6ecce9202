// vhacd: approximate convex decomposition of triangle meshes (V-HACD 2.0 style).
//
// The library depends only on Eigen3 and the C++ standard library (threads included). It never
// throws across this API, never asserts on user input and never returns NaN or Inf: every failure
// is reported as a Status value in the Result.
//
// Pipeline (see Decompose):
//   1. validation and normalization (translate to the bounding-box centre, scale to a unit box,
//      optional PCA rotation);
//   2. voxelization at about `resolution` voxels: a voxel is a *surface* voxel when a triangle
//      overlaps its closed box (exact separating-axis test, evaluated only on the voxels of each
//      triangle's bounding box);
//   3. interior fill. A non-surface voxel is *inside* when either
//        (a) it cannot be reached from outside the grid through non-surface voxels (flood fill), or
//        (b) at least 4 of the 6 axis-aligned rays from its centre (+x,-x,+y,-y,+z,-z) cross the
//            surface an odd number of times.
//      Rule (a) is exact for closed surfaces, including overlapping closed components; rule (b)
//      keeps meshes with small holes (scans such as the Stanford bunny, open at the base) solid,
//      because a ray only escapes through a hole it is aimed at. Crossings are counted with a
//      tie-breaking rule so that a ray through a shared edge or vertex is counted once.
//      Rule (b) does not apply where a ball of diameter `min_opening` x diagonal reaches from
//      outside the grid between the surface voxels (the cavity of an open pot, cup or lidless
//      box), nor to the thin left-over regions the ball leaves in the corners of such a cavity
//      (fewer voxels than the ball radius times their faces shared with the swept region).
//   4. recursive clipping, up to `depth` levels: each part is cut while its concavity
//      (volume of its hull - its volume) / (volume of the hull of the whole voxel set) exceeds
//      `concavity`, or while its hull sticks out of the solid by more than `max_distance` (measured
//      with a Euclidean distance transform of the voxel grid). The cut is the axis-aligned plane
//      minimising
//        concavity(left) + concavity(right) + alpha * balance + beta * revolution-axis penalty,
//      searched every `plane_downsampling` voxels on hulls of every `convexhull_downsampling`-th
//      voxel line, then refined voxel by voxel (exact hulls) around the best plane; when that cut
//      removes no concavity although the coarse estimate said it would (a feature thinner than the
//      downsampling, missed by the sampled lines), every plane is searched again with exact hulls;
//   5. one convex hull per part: the input surface clipped to the part's box plus the corners of
//   its
//      interior voxels, so hulls hug the mesh, not the voxels (a flat part falls back to its
//      voxels);
//   6. simplification of each hull to at most `max_vertices_per_hull` vertices, greedily keeping
//      the point with the largest volume increment and stopping early when the increment falls
//      below `min_volume_per_hull` times the volume of the hull of the whole voxel set (but never
//      dropping a point that adds more than 0.2 % of its own hull);
//   7. merge: the pair of hulls whose merged hull adds the least volume (relative to the hull of
//      the whole voxel set) is merged while that cost is below `gamma` and the merged hull does not
//      stick out by more than `max_distance`; then, while more than `max_convex_hulls` hulls remain
//      (when that budget is non-zero), the pair whose merged hull sticks out least is merged;
//      merged hulls are simplified again;
//   8. an error report (see Report).
//
// Quality: with the defaults the hulls stick out of the input by about max_distance (3 % of the
// bounding-box diagonal) at most, at the cost of more hulls on very concave shapes; set
// max_distance = 0 for the pure V-HACD 2.0 behaviour (volume criterion only).
//
// Determinism: the output is identical for any `num_threads` and from run to run (work is
// partitioned into fixed tasks whose results are combined in a fixed order).
#ifndef VHACD_VHACD_H_
#define VHACD_VHACD_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vhacd {

#define VHACD_VERSION 20000  // major * 10000 + minor * 100 + patch

enum class Status {
  kOk = 0,
  kInvalidParameter,  // a Parameters field is out of its documented range
  kEmptyMesh,         // no points or no triangles (after dropping degenerate triangles)
  kInvalidMesh,       // NaN/Inf coordinate, null pointer, bad stride, zero-size bounding box
  kIndexOutOfRange,   // a triangle refers to a point that does not exist
  kUnsupported,       // a valid request this build cannot honour
  kCancelled,         // Observer::IsCancelled() returned true
  kOutOfMemory,
  kInternalError,
};

// "ok", "invalid parameter", ...
const char* StatusName(Status status);

enum class Mode : int {
  kVoxel = 0,  // voxel-based decomposition
  // Tetrahedron-based decomposition: every voxel is split into 5 tetrahedra and those of the
  // surface voxels are trimmed to the input surface, so the clipping stage measures volumes and
  // hulls on a solid that follows the surface within a voxel (slower than kVoxel).
  kTetrahedron = 1,
};

// Cut planes along a part's own axes besides the voxel slices (Parameters::oriented_cuts).
enum class OrientedCuts : int {
  kOff = 0,     // voxel slices only
  kAuto = 1,    // both ways, the closer result kept
  kAlways = 2,  // oriented planes wherever they beat the slices
};

// Parameters with the defaults and ranges of V-HACD 2.0. Ranges are inclusive.
struct Parameters {
  uint32_t resolution = 100000;          // number of voxels of the grid [10000, 64000000]
  uint32_t depth = 20;                   // maximum clipping depth [1, 32]
  double concavity = 0.0025;             // maximum concavity of a part [0, 1]
  uint32_t plane_downsampling = 4;       // coarse plane search step, in voxels [1, 16]
  uint32_t convexhull_downsampling = 4;  // hull precision during the plane search [1, 16]
  double alpha = 0.05;                   // weight of the balance term [0, 1]
  double beta = 0.05;                    // weight of the revolution-axis term [0, 1]
  double gamma = 0.00125;                // maximum concavity of a merge [0, 1]
  bool pca = false;                      // align the mesh on its principal axes first
  Mode mode = Mode::kVoxel;
  uint32_t max_vertices_per_hull = 64;  // [4, 1024]
  double min_volume_per_hull = 0.0001;  // adaptive hull sampling [0, 0.01]
  uint32_t max_convex_hulls = 0;        // hull budget; 0 = no budget [0, 100000]
  // Extension: largest distance a part's hull may stick out of the input solid, as a fraction of
  // the bounding-box diagonal; parts are split further and merges refused beyond it (measured on
  // the voxel grid, so it is only as precise as a voxel). 0 disables it (pure V-HACD 2.0). [0, 1]
  double max_distance = 0.03;
  // Target error: when > 0, parts are split until every hull lies within max_concavity x the
  // bounding-box diagonal of the input surface (the Report's `concavity` measure), then merged
  // while the merged hull stays within it; `concavity`, `gamma` and `max_distance` are then
  // ignored, and the grid is refined (up to 1,000,000 voxels) when max_concavity spans fewer than 3
  // voxels. How far a hull sticks out is measured on the exact input surface as well as on the
  // grid, so targets below a voxel are followed. The report says whether it was reached
  // (target_reached, target_note). For game colliders 0.02 is the recommended setting (closer than
  // the defaults with fewer hulls; see vhacd/README.md). [0, 1]
  double max_concavity = 0.0;
  // Exact hull count: when > 0, the result has exactly this many hulls whenever the voxel set can
  // be cut into that many parts (parts are cut further when the clipping gives fewer, the pairs
  // whose merged hull sticks out least from the exact surface are merged when it gives more). The
  // grid gets at least 6250 voxels per hull (up to 1,000,000; `resolution` when larger), and when
  // that refines it, the requested resolution is run too and the closer result kept (so from 17
  // hulls on a call costs two decompositions). Takes precedence over max_convex_hulls and
  // max_concavity. [0, 100000]
  uint32_t hull_count = 0;
  // With hull_count or max_concavity on a closed input: parts may also be cut along their own axes
  // (principal axes and their bisectors), where that makes the halves' hulls clearly closer to the
  // exact surface. kAuto decomposes with and without them on the same voxels and keeps the result
  // closer by the report (max_concavity: the one reaching D, both doing so the oriented one only
  // when closer with no more hulls), so it is never farther than kOff; much closer on rotated or
  // slanted parts (a rotated L in 2 hulls), at about twice the CPU on a closed mesh (up to 3x on
  // small ones). kAlways uses them alone (greedily, cut by cut). Other settings ignore it.
  OrientedCuts oriented_cuts = OrientedCuts::kAuto;
  // Fill rule for open meshes: a cavity that a ball of this diameter (fraction of the diagonal)
  // can reach from outside stays empty (open containers: pots, cups, lidless boxes); smaller
  // openings (holes in scans) are filled by the parity vote. 0 = parity vote only. [0, 1]
  double min_opening = 0.2;
  uint32_t num_threads = 0;    // 0 = std::thread::hardware_concurrency() [0, 256]
  bool compute_report = true;  // fill Result::report's error measures (costs time)
  // Memory for time: a clean input's points (each used, none repeated, in an order local to the
  // triangles) are read from the view and mapped into the working frame on every read, instead
  // of copied in double precision (24 bytes per point, the largest array of a large mesh's
  // decomposition). The hulls are the same bit for bit; the decomposition takes about twice as
  // long (see vhacd/README.md).
  bool points_in_place = false;

  // The V-HACD 2.0 defaults (same as a default-constructed Parameters).
  static Parameters Default() { return Parameters(); }
  // Finer voxels (400000), lower thresholds (concavity 0.001, gamma 0.0005, max_distance 0.018)
  // and up to 128 vertices per hull: tighter hulls, more of them, about 3x slower.
  static Parameters High();
};

// Returns kOk, or kInvalidParameter with the offending field named in *why (when non-null).
Status ValidateParameters(const Parameters& params, std::string* why);

// A borrowed, read-only triangle mesh. Exactly one of points_f / points_d is non-null. Point i is
// (p[i*point_stride], p[i*point_stride+1], p[i*point_stride+2]); triangle t is
// (indices[t*triangle_stride], ... +1, ... +2). Strides are in elements and must be >= 3.
// Any soup is accepted: open or closed, several components, unoriented, duplicated or two-sided
// faces; degenerate and duplicate triangles are ignored.
struct MeshView {
  const float* points_f = nullptr;
  const double* points_d = nullptr;
  size_t point_count = 0;
  size_t point_stride = 3;
  const uint32_t* indices = nullptr;
  size_t triangle_count = 0;
  size_t triangle_stride = 3;

  static MeshView FromDouble(const double* points, size_t point_count, const uint32_t* indices,
                             size_t triangle_count) {
    MeshView m;
    m.points_d = points;
    m.point_count = point_count;
    m.indices = indices;
    m.triangle_count = triangle_count;
    return m;
  }
  static MeshView FromFloat(const float* points, size_t point_count, const uint32_t* indices,
                            size_t triangle_count) {
    MeshView m;
    m.points_f = points;
    m.point_count = point_count;
    m.indices = indices;
    m.triangle_count = triangle_count;
    return m;
  }
};

// A closed convex polyhedron: counter-clockwise (outward-facing) triangles, every vertex used.
struct ConvexHull {
  std::vector<double> points;       // 3 per vertex
  std::vector<uint32_t> triangles;  // 3 per triangle
  double volume = 0.0;  // clamped to DBL_MAX; underflows to 0 for inputs smaller than ~1e-100
  double center[3] = {0.0, 0.0, 0.0};  // centroid of the solid

  size_t vertex_count() const { return points.size() / 3; }
  size_t triangle_count() const { return triangles.size() / 3; }
};

struct HullReport {
  uint32_t vertex_count = 0;
  double volume = 0.0;
  // (hull volume - volume of the input solid inside the hull) / volume of the input's hull,
  // measured on the voxel centres.
  double concavity = 0.0;
  // Largest distance from this hull's part of the boundary of the union of hulls to the input
  // surface, as a fraction of the diagonal (the hull's share of hausdorff_hulls_to_mesh); -1 when
  // not measured.
  double distance = -1.0;
};

// Error measures of a decomposition. Distances are fractions of the bounding-box diagonal of the
// input; -1 means "not measured" (report disabled, or IoU of an open mesh).
struct Report {
  std::vector<HullReport> hulls;
  bool closed_input = false;  // every edge of the input is shared by exactly two triangles
  double volume_iou = -1.0;   // |solid ∩ hulls| / |solid ∪ hulls| on the voxel centres
  // |solid ∩ hulls| / |solid| on the voxel centres, where the solid is the filled voxel set (see
  // the fill rule above); measured for open meshes too.
  double solid_coverage = -1.0;
  // One-sided Hausdorff distances on samples of both surfaces. mesh -> hulls counts 0 for a mesh
  // point inside a hull; hulls -> mesh uses only points of the boundary of the union of hulls (a
  // hull surface point within 0.2 % of the diagonal of another hull counts as interior: cracks
  // narrower than that between hulls are ignored).
  double hausdorff_mesh_to_hulls = -1.0;
  double hausdorff_hulls_to_mesh = -1.0;
  double concavity = -1.0;   // max of the two Hausdorff distances
  uint64_t voxel_count = 0;  // surface + inside voxels
  uint64_t surface_voxel_count = 0;
  uint64_t tetrahedron_count =
      0;  // mode 1: 5 per interior voxel + the surface voxels' trimmed ones
  uint32_t parts_before_merge = 0;
  // Parameters::max_concavity / hull_count: whether the target was met (always true without a
  // target) and, when not, why (which hulls stay over max_concavity, or how many parts the mesh
  // could give).
  bool target_reached = true;
  std::string target_note;
  uint32_t attempts = 0;  // max_concavity: decompositions tried (each with a tighter split limit)
  // Wall-clock seconds per stage (distance: the distance transform used by max_distance, and the
  // triangle indexes of the exact-surface measures). tetrahedra: mode 1's trimmed tetrahedra of
  // the surface voxels.
  double seconds_voxelize = 0.0, seconds_fill = 0.0, seconds_tetrahedra = 0.0,
         seconds_distance = 0.0, seconds_clip = 0.0, seconds_hulls = 0.0, seconds_merge = 0.0,
         seconds_simplify = 0.0, seconds_report = 0.0, seconds_total = 0.0;
};

struct Result {
  Status status = Status::kOk;
  std::string message;            // human-readable detail for a non-ok status
  std::vector<ConvexHull> hulls;  // empty unless status == kOk
  Report report;

  bool ok() const { return status == Status::kOk; }
};

// Progress, logging and cancellation hooks. All methods may be called from any of the library's
// threads but never concurrently (the library serializes the calls).
class Observer {
 public:
  virtual ~Observer() = default;
  // Percentages in [0, 100]. A run is a sequence of stages made of operations.
  virtual void OnProgress(double overall, double stage, double operation, const char* stage_name,
                          const char* operation_name) {}
  virtual void OnLog(const char* message) {}
  // Polled often (about every millisecond of work); return true to stop: Decompose then returns
  // Status::kCancelled promptly.
  virtual bool IsCancelled() { return false; }
};

// Decomposes `mesh` into convex hulls. `observer` may be null.
Result Decompose(const MeshView& mesh, const Parameters& params, Observer* observer = nullptr);

}  // namespace vhacd

#endif  // VHACD_VHACD_H_
