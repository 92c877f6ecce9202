// Decoding streams written by the original Open3DGC SC3DMC encoder (amd/rest3d, 2013), binary and
// ASCII: TFAN connectivity, quantized positions, normals, float and int attributes, and the
// triangle order when the encoder kept it. o3dgc::Decode and o3dgc::ReadStreamInfo route such
// streams here (they start with the SC3DMC start code instead of "O3DG"/"O3DA").
//
// Mapping to DecodedMesh: one vertex per coordinate; normals and attributes must have one entry
// per coordinate (the original tool always writes them so; other layouts are kUnsupported);
// float attribute types map to semantics (texcoord, color, weight, normal, else generic), int
// attributes of type "joint id" to kJointId, others to kGeneric. Values are returned as stored:
// the original tool kept OBJ texture coordinates (v up) as they were. Triangles come in the
// encoder's input order when the stream keeps it, else in decoding order.
#ifndef O3DGC_SRC_LEGACY_DECODER_H_
#define O3DGC_SRC_LEGACY_DECODER_H_

#include <cstddef>
#include <cstdint>

#include "legacy_stream_reader.h"  // IsLegacyStream
#include "o3dgc/o3dgc.h"

namespace o3dgc {

// A legacy stream pays for its elements (triangles, and values of every array) with at least one
// byte per this many; larger claims are rejected (kLimitExceeded) before anything is allocated.
// The original encoder does not pad, so this is a guard, set ~70x above the densest stream of the
// reference vectors (3.7 elements per byte).
constexpr uint64_t kLegacyElementsPerByte = 256;

Status DecodeLegacy(const uint8_t* data, size_t size, const DecodeOptions& options,
                    DecodedMesh* out, StreamInfo* info);

// Header only: counts, stream type, format; part sizes other than `header` are left 0.
Status ReadLegacyStreamInfo(const uint8_t* data, size_t size, StreamInfo* info);

}  // namespace o3dgc

#endif  // O3DGC_SRC_LEGACY_DECODER_H_
