#include "robot/hull_files.h"

#include <cmath>
#include <cstring>
#include <vector>

#include "common/file_util.h"
#include "io/obj_writer.h"

namespace hullpack {
namespace {

constexpr size_t kPieceBytes = size_t{1} << 20;

void PutFloat(float value, std::vector<uint8_t>* out) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  for (int i = 0; i < 4; ++i) out->push_back(static_cast<uint8_t>(bits >> (8 * i)));
}

}  // namespace

void EncodeBinaryStl(const Mesh& mesh, const ByteSink& sink) {
  std::vector<uint8_t> out(80, 0);
  const char header[] = "binary STL written by hullpack";
  std::memcpy(out.data(), header, sizeof(header) - 1);
  const uint32_t count = static_cast<uint32_t>(mesh.triangle_count());
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(count >> (8 * i)));
  out.reserve(kPieceBytes + 50);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &mesh.positions[mesh.indices[t * 3 + k] * 3];
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n) c = len > 0 ? c / len : 0;
    for (double c : n) PutFloat(static_cast<float>(c), &out);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) PutFloat(p[k][i], &out);
    out.push_back(0);
    out.push_back(0);
    if (out.size() >= kPieceBytes) {
      sink(out.data(), out.size());
      out.clear();
    }
  }
  if (!out.empty()) sink(out.data(), out.size());
}

Status WriteMeshFile(const Mesh& mesh, RobotFormat format, const std::string& path) {
  Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
  if (!file.ok()) return file.status();
  AtomicFileWriter& writer = file.value();
  if (format != RobotFormat::kMjcf) {
    EncodeBinaryStl(mesh, [&](const void* data, size_t size) { writer.Write(data, size); });
  } else {
    EncodeObjMesh(mesh, [&](std::string_view text) { writer.Write(text.data(), text.size()); });
  }
  return writer.Commit();
}

}  // namespace hullpack
