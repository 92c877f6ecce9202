#include "gltf/component_store.h"

#include <cmath>
#include <cstring>
#include <optional>

#include "gltf/gltf_document.h"

namespace hullpack {
namespace gltf {

bool StoreComponent(double value, int component_type, bool normalized, uint8_t* out) {
  if (!std::isfinite(value)) return false;
  auto integer = [&](double lo, double hi, double scale) -> std::optional<int64_t> {
    const double v = normalized ? std::round(value * scale) : value;
    if (v < lo || v > hi || (!normalized && v != std::floor(v))) return std::nullopt;
    return static_cast<int64_t>(v);
  };
  switch (component_type) {
    case kFloat: {
      const float f = static_cast<float>(value);
      std::memcpy(out, &f, 4);
      return true;
    }
    case kUnsignedInt: {
      auto v = integer(0, 4294967295.0, 4294967295.0);
      if (!v) return false;
      const uint32_t u = static_cast<uint32_t>(*v);
      std::memcpy(out, &u, 4);
      return true;
    }
    case kUnsignedShort: {
      auto v = integer(0, 65535, 65535);
      if (!v) return false;
      const uint16_t u = static_cast<uint16_t>(*v);
      std::memcpy(out, &u, 2);
      return true;
    }
    case kUnsignedByte: {
      auto v = integer(0, 255, 255);
      if (!v) return false;
      *out = static_cast<uint8_t>(*v);
      return true;
    }
    case kShort: {
      auto v = integer(-32768, 32767, 32767);
      if (!v) return false;
      const int16_t s = static_cast<int16_t>(*v);
      std::memcpy(out, &s, 2);
      return true;
    }
    case kByte: {
      auto v = integer(-128, 127, 127);
      if (!v) return false;
      const int8_t s = static_cast<int8_t>(*v);
      std::memcpy(out, &s, 1);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace gltf
}  // namespace hullpack
