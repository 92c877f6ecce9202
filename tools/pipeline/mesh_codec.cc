#include "pipeline/mesh_codec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "pipeline/codec_weld.h"

namespace hullpack {
namespace {

o3dgc::FloatAttributeView FloatView(const std::vector<float>& values, uint32_t dimension,
                                    o3dgc::Semantic semantic, int bits) {
  o3dgc::FloatAttributeView v;
  v.data = values.data();
  v.stride = dimension * sizeof(float);
  v.dimension = dimension;
  v.semantic = semantic;
  v.bits = bits;
  return v;
}

}  // namespace

Status MakeCodecInput(const Mesh& input, const std::vector<uint32_t>& groups,
                      const MeshCodecSettings& s, CodecInput* in) {
  in->welded.reset();
  if (!s.keep_order) in->welded = WeldNormalsStoredAlike(input, s.normal_bits);
  const Mesh& mesh = in->welded ? *in->welded : input;
  EncodedMesh& out = in->attributes;
  out.gltf_attributes.clear();
  out.gltf_targets.clear();
  in->view = o3dgc::MeshView();
  o3dgc::MeshView& view = in->view;
  view.positions = mesh.positions.data();
  view.position_stride = 3 * sizeof(float);
  view.num_vertices = mesh.vertex_count();
  view.indices = mesh.indices.data();
  view.num_triangles = mesh.triangle_count();
  int id = 0;
  out.gltf_attributes.emplace_back("POSITION", id++);
  if (!mesh.normals.empty()) {
    view.normals = mesh.normals.data();
    view.normal_stride = 3 * sizeof(float);
    out.gltf_attributes.emplace_back("NORMAL", id++);
  }
  for (size_t k = 0; k < mesh.uv_sets.size(); ++k) {
    // By default one range for u and v (square cells), as Draco and glTF quantize them: u and v
    // are lengths in the same texture, so a texel needs the same step on both. One range per axis
    // spent more bits on the shorter axis, and skewed the shape-based prediction, whose
    // perpendicular in UV space is only one where the cells are square.
    o3dgc::FloatAttributeView uv =
        FloatView(mesh.uv_sets[k], 2, o3dgc::Semantic::kTexCoord, s.uv_bits);
    uv.range = s.uv_range;
    view.float_attributes.push_back(uv);
    out.gltf_attributes.emplace_back("TEXCOORD_" + std::to_string(k), id++);
  }
  if (!mesh.colors.empty()) {
    view.float_attributes.push_back(
        FloatView(mesh.colors, 4, o3dgc::Semantic::kColor, s.color_bits));
    out.gltf_attributes.emplace_back("COLOR_0", id++);
  }
  if (!mesh.weights.empty()) {
    // Skin weights are constant over large regions: the previous vertex predicts them better than
    // a parallelogram does. One range for the four (all in [0, 1]), as glTF's Draco extension has.
    o3dgc::FloatAttributeView w =
        FloatView(mesh.weights, 4, o3dgc::Semantic::kWeight, s.weight_bits);
    w.prediction = o3dgc::Prediction::kDifferential;
    w.range = o3dgc::RangeMode::kUniform;
    view.float_attributes.push_back(w);
    out.gltf_attributes.emplace_back("WEIGHTS_0", id++);
  }
  if (!mesh.tangents.empty()) {
    view.float_attributes.push_back(
        FloatView(mesh.tangents, 4, o3dgc::Semantic::kGeneric, s.tangent_bits));
    out.gltf_attributes.emplace_back("TANGENT", id++);
  }
  if (!mesh.morph_targets.empty()) {
    const double position_step =
        PositionRange(mesh) / (std::ldexp(1.0, std::clamp(s.position_bits, 1, 30)) - 1.0);
    const double error = s.morph_error > 0 ? s.morph_error : std::sqrt(3.0) / 2 * position_step;
    for (const MorphTarget& t : mesh.morph_targets) {
      // One range for the three offsets (cubic cells, as the positions have).
      float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
      for (size_t i = 0; i < t.positions.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], t.positions[i]);
        hi[i % 3] = std::max(hi[i % 3], t.positions[i]);
      }
      const double range = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
      o3dgc::FloatAttributeView offsets =
          FloatView(t.positions, 3, o3dgc::Semantic::kGeneric,
                    range > 0 ? PositionBitsForMaxError(range, error) : 1);
      offsets.range = o3dgc::RangeMode::kUniform;
      view.float_attributes.push_back(offsets);
      out.gltf_targets.push_back({{"POSITION", id++}});
      if (!t.normals.empty()) {
        o3dgc::FloatAttributeView normals =
            FloatView(t.normals, 3, o3dgc::Semantic::kGeneric, s.normal_bits);
        normals.range = o3dgc::RangeMode::kUniform;
        view.float_attributes.push_back(normals);
        out.gltf_targets.back().emplace_back("NORMAL", id++);
      }
    }
  }
  std::vector<int32_t>& joints = in->joints;
  joints.assign(mesh.joints.begin(), mesh.joints.end());
  if (!joints.empty()) {
    o3dgc::IntAttributeView j;
    j.data = joints.data();
    j.dimension = 4;
    j.semantic = o3dgc::Semantic::kJointId;
    view.int_attributes.push_back(j);
    out.gltf_attributes.emplace_back("JOINTS_0", id++);
  }
  if (!groups.empty()) {
    if (groups.size() != mesh.triangle_count()) {
      return Status(StatusCode::kInvalidArgument,
                    "triangle groups: " + std::to_string(groups.size()) + " for " +
                        std::to_string(mesh.triangle_count()) + " triangles");
    }
    view.triangle_groups = groups.data();
  }
  o3dgc::EncodeParams& params = in->params;
  params = o3dgc::EncodeParams();
  params.stream_type = s.stream_type;
  params.keep_order = s.keep_order;
  params.keep_degenerate_triangles = s.keep_degenerate_triangles;
  params.fast_decode = s.fast_decode;
  params.max_compression = s.max_compression;
  params.position_bits = s.position_bits;
  params.position_range = s.position_range;
  params.position_box = s.position_box;
  params.normal_bits = s.normal_bits;
  params.progress = s.progress;
  return Status::Ok();
}

