#include "pipeline/pack.h"

#include <chrono>
#include <cmath>

#include "mesh/validate.h"
#include "pipeline/error_budget.h"
#include "pipeline/hull_stream.h"

namespace hullpack {
namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Bytes of the plain accessors the GLB writer would write for `m`.
size_t PlainGeometryBytes(const Mesh& m) {
  size_t per_vertex = 12;
  if (!m.normals.empty()) per_vertex += 12;
  if (!m.tangents.empty()) per_vertex += 16;
  per_vertex += 8 * m.uv_sets.size();
  if (!m.colors.empty()) per_vertex += 16;
  if (!m.weights.empty()) per_vertex += 16;
  if (!m.joints.empty()) per_vertex += 8;
  const size_t index_size = m.vertex_count() < 65536 ? 2 : 4;
  return m.vertex_count() * per_vertex + m.indices.size() * index_size;
}

// Forwards vhacd's progress into the pack observer's scale.
class DecomposeProgress : public vhacd::Observer {
 public:
  DecomposeProgress(PackObserver* observer, double from, double to, std::string prefix)
      : observer_(observer), from_(from), to_(to), prefix_(std::move(prefix)) {}
  void OnProgress(double overall, double, double, const char* stage, const char*) override {
    if (!observer_) return;
    const int percent = static_cast<int>(overall);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    observer_->OnProgress(from_ + (to_ - from_) * overall / 100.0,
                          prefix_ + "decompose " + std::to_string(percent) + "% (" + stage + ")");
  }
  bool IsCancelled() override { return observer_ && observer_->IsCancelled(); }

 private:
  PackObserver* observer_;
  double from_, to_;
  std::string prefix_;
  int last_percent_ = -1;
};

MeshCodecSettings SettingsFor(const PackOptions& options) {
  MeshCodecSettings s;
  s.stream_type = options.stream_type;
  s.keep_order = options.keep_order;
  s.fast_decode = options.fast_decode;
  s.normal_bits = options.normal_bits;
  s.uv_bits = options.uv_bits;
  return s;
}

// The render mesh's stream: explicit bits (uniform grid, as given), or the smallest stream within
// the error budget.
Result<BudgetedEncoding> EncodeRenderMesh(const Mesh& mesh, const PackOptions& options) {
  MeshCodecSettings s = SettingsFor(options);
  if (options.position_bits <= 0) {
    return EncodeWithinError(mesh, mesh.material_ids, s,
                             options.max_error * BoundingBoxDiagonal(mesh));
  }
  BudgetedEncoding out;
  s.position_bits = options.position_bits;
  auto t = Clock::now();
  Result<EncodedMesh> encoded = EncodeMesh(mesh, mesh.material_ids, s);
  if (!encoded.ok()) return encoded.status();
  out.seconds_encode = Seconds(t);
  t = Clock::now();
  Result<Mesh> decoded =
      DecodeMesh(encoded->stream.data(), encoded->stream.size(), &out.groups, mesh.name);
  if (!decoded.ok())
    return Status(StatusCode::kInternal,
                  "mesh '" + mesh.name + "' does not decode: " + decoded.status().message());
  out.seconds_decode = Seconds(t);
  out.encoded = std::move(encoded.value());
  out.decoded = std::move(decoded.value());
  out.position_bits = s.position_bits;
  out.position_range = s.position_range;
  out.max_error = MaxVertexDistance(mesh, out.decoded);
  out.streams_tried = 1;
  return out;
}

struct PackedMesh {
  Mesh decoded;
  std::vector<Mesh> hulls;
};

Status PackHulls(const Mesh& mesh, const PackOptions& options, PackObserver* observer, double from,
                 double to, const std::string& prefix, PackedStreams& streams, PackedMesh& packed,
                 MeshPackReport& report) {
  const auto t0 = Clock::now();
  DecomposeProgress progress(observer, from, to, prefix);
  Result<HullSet> set = DecomposeMesh(mesh, options.collision, &progress);
  if (!set.ok()) return set.status();
  report.seconds_decompose = Seconds(t0);
  report.hull_count = set->hulls.size();
  report.hull_concavity = set->report.concavity;
  report.hull_iou = set->report.volume_iou;
  if (set->hulls.empty()) return Status::Ok();
  // All hulls of the mesh in one stream, one group per hull, quantized to the hull budget.
  for (const Mesh& hull : set->hulls) report.hull_vertices += hull.vertex_count();
  const double diagonal = BoundingBoxDiagonal(mesh);
  const auto t1 = Clock::now();
  Result<EncodedHulls> encoded =
      EncodeHulls(set->hulls, SettingsFor(options), options.hull_error * diagonal);
  if (!encoded.ok())
    return Status(encoded.status().code(),
                  "mesh '" + mesh.name + "': hulls: " + encoded.status().message());
  report.seconds_hull_encode = Seconds(t1);
  report.hull_quantization_error = diagonal > 0 ? encoded->max_error / diagonal : 0;
  report.hull_position_bits = encoded->position_bits;
  report.hull_position_range = RangeModeName(encoded->position_range);
  report.hull_bytes = encoded->encoded.stream.size();
  const int stream = static_cast<int>(streams.streams.size());
  streams.streams.push_back(std::move(encoded->encoded));
  for (size_t h = 0; h < set->hulls.size(); ++h) {
    Mesh hull = std::move(encoded->decoded[h]);
    hull.name = mesh.name + "_hull_" + std::to_string(h);
    hull.material_ids.clear();
    packed.hulls.push_back(std::move(hull));
    MeshSource source;
    source.stream = stream;
    source.hull = true;
    source.hull_group = static_cast<uint32_t>(h);
    streams.sources.push_back(source);  // order: appended after the render meshes, see below
  }
  return Status::Ok();
}

}  // namespace

