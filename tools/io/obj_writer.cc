#include "io/obj_writer.h"

#include "io/text_writer.h"

namespace hullpack {
namespace {

constexpr size_t kPieceBytes = size_t{1} << 20;

// Writes meshes as OBJ text, handing it to `sink` piece by piece.
class ObjText {
 public:
  explicit ObjText(const TextSink& sink) : sink_(sink) { w_ << "# written by hullpack\n"; }

  // `materials`: the scene's, for `usemtl` names; null writes no `usemtl`.
  void AddMesh(const Mesh& m, size_t index, const std::vector<Material>* materials) {
    w_ << "o " << (m.name.empty() ? "mesh_" + std::to_string(index) : m.name) << '\n';
    const size_t n = m.vertex_count();
    const bool colors = m.colors.size() == n * 4 && n > 0;
    const bool uvs = !m.uv_sets.empty() && m.uv_sets[0].size() == n * 2 && n > 0;
    const bool normals = m.normals.size() == n * 3 && n > 0;
    for (size_t i = 0; i < n; ++i) {
      w_ << "v " << m.positions[i * 3] << ' ' << m.positions[i * 3 + 1] << ' '
         << m.positions[i * 3 + 2];
      if (colors)
        w_ << ' ' << m.colors[i * 4] << ' ' << m.colors[i * 4 + 1] << ' ' << m.colors[i * 4 + 2];
      w_ << '\n';
      Hand();
    }
    if (uvs) {
      for (size_t i = 0; i < n; ++i) {
        w_ << "vt " << m.uv_sets[0][i * 2] << ' ' << (1.0f - m.uv_sets[0][i * 2 + 1]) << '\n';
        Hand();
      }
    }
    if (normals) {
      for (size_t i = 0; i < n; ++i) {
        w_ << "vn " << m.normals[i * 3] << ' ' << m.normals[i * 3 + 1] << ' '
           << m.normals[i * 3 + 2] << '\n';
        Hand();
      }
    }
    const bool by_material = materials != nullptr && m.material_ids.size() == m.triangle_count();
    uint32_t current = 0xFFFFFFFFu;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      if (by_material && m.material_ids[t] != current) {
        current = m.material_ids[t];
        w_ << "usemtl "
           << (current < materials->size() && !(*materials)[current].name.empty()
                   ? (*materials)[current].name
                   : "material_" + std::to_string(current))
           << '\n';
      }
      w_ << 'f';
      for (int k = 0; k < 3; ++k) {
        const uint64_t i = base_ + m.indices[t * 3 + k];
        w_ << ' ' << i;
        if (uvs || normals) {
          w_ << '/';
          if (uvs) w_ << i;
          if (normals) w_ << '/' << i;
        }
      }
      w_ << '\n';
      Hand();
    }
    base_ += n;  // OBJ indices are global and 1-based
  }

  // Hands over the rest of the text.
  void Finish() {
    if (!w_.str().empty()) sink_(w_.str());
    w_.str().clear();
  }

 private:
  void Hand() {
    if (w_.str().size() < kPieceBytes) return;
    sink_(w_.str());
    w_.str().clear();
  }

  const TextSink& sink_;
  TextWriter w_;
  uint64_t base_ = 1;
};

}  // namespace

std::string EncodeObj(const Scene& scene) {
  std::string text;
  EncodeObj(scene, [&](std::string_view piece) { text.append(piece.data(), piece.size()); });
  return text;
}

void EncodeObj(const Scene& scene, const TextSink& sink) {
  ObjText text(sink);
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi)
    text.AddMesh(scene.meshes[mi], mi, &scene.materials);
  text.Finish();
}

void EncodeObjMesh(const Mesh& mesh, const TextSink& sink) {
  ObjText text(sink);
  text.AddMesh(mesh, 0, nullptr);
  text.Finish();
}

}  // namespace hullpack