bool UvExtentsDiffer(const Mesh& mesh) {
  for (const std::vector<float>& uv : mesh.uv_sets) {
    if (uv.size() < 2) continue;
    float lo[2] = {uv[0], uv[1]}, hi[2] = {uv[0], uv[1]};
    for (size_t i = 0; i + 1 < uv.size(); i += 2) {
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], uv[i + k]);
        hi[k] = std::max(hi[k], uv[i + k]);
      }
    }
    if (hi[0] - lo[0] != hi[1] - lo[1]) return true;
  }
  return false;
}

Status EncoderStatus(o3dgc::Status st, const std::string& mesh_name) {
  if (st == o3dgc::Status::kOk) return Status::Ok();
  if (st == o3dgc::Status::kCancelled) return Status(StatusCode::kCancelled, "cancelled");
  return Status(StatusCode::kInvalidMesh,
                std::string("mesh '") + mesh_name + "': encoder: " + o3dgc::StatusName(st));
}

namespace {

Result<EncodedMesh> EncodeWithUvRange(const Mesh& mesh, const std::vector<uint32_t>& groups,
                                      const MeshCodecSettings& s) {
  CodecInput in;
  Status status = MakeCodecInput(mesh, groups, s, &in);
  if (!status.ok()) return status;
  EncodedMesh out = std::move(in.attributes);
  status = EncoderStatus(o3dgc::Encode(in.view, in.params, &out.stream, &out.info), mesh.name);
  if (!status.ok()) return status;
  return out;
}

}  // namespace

