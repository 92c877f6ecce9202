// Connectivity of original Open3DGC streams: TFAN (triangle fan) decoding.
//
// The stream holds six symbol arrays (fans per vertex, fan degrees, fan configurations, a bit per
// fan vertex saying "existing vertex", the references of existing vertices, and optionally the
// triangle order), each as its own section. Decoding visits vertices in order; each one's
// already-decoded triangles give its "visited" neighbours (sorted by id, those seen in one
// triangle first), and each fan names its vertices as new ones, visited ones or relative ids
// (see docs/open3dgc-legacy-format.md).
#ifndef O3DGC_SRC_LEGACY_CONNECTIVITY_DECODER_H_
#define O3DGC_SRC_LEGACY_CONNECTIVITY_DECODER_H_

#include <cstdint>
#include <vector>

#include "legacy_stream_reader.h"
#include "o3dgc/o3dgc.h"

namespace o3dgc {

struct LegacyConnectivity {
  std::vector<uint32_t> triangles;  // 3 per triangle, in decoding order (the order attributes use)
  // Empty, or for each decoded triangle its position in the encoder's input order (a permutation).
  std::vector<uint32_t> placement;
};

// Reads the connectivity part at the reader's position (and leaves the reader after it). The
// stream must produce exactly `num_triangles` triangles over `num_vertices` vertices. kUnsupported
// for streams with a coded vertex order (the original decoder has none either).
Status DecodeLegacyConnectivity(LegacyReader* r, uint32_t num_vertices, uint32_t num_triangles,
                                LegacyConnectivity* out);

}  // namespace o3dgc

#endif  // O3DGC_SRC_LEGACY_CONNECTIVITY_DECODER_H_
