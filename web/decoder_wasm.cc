// WebAssembly glue for the o3dgc decoder: a flat C API over o3dgc::Decode for JavaScript
// (web/hullpack_decoder.js). Only decoding is compiled in.
//
//   ptr = malloc(size); copy the stream to HEAPU8[ptr..]; h = hp_decode(ptr, size); free(ptr);
//   if (hp_status(h) != 0) -> error hp_status_name(h)
//   read hp_positions(h) (3 * hp_num_vertices floats), hp_indices(h) (3 * hp_num_triangles u32),
//   ... hp_free(h);
//
// A handle is never null unless memory ran out (then the JS side reports "out_of_memory").
// Every getter returns 0/null for an absent array or an out-of-range attribute index.
#include <cstddef>
#include <cstdint>
#include <new>

#include "o3dgc/o3dgc.h"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#define HP_EXPORT extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define HP_EXPORT extern "C"
#endif

namespace {

struct Result {
  o3dgc::Status status = o3dgc::Status::kOk;
  o3dgc::DecodedMesh mesh;
  o3dgc::StreamInfo info;
};

template <typename T>
const T* DataOrNull(const std::vector<T>& v) {
  return v.empty() ? nullptr : v.data();
}

}  // namespace

// verify_checksum 0 skips the CRC check (for tests that feed mutated streams to the decoder).
HP_EXPORT Result* hp_decode_ex(const uint8_t* data, size_t size, int verify_checksum) {
  Result* r = new (std::nothrow) Result;
  if (!r) return nullptr;
  o3dgc::DecodeOptions options;
  options.verify_checksum = verify_checksum != 0;
  // Bound what a hostile stream may make us allocate in a 32-bit address space.
  options.max_vertices = size_t(1) << 24;
  options.max_triangles = size_t(1) << 25;
  r->status = o3dgc::Decode(data, size, options, &r->mesh, &r->info);
  if (r->status != o3dgc::Status::kOk) r->mesh = o3dgc::DecodedMesh();
  return r;
}

HP_EXPORT Result* hp_decode(const uint8_t* data, size_t size) {
  return hp_decode_ex(data, size, 1);
}

HP_EXPORT void hp_free(Result* r) { delete r; }

HP_EXPORT int hp_status(const Result* r) { return int(r->status); }
HP_EXPORT const char* hp_status_name(const Result* r) { return o3dgc::StatusName(r->status); }
HP_EXPORT int hp_stream_type(const Result* r) { return int(r->info.stream_type); }

HP_EXPORT uint32_t hp_num_vertices(const Result* r) { return uint32_t(r->mesh.num_vertices()); }
HP_EXPORT uint32_t hp_num_triangles(const Result* r) { return uint32_t(r->mesh.num_triangles()); }
HP_EXPORT const float* hp_positions(const Result* r) { return DataOrNull(r->mesh.positions); }
HP_EXPORT const uint32_t* hp_indices(const Result* r) { return DataOrNull(r->mesh.indices); }
HP_EXPORT const float* hp_normals(const Result* r) { return DataOrNull(r->mesh.normals); }
HP_EXPORT const uint32_t* hp_groups(const Result* r) { return DataOrNull(r->mesh.triangle_groups); }

HP_EXPORT uint32_t hp_num_float_attributes(const Result* r) {
  return uint32_t(r->mesh.float_attributes.size());
}
HP_EXPORT int hp_float_attribute_semantic(const Result* r, uint32_t i) {
  return i < r->mesh.float_attributes.size() ? int(r->mesh.float_attributes[i].semantic) : -1;
}
HP_EXPORT uint32_t hp_float_attribute_dimension(const Result* r, uint32_t i) {
  return i < r->mesh.float_attributes.size() ? r->mesh.float_attributes[i].dimension : 0;
}
HP_EXPORT const float* hp_float_attribute_values(const Result* r, uint32_t i) {
  return i < r->mesh.float_attributes.size() ? DataOrNull(r->mesh.float_attributes[i].values)
                                             : nullptr;
}

HP_EXPORT uint32_t hp_num_int_attributes(const Result* r) {
  return uint32_t(r->mesh.int_attributes.size());
}
HP_EXPORT int hp_int_attribute_semantic(const Result* r, uint32_t i) {
  return i < r->mesh.int_attributes.size() ? int(r->mesh.int_attributes[i].semantic) : -1;
}
HP_EXPORT uint32_t hp_int_attribute_dimension(const Result* r, uint32_t i) {
  return i < r->mesh.int_attributes.size() ? r->mesh.int_attributes[i].dimension : 0;
}
HP_EXPORT const int32_t* hp_int_attribute_values(const Result* r, uint32_t i) {
  return i < r->mesh.int_attributes.size() ? DataOrNull(r->mesh.int_attributes[i].values) : nullptr;
}