Result<EncodedMesh> EncodeMesh(const Mesh& mesh, const std::vector<uint32_t>& groups,
                               const MeshCodecSettings& s) {
  Result<EncodedMesh> out = EncodeWithUvRange(mesh, groups, s);
  if (!out.ok() || s.uv_range != o3dgc::RangeMode::kUniform || !UvExtentsDiffer(mesh)) return out;
  // Per-axis cells are no larger than uniform ones, and on UVs that sit on a few values at the
  // ends of their ranges (palette textures) its clamped predictions hit them exactly.
  MeshCodecSettings per_axis = s;
  per_axis.uv_range = o3dgc::RangeMode::kPerAxis;
  Result<EncodedMesh> other = EncodeWithUvRange(mesh, groups, per_axis);
  if (other.ok() && other->stream.size() < out->stream.size()) return other;
  return out;
}

Result<Mesh> DecodeMesh(const uint8_t* data, size_t size, std::vector<uint32_t>* groups,
                        const std::string& name, o3dgc::StreamInfo* info,
                        const std::vector<std::vector<std::pair<std::string, int>>>* targets) {
  o3dgc::DecodedMesh d;
  o3dgc::StreamInfo local_info;
  if (!info) info = &local_info;
  const o3dgc::Status st = DecodePackedStream(data, size, &d, info);
  if (st != o3dgc::Status::kOk) {
    return Status(StatusCode::kParseError,
                  name + ": compressed mesh stream: " + o3dgc::StatusName(st));
  }
  // The original Open3DGC tool coded texture coordinates as OBJ has them (v up); the scene model,
  // like glTF, has v down.
  const bool obj_uvs = info->format == o3dgc::StreamFormat::kOpen3dgc2013;
  Mesh m;
  const size_t n = d.num_vertices();
  // Morph-target offsets first: they are generic attributes, which only the caller can name.
  const size_t first_float_id = d.normals.empty() ? 1 : 2;
  std::vector<bool> is_target(d.float_attributes.size(), false);
  for (size_t t = 0; targets && t < targets->size(); ++t) {
    MorphTarget target;
    for (const auto& [attribute, id] : (*targets)[t]) {
      const size_t k = static_cast<size_t>(id) - first_float_id;
      if (id < static_cast<int>(first_float_id) || k >= d.float_attributes.size() ||
          d.float_attributes[k].dimension != 3 || d.float_attributes[k].values.size() != 3 * n) {
        return Status(StatusCode::kParseError, name + ": morph target " + std::to_string(t) + " " +
                                                   attribute +
                                                   " is not a 3-component stream attribute");
      }
      is_target[k] = true;
      (attribute == "NORMAL" ? target.normals : target.positions) =
          std::move(d.float_attributes[k].values);
    }
    m.morph_targets.push_back(std::move(target));
  }
  m.positions = std::move(d.positions);
  m.indices = std::move(d.indices);
  m.normals = std::move(d.normals);
  for (size_t k = 0; k < d.float_attributes.size(); ++k) {
    o3dgc::DecodedFloatAttribute& a = d.float_attributes[k];
    if (is_target[k] || a.values.size() != n * a.dimension) continue;
    if (a.semantic == o3dgc::Semantic::kTexCoord && a.dimension == 2) {
      if (obj_uvs) {
        for (size_t i = 1; i < a.values.size(); i += 2) a.values[i] = 1.0f - a.values[i];
      }
      m.uv_sets.push_back(std::move(a.values));
    } else if (a.semantic == o3dgc::Semantic::kColor && a.dimension == 4) {
      m.colors = std::move(a.values);
    } else if (a.semantic == o3dgc::Semantic::kWeight && a.dimension == 4) {
      m.weights = std::move(a.values);
    } else if (a.semantic == o3dgc::Semantic::kGeneric && a.dimension == 4) {
      m.tangents = std::move(a.values);
    }
  }
  for (const o3dgc::DecodedIntAttribute& a : d.int_attributes) {
    if (a.semantic != o3dgc::Semantic::kJointId || a.dimension != 4 || a.values.size() != n * 4)
      continue;
    m.joints.resize(a.values.size());
    for (size_t i = 0; i < a.values.size(); ++i) {
      const int32_t j = a.values[i];
      if (j < 0 || j > 65535)
        return Status(StatusCode::kParseError,
                      name + ": joint index " + std::to_string(j) + " out of range");
      m.joints[i] = static_cast<uint16_t>(j);
    }
  }
  if (groups) *groups = std::move(d.triangle_groups);
  return m;
}