Result<PackResult> PackScene(Scene scene, const PackOptions& options, PackObserver* observer) {
  if (!(options.max_error > 0) && options.position_bits <= 0) {
    return Status(StatusCode::kInvalidArgument, "--max-error must be positive (or give --qp)");
  }
  if (!(options.hull_error > 0))
    return Status(StatusCode::kInvalidArgument, "--hull-error must be positive");
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    Status valid = ValidateMesh(scene.meshes[i]);
    if (!valid.ok())
      return Status(valid.code(), "mesh " + std::to_string(i) + ": " + valid.message());
  }
  PackResult result;
  PackReport& report = result.report;
  report.not_kept = scene.dropped;
  auto t0 = Clock::now();
  const PruneReport pruned = LeaveOutUnused(scene, options.prune);
  report.left_out = pruned.lines;
  report.seconds_prune = Seconds(t0);

  t0 = Clock::now();
  PackedStreams render_streams;  // render meshes' streams and sources first
  PackedStreams hull_streams;    // hull sources, re-based below
  std::vector<PackedMesh> packed(scene.meshes.size());
  const size_t n = scene.meshes.size();
  for (size_t i = 0; i < n; ++i) {
    if (observer && observer->IsCancelled()) return Status(StatusCode::kCancelled, "cancelled");
    const Mesh& mesh = scene.meshes[i];
    const std::string prefix =
        "mesh " + std::to_string(i + 1) + "/" + std::to_string(n) + " '" + mesh.name + "': ";
    const double from = double(i) / n, to = double(i + 1) / n;
    MeshPackReport r;
    r.name = mesh.name;
    r.triangles = mesh.triangle_count();
    r.vertices = mesh.vertex_count();
    r.bytes_before = PlainGeometryBytes(mesh);
    if (observer) observer->OnProgress(from, prefix + "encode");
    Result<BudgetedEncoding> encoded = EncodeRenderMesh(mesh, options);
    if (!encoded.ok()) return encoded.status();
    r.position_bits = encoded->position_bits;
    r.position_range = RangeModeName(encoded->position_range);
    r.seconds_encode = encoded->seconds_encode;
    r.seconds_decode = encoded->seconds_decode;
    Mesh& out = packed[i].decoded;
    out = std::move(encoded->decoded);
    out.name = mesh.name;
    out.collides = mesh.collides;
    out.material_ids =
        mesh.material_ids.empty() ? std::vector<uint32_t>() : std::move(encoded->groups);
    r.max_error = encoded->max_error;
    const double diagonal = BoundingBoxDiagonal(mesh);
    r.max_error_fraction = diagonal > 0 ? r.max_error / diagonal : 0;
    r.bytes_after = encoded->encoded.stream.size();
    r.bits_per_vertex = r.vertices ? 8.0 * r.bytes_after / r.vertices : 0;
    MeshSource source;
    source.stream = static_cast<int>(render_streams.streams.size());
    source.grouped = !mesh.material_ids.empty();
    render_streams.streams.push_back(std::move(encoded->encoded));
    render_streams.sources.push_back(source);

    r.no_hulls_reason = WhyNoHulls(mesh, options.collision);
    if (r.no_hulls_reason.empty()) {
      Status s = PackHulls(mesh, options, observer, from, to, prefix, hull_streams, packed[i], r);
      if (!s.ok()) return s;
    }
    report.meshes.push_back(std::move(r));
  }
  report.seconds_meshes = Seconds(t0);

  // The decoded scene: render meshes keep their indices (so nodes stay valid), hulls follow.
  t0 = Clock::now();
  Scene decoded_scene;
  decoded_scene.materials = std::move(scene.materials);
  decoded_scene.images = std::move(scene.images);
  decoded_scene.skins = std::move(scene.skins);
  decoded_scene.nodes = std::move(scene.nodes);
  PackedStreams streams = std::move(render_streams);
  const int hull_stream_base = static_cast<int>(streams.streams.size());
  for (EncodedMesh& s : hull_streams.streams) streams.streams.push_back(std::move(s));
  streams.hulls_of.resize(n);
  for (size_t i = 0; i < n; ++i) decoded_scene.meshes.push_back(std::move(packed[i].decoded));
  size_t hull_source = 0;
  for (size_t i = 0; i < n; ++i) {
    for (Mesh& hull : packed[i].hulls) {
      streams.hulls_of[i].push_back(static_cast<int>(decoded_scene.meshes.size()));
      decoded_scene.meshes.push_back(std::move(hull));
      MeshSource source = hull_streams.sources[hull_source++];
      source.stream += hull_stream_base;
      streams.sources.push_back(source);
    }
  }
  streams.hulls_of.resize(decoded_scene.meshes.size());
  Result<std::vector<uint8_t>> glb = WritePackedGlb(decoded_scene, streams, options.glb);
  if (!glb.ok()) return glb.status();
  result.glb = std::move(glb.value());
  report.output_bytes = result.glb.size();
  report.seconds_write = Seconds(t0);
  if (observer) observer->OnProgress(1.0, "done");
  return result;
}

}  // namespace hullpack
