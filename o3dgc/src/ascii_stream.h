// The 7-bit ASCII form of a stream: magic "O3DA" followed by the binary stream repacked 7 bits per
// byte (most significant bits first; the last byte is zero-padded). Every byte is < 128, so the
// stream can travel through text channels; gzip's Huffman stage takes the 8/7 expansion back, so a
// served, gzip'd ASCII stream is about the size of the binary one. A script-side decoder unpacks
// the 7-bit groups and runs the binary decoder.
#ifndef O3DGC_SRC_ASCII_STREAM_H_
#define O3DGC_SRC_ASCII_STREAM_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "o3dgc/o3dgc.h"

namespace o3dgc {

constexpr uint8_t kAsciiMagic[4] = {'O', '3', 'D', 'A'};

bool IsAsciiStream(const uint8_t* data, size_t size);
std::vector<uint8_t> PackAscii(const std::vector<uint8_t>& binary);
// Unpacks an ASCII stream into its binary form; kCorrupt if a byte is >= 128 or the padding is not
// zero.
Status UnpackAscii(const uint8_t* data, size_t size, std::vector<uint8_t>* binary);

}  // namespace o3dgc

#endif  // O3DGC_SRC_ASCII_STREAM_H_
