// Writing one accessor component in its glTF component type: what a reader that decodes compressed
// primitives (HULLPACK_mesh_compression, KHR_draco_mesh_compression) does to give their accessors
// plain data.
#ifndef HULLPACK_TOOLS_GLTF_COMPONENT_STORE_H_
#define HULLPACK_TOOLS_GLTF_COMPONENT_STORE_H_

#include <cstdint>

namespace hullpack {
namespace gltf {

// Stores `value` at `out` (little-endian, ComponentSize(component_type) bytes). A normalized
// integer type takes `value` in [0, 1] ([-1, 1] when signed) and rounds; a plain integer type takes
// only whole numbers in its range. Returns false, writing nothing, for a value the type cannot
// hold, a non-finite value, or an unknown type.
bool StoreComponent(double value, int component_type, bool normalized, uint8_t* out);

}  // namespace gltf
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_COMPONENT_STORE_H_
