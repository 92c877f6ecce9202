#ifndef HULLPACK_TOOLS_BENCH_GZIP_SIZE_H_
#define HULLPACK_TOOLS_BENCH_GZIP_SIZE_H_

#include <cstddef>
#include <cstdint>

namespace hullpack {

// Bytes of `data` as a web server sends it with Content-Encoding: gzip at the highest level:
// zlib's deflate at level 9 in the gzip wrapper, without a file name in the header (what
// `gzip -9n` writes). 0 when zlib fails.
size_t GzipSize(const uint8_t* data, size_t size);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_GZIP_SIZE_H_
