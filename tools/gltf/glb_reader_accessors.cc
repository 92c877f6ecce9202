// Buffer views and accessors: every offset, stride and count checked against the bytes there are.
#include "gltf/glb_reader_decoder.h"

#include <algorithm>
#include <cstring>

namespace hullpack {
namespace glb_reader_internal {

double ReadComponent(const uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
    case gltf::kByte: {
      const double v = static_cast<int8_t>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case gltf::kUnsignedByte: {
      const double v = p[0];
      return normalized ? v / 255.0 : v;
    }
    case gltf::kShort: {
      const double v = static_cast<int16_t>(LoadU16(p));
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case gltf::kUnsignedShort: {
      const double v = LoadU16(p);
      return normalized ? v / 65535.0 : v;
    }
    case gltf::kUnsignedInt:
      return static_cast<double>(LoadU32(p));
    case gltf::kFloat: {
      const uint32_t bits = LoadU32(p);
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return f;
    }
    default:
      return 0;
  }
}

uint32_t ReadUnsigned(const uint8_t* p, int component_type) {
  switch (component_type) {
    case gltf::kUnsignedByte:
      return p[0];
    case gltf::kUnsignedShort:
      return LoadU16(p);
    case gltf::kUnsignedInt:
      return LoadU32(p);
    default:
      return 0;
  }
}

Status Decoder::GetBufferView(int64_t index, const std::string& where, const uint8_t** data,
                              size_t* size, size_t* stride) {
  const json* views = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("bufferViews", &views));
  if (index < 0 || views == nullptr || static_cast<size_t>(index) >= views->size()) {
    return Error(where, "bufferView " + std::to_string(index) + " does not exist");
  }
  const std::string vw = Item("bufferViews", static_cast<uint64_t>(index));
  const json& v = (*views)[static_cast<size_t>(index)];
  int64_t buffer = -1;
  uint64_t offset = 0, length = 0, byte_stride = 0;
  HP_RETURN_IF_ERROR(GetIndex(v, "buffer", vw, &buffer));
  if (buffer < 0) return Error(vw, "has no buffer");
  if (v.find("byteLength") == v.end()) return Error(vw, "has no byteLength");
  HP_RETURN_IF_ERROR(GetUint(v, "byteOffset", vw, 0, &offset));
  HP_RETURN_IF_ERROR(GetUint(v, "byteLength", vw, 0, &length));
  HP_RETURN_IF_ERROR(GetUint(v, "byteStride", vw, 0, &byte_stride));
  if (v.find("byteStride") != v.end() &&
      (byte_stride < 4 || byte_stride > 252 || byte_stride % 4 != 0)) {
    return Error(vw,
                 "byteStride " + std::to_string(byte_stride) + " is not a multiple of 4 in 4..252");
  }
  const BufferData* buf = nullptr;
  HP_RETURN_IF_ERROR(GetBuffer(buffer, vw, &buf));
  uint64_t end = 0;
  if (__builtin_add_overflow(offset, length, &end) || end > buf->size) {
    return Error(vw, "bytes " + std::to_string(offset) + "+" + std::to_string(length) + " exceed " +
                         Item("buffers", static_cast<uint64_t>(buffer)) + " (" +
                         std::to_string(buf->size) + " bytes)");
  }
  *data = buf->data + offset;
  *size = static_cast<size_t>(length);
  *stride = static_cast<size_t>(byte_stride);
  return Status::Ok();
}

Status Decoder::GetAccessor(int64_t index, const std::string& where, AccessorView* out,
                            bool allow_sparse) {
  const json* accessors = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("accessors", &accessors));
  if (index < 0 || accessors == nullptr || static_cast<size_t>(index) >= accessors->size()) {
    return Error(where, "accessor " + std::to_string(index) + " does not exist");
  }
  const std::string aw = Item("accessors", static_cast<uint64_t>(index));
  const json& a = (*accessors)[static_cast<size_t>(index)];
  if (a.contains("sparse") && !allow_sparse)
    return Unsupported(aw, "sparse accessors are not supported here");
  uint64_t component_type = 0, count = 0, offset = 0;
  if (a.find("componentType") == a.end()) return Error(aw, "has no componentType");
  if (a.find("count") == a.end()) return Error(aw, "has no count");
  HP_RETURN_IF_ERROR(GetUint(a, "componentType", aw, 0, &component_type));
  HP_RETURN_IF_ERROR(GetUint(a, "count", aw, 0, &count));
  HP_RETURN_IF_ERROR(GetUint(a, "byteOffset", aw, 0, &offset));
  const size_t csize =
      component_type > 0xFFFF ? 0 : gltf::ComponentSize(static_cast<int>(component_type));
  if (csize == 0) return Error(aw, "unknown componentType " + std::to_string(component_type));
  std::string type;
  HP_RETURN_IF_ERROR(GetString(a, "type", aw, &type));
  const int components = gltf::ComponentCount(type);
  if (components == 0) return Error(aw, "unknown type '" + type + "'");
  if ((type == "MAT2" || type == "MAT3") && csize < 4) {
    return Unsupported(aw, type + " accessors of 1- or 2-byte components are not supported");
  }
  bool normalized = false;
  HP_RETURN_IF_ERROR(GetBool(a, "normalized", aw, &normalized));
  if (normalized && (component_type == gltf::kFloat || component_type == gltf::kUnsignedInt)) {
    return Error(aw, "normalized is only allowed for byte and short components");
  }
  if (count == 0) return Error(aw, "count is 0");
  out->count = static_cast<size_t>(count);
  out->components = components;
  out->component_type = static_cast<int>(component_type);
  out->normalized = normalized;
  out->type = type;
  const size_t element = csize * static_cast<size_t>(components);
  int64_t view = -1;
  HP_RETURN_IF_ERROR(GetIndex(a, "bufferView", aw, &view));
  if (view < 0) {
    // Zero-filled: no bytes back it, so its size is charged against the budget before any
    // allocation.
    uint64_t bytes = 0;
    if (!MulAdd(count, element, 0, &bytes)) return Error(aw, "count overflows");
    HP_RETURN_IF_ERROR(Charge(bytes, aw));
    out->data = nullptr;
    out->stride = element;
    return Status::Ok();
  }
  const uint8_t* data = nullptr;
  size_t view_size = 0, stride = 0;
  HP_RETURN_IF_ERROR(GetBufferView(view, aw, &data, &view_size, &stride));
  if (stride == 0) stride = element;
  if (stride < element) {
    return Error(aw, "byteStride " + std::to_string(stride) + " is smaller than its element (" +
                         std::to_string(element) + " bytes)");
  }
  uint64_t span = 0;
  if (!MulAdd(count - 1, stride, element, &span) || __builtin_add_overflow(span, offset, &span) ||
      span > view_size) {
    return Error(aw, "byteOffset " + std::to_string(offset) + " + count " + std::to_string(count) +
                         " x stride " + std::to_string(stride) + " exceeds " +
                         Item("bufferViews", static_cast<uint64_t>(view)) + " (" +
                         std::to_string(view_size) + " bytes)");
  }
  out->data = data + offset;
  out->stride = stride;
  return Status::Ok();
}

Status Decoder::ApplySparse(int64_t index, const AccessorView& a, std::vector<float>* out) {
  const std::string aw = Item("accessors", static_cast<uint64_t>(index)) + ".sparse";
  const json& sparse = (*root_.find("accessors"))[static_cast<size_t>(index)]["sparse"];
  if (!sparse.is_object()) return Error(aw, "is not an object");
  uint64_t count = 0;
  HP_RETURN_IF_ERROR(GetUint(sparse, "count", aw, 0, &count));
  if (count == 0 || count > a.count) {
    return Error(aw, "count " + std::to_string(count) + " is not in 1.." + std::to_string(a.count));
  }
  auto indices = sparse.find("indices");
  auto values = sparse.find("values");
  if (indices == sparse.end() || !indices->is_object() || values == sparse.end() ||
      !values->is_object()) {
    return Error(aw, "needs indices and values objects");
  }
  // One tightly packed run of `count` elements of `element` bytes in a bufferView.
  auto run = [&](const json& j, const std::string& w, size_t element, const uint8_t** data) {
    int64_t view = -1;
    uint64_t offset = 0;
    HP_RETURN_IF_ERROR(GetIndex(j, "bufferView", w, &view));
    HP_RETURN_IF_ERROR(GetUint(j, "byteOffset", w, 0, &offset));
    const uint8_t* bytes = nullptr;
    size_t size = 0, stride = 0;
    HP_RETURN_IF_ERROR(GetBufferView(view, w, &bytes, &size, &stride));
    uint64_t end = 0;
    if (!MulAdd(count, element, offset, &end) || end > size)
      return Error(w, "exceeds its bufferView (" + std::to_string(size) + " bytes)");
    *data = bytes + offset;
    return Status::Ok();
  };
  uint64_t index_type = 0;
  HP_RETURN_IF_ERROR(GetUint(*indices, "componentType", aw + ".indices", 0, &index_type));
  if (index_type != gltf::kUnsignedByte && index_type != gltf::kUnsignedShort &&
      index_type != gltf::kUnsignedInt) {
    return Error(aw + ".indices", "componentType must be an unsigned integer type");
  }
  const size_t index_size = gltf::ComponentSize(static_cast<int>(index_type));
  const size_t csize = gltf::ComponentSize(a.component_type);
  const size_t element = csize * static_cast<size_t>(a.components);
  const uint8_t* index_data = nullptr;
  const uint8_t* value_data = nullptr;
  HP_RETURN_IF_ERROR(run(*indices, aw + ".indices", index_size, &index_data));
  HP_RETURN_IF_ERROR(run(*values, aw + ".values", element, &value_data));
  int64_t previous = -1;
  for (size_t k = 0; k < count; ++k) {
    const uint32_t i = ReadUnsigned(index_data + k * index_size, static_cast<int>(index_type));
    if (i >= a.count || static_cast<int64_t>(i) <= previous) {
      return Error(aw + ".indices", "index " + std::to_string(k) + " (" + std::to_string(i) +
                                        ") is out of range or not increasing");
    }
    previous = i;
    for (int c = 0; c < a.components; ++c) {
      (*out)[i * static_cast<size_t>(a.components) + static_cast<size_t>(c)] = static_cast<float>(
          ReadComponent(value_data + k * element + static_cast<size_t>(c) * csize, a.component_type,
                        a.normalized));
    }
  }
  return Status::Ok();
}

Status Decoder::ReadFloats(int64_t index, const std::string& where,
                           std::initializer_list<int> allowed_components, std::vector<float>* out,
                           int* components) {
  AccessorView a;
  HP_RETURN_IF_ERROR(GetAccessor(index, where, &a, /*allow_sparse=*/true));
  const std::string aw = where + " (" + Item("accessors", static_cast<uint64_t>(index)) + ")";
  if (std::find(allowed_components.begin(), allowed_components.end(), a.components) ==
      allowed_components.end()) {
    return Error(aw, "has type " + a.type + ", which this attribute does not allow");
  }
  const size_t n = a.count * static_cast<size_t>(a.components);
  HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(n) * sizeof(float), aw));
  out->assign(n, 0.0f);
  if (a.data != nullptr) {
    const size_t csize = gltf::ComponentSize(a.component_type);
    for (size_t i = 0; i < a.count; ++i) {
      const uint8_t* e = a.data + i * a.stride;
      for (int c = 0; c < a.components; ++c) {
        (*out)[i * static_cast<size_t>(a.components) + static_cast<size_t>(c)] = static_cast<float>(
            ReadComponent(e + static_cast<size_t>(c) * csize, a.component_type, a.normalized));
      }
    }
  }
  if ((*root_.find("accessors"))[static_cast<size_t>(index)].contains("sparse"))
    HP_RETURN_IF_ERROR(ApplySparse(index, a, out));
  *components = a.components;
  return Status::Ok();
}

Status Decoder::ReadIndices(int64_t index, const std::string& where, std::vector<uint32_t>* out) {
  AccessorView a;
  HP_RETURN_IF_ERROR(GetAccessor(index, where, &a));
  const std::string aw = where + " (" + Item("accessors", static_cast<uint64_t>(index)) + ")";
  if (a.components != 1 || a.normalized ||
      (a.component_type != gltf::kUnsignedByte && a.component_type != gltf::kUnsignedShort &&
       a.component_type != gltf::kUnsignedInt)) {
    return Error(aw, "is not an unsigned-integer SCALAR accessor");
  }
  HP_RETURN_IF_ERROR(Charge(static_cast<uint64_t>(a.count) * sizeof(uint32_t), aw));
  out->assign(a.count, 0);
  if (a.data != nullptr) {
    for (size_t i = 0; i < a.count; ++i)
      (*out)[i] = ReadUnsigned(a.data + i * a.stride, a.component_type);
  }
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