Mesh ExtractGroup(const Mesh& mesh, const std::vector<uint32_t>& groups, uint32_t group) {
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> new_index(mesh.vertex_count(), kUnused);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (groups[t] != group) continue;
    for (int k = 0; k < 3; ++k) new_index[mesh.indices[t * 3 + k]] = 0;
  }
  std::vector<uint32_t> kept;
  for (uint32_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] == kUnused) continue;
    new_index[v] = static_cast<uint32_t>(kept.size());
    kept.push_back(v);
  }
  Mesh out;
  out.name = mesh.name;
  auto gather = [&](const std::vector<float>& src, size_t width, std::vector<float>& dst) {
    if (src.empty()) return;
    dst.resize(kept.size() * width);
    for (size_t i = 0; i < kept.size(); ++i)
      std::copy_n(&src[kept[i] * width], width, &dst[i * width]);
  };
  gather(mesh.positions, 3, out.positions);
  gather(mesh.normals, 3, out.normals);
  gather(mesh.tangents, 4, out.tangents);
  gather(mesh.colors, 4, out.colors);
  gather(mesh.weights, 4, out.weights);
  for (const MorphTarget& t : mesh.morph_targets) {
    out.morph_targets.push_back({t.name, {}, {}});
    gather(t.positions, 3, out.morph_targets.back().positions);
    gather(t.normals, 3, out.morph_targets.back().normals);
  }
  out.morph_weights = mesh.morph_weights;
  for (const auto& uv : mesh.uv_sets) {
    out.uv_sets.emplace_back();
    gather(uv, 2, out.uv_sets.back());
  }
  if (!mesh.joints.empty()) {
    out.joints.resize(kept.size() * 4);
    for (size_t i = 0; i < kept.size(); ++i)
      std::copy_n(&mesh.joints[kept[i] * 4], 4, &out.joints[i * 4]);
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (groups[t] != group) continue;
    for (int k = 0; k < 3; ++k) out.indices.push_back(new_index[mesh.indices[t * 3 + k]]);
    if (!mesh.material_ids.empty()) out.material_ids.push_back(mesh.material_ids[t]);
  }
  return out;
}

int PositionBitsForMaxError(double range, double max_error) {
  if (!(range > 0) || !(max_error > 0) || !std::isfinite(range) || !std::isfinite(max_error))
    return 14;
  // Uniform cells of side range / (2^b - 1); the farthest a point lies from its cell centre is
  // half the cell diagonal: sqrt(3) / 2 * side.
  const double cells = std::sqrt(3.0) * range / (2.0 * max_error);
  const int bits = static_cast<int>(std::ceil(std::log2(cells + 1.0)));
  return std::clamp(bits, 1, 30);
}

std::array<double, 3> PositionExtent(const Mesh& mesh) {
  if (mesh.positions.empty()) return {0, 0, 0};
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = mesh.positions[k];
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    lo[i % 3] = std::min<double>(lo[i % 3], mesh.positions[i]);
    hi[i % 3] = std::max<double>(hi[i % 3], mesh.positions[i]);
  }
  return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

double PositionRange(const Mesh& mesh) {
  const std::array<double, 3> e = PositionExtent(mesh);
  return std::max({e[0], e[1], e[2]});
}

