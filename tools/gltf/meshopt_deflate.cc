#include "gltf/meshopt_deflate.h"

#include <meshoptimizer.h>

#include <cmath>
#include <mutex>

#include "gltf/meshopt_inflate.h"

namespace hullpack {

std::vector<uint8_t> ApplyMeshoptFilter(MeshoptFilter filter, const float* values, size_t count,
                                        size_t stride) {
  std::vector<uint8_t> out;
  if (filter == MeshoptFilter::kQuaternion) {
    // The filter expects unit quaternions; key frames are normalized, but not always exactly.
    std::vector<float> unit(values, values + 4 * count);
    for (size_t k = 0; k < count; ++k) {
      float* q = &unit[4 * k];
      const double n = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] +
                                 double(q[3]) * q[3]);
      for (int c = 0; c < 4; ++c) q[c] = n > 0 ? static_cast<float>(q[c] / n) : (c == 3 ? 1 : 0);
    }
    out.resize(8 * count);
    meshopt_encodeFilterQuat(out.data(), count, 8, kQuaternionFilterBits, unit.data());
  } else if (filter == MeshoptFilter::kExponential) {
    out.resize(stride * count);
    meshopt_encodeFilterExp(out.data(), count, stride, kExponentialFilterBits, values);
  }
  return out;
}

void UndoMeshoptFilter(MeshoptFilter filter, std::vector<uint8_t>* elements, size_t stride) {
  const size_t count = stride == 0 ? 0 : elements->size() / stride;
  if (filter == MeshoptFilter::kQuaternion) meshopt_decodeFilterQuat(elements->data(), count, 8);
  if (filter == MeshoptFilter::kExponential)
    meshopt_decodeFilterExp(elements->data(), count, stride);
}

std::vector<uint8_t> EncodeMeshoptAttributes(const std::vector<uint8_t>& elements, size_t stride) {
  const size_t count = elements.size() / stride;
  std::vector<uint8_t> encoded(meshopt_encodeVertexBufferBound(count, stride));
  // Version 0 of the codec: the one the extension specifies and every decoder reads. The setting
  // is the library's global state: set once, so that packs on several threads do not race on it.
  static std::once_flag version;
  std::call_once(version, [] { meshopt_encodeVertexVersion(0); });
  encoded.resize(
      meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), elements.data(), count, stride));
  return encoded;
}

int AddMeshoptBufferView(GltfDocument& doc, const std::vector<uint8_t>& encoded, size_t count,
                         size_t stride, MeshoptFilter filter) {
  const size_t decoded_size = count * stride;
  nlohmann::json& json = doc.json();
  // Buffer 0 is the binary chunk; the fallback buffer (no data) is buffer 1.
  nlohmann::json& buffers = json["buffers"];
  if (!buffers.is_array()) buffers = nlohmann::json::array();
  if (buffers.empty()) buffers.push_back(nlohmann::json::object());
  if (buffers.size() < 2) {
    buffers.push_back(
        {{"byteLength", 0}, {"extensions", {{kMeshoptExtension, {{"fallback", true}}}}}});
  }
  const size_t fallback_offset = buffers[1]["byteLength"].get<size_t>();
  buffers[1]["byteLength"] = fallback_offset + (decoded_size + 3) / 4 * 4;
  // The compressed bytes as a view of their own (what CompactBufferViews moves), referenced from
  // the extension of the view the accessors use.
  std::vector<uint8_t>& bin = doc.binary();
  while (bin.size() % 4 != 0) bin.push_back(0);
  const size_t offset = bin.size();
  bin.insert(bin.end(), encoded.begin(), encoded.end());
  nlohmann::json ext = {
      {"buffer", 0},          {"byteOffset", offset}, {"byteLength", encoded.size()},
      {"byteStride", stride}, {"count", count},       {"mode", "ATTRIBUTES"}};
  if (filter == MeshoptFilter::kQuaternion) ext["filter"] = "QUATERNION";
  if (filter == MeshoptFilter::kExponential) ext["filter"] = "EXPONENTIAL";
  nlohmann::json view = {{"buffer", 1},
                         {"byteOffset", fallback_offset},
                         {"byteLength", decoded_size},
                         {"extensions", {{kMeshoptExtension, std::move(ext)}}}};
  doc.UseExtension(kMeshoptExtension, true);
  return doc.Append("bufferViews", std::move(view));
}

}  // namespace hullpack