double BoundingBoxDiagonal(const Mesh& mesh) {
  const std::array<double, 3> e = PositionExtent(mesh);
  return std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}

namespace {

// Nearest-vertex queries on a uniform grid sized for about one point per cell.
class VertexGrid {
 public:
  explicit VertexGrid(const std::vector<float>& p) : p_(p) {
    const size_t n = p.size() / 3;
    for (int k = 0; k < 3; ++k) lo_[k] = hi_[k] = n ? p[k] : 0;
    for (size_t i = 0; i < p.size(); ++i) {
      lo_[i % 3] = std::min<double>(lo_[i % 3], p[i]);
      hi_[i % 3] = std::max<double>(hi_[i % 3], p[i]);
    }
    const double extent = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2], 1e-30});
    res_ = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(n))));
    cell_ = extent / res_;
    for (size_t i = 0; i < n; ++i) cells_[Key(Cell(&p[i * 3]))].push_back(static_cast<uint32_t>(i));
  }

  double Nearest(const float* q) const {
    const std::array<int64_t, 3> c = Cell(q);
    double best = std::numeric_limits<double>::infinity();
    // Grow the searched shell until the best hit is closer than the shell's inner distance.
    for (int64_t r = 0; r <= res_ + 1; ++r) {
      for (int64_t x = c[0] - r; x <= c[0] + r; ++x) {
        for (int64_t y = c[1] - r; y <= c[1] + r; ++y) {
          for (int64_t z = c[2] - r; z <= c[2] + r; ++z) {
            if (std::max({std::llabs(x - c[0]), std::llabs(y - c[1]), std::llabs(z - c[2])}) != r)
              continue;
            auto it = cells_.find(Key({x, y, z}));
            if (it == cells_.end()) continue;
            for (uint32_t i : it->second) {
              const double dx = double(p_[i * 3]) - q[0], dy = double(p_[i * 3 + 1]) - q[1],
                           dz = double(p_[i * 3 + 2]) - q[2];
              best = std::min(best, dx * dx + dy * dy + dz * dz);
            }
          }
        }
      }
      if (best <= (r * cell_) * (r * cell_)) break;
    }
    if (!std::isfinite(best)) {  // the query lies far outside the grid: look at every point
      for (size_t i = 0; i < p_.size() / 3; ++i) {
        const double dx = double(p_[i * 3]) - q[0], dy = double(p_[i * 3 + 1]) - q[1],
                     dz = double(p_[i * 3 + 2]) - q[2];
        best = std::min(best, dx * dx + dy * dy + dz * dz);
      }
    }
    return std::sqrt(best);
  }

 private:
  std::array<int64_t, 3> Cell(const float* q) const {
    std::array<int64_t, 3> c;
    for (int k = 0; k < 3; ++k) {
      const double t = (double(q[k]) - lo_[k]) / cell_;
      c[k] = static_cast<int64_t>(std::floor(std::clamp(t, -1e9, 1e9)));
    }
    return c;
  }
  static uint64_t Key(const std::array<int64_t, 3>& c) {
    return (static_cast<uint64_t>(c[0] & 0x1FFFFF) << 42) |
           (static_cast<uint64_t>(c[1] & 0x1FFFFF) << 21) | static_cast<uint64_t>(c[2] & 0x1FFFFF);
  }
  const std::vector<float>& p_;
  double lo_[3], hi_[3], cell_ = 1;
  int res_ = 1;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

double OneWay(const Mesh& from, const Mesh& to) {
  if (from.positions.empty() || to.positions.empty()) return 0;
  const VertexGrid grid(to.positions);
  double worst = 0;
  for (size_t i = 0; i < from.vertex_count(); ++i)
    worst = std::max(worst, grid.Nearest(&from.positions[i * 3]));
  return worst;
}

}  // namespace

double MaxVertexDistance(const Mesh& a, const Mesh& b) {
  return std::max(OneWay(a, b), OneWay(b, a));
}

}  // namespace hullpack
