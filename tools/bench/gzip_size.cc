#include "bench/gzip_size.h"

#include <zlib.h>

#include <vector>

namespace hullpack {

size_t GzipSize(const uint8_t* data, size_t size) {
  z_stream z{};
  // windowBits 15 + 16: the gzip wrapper; memLevel 8 is zlib's default.
  if (deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) return 0;
  std::vector<uint8_t> out(deflateBound(&z, static_cast<uLong>(size)));
  z.next_in = const_cast<Bytef*>(data);
  z.avail_in = static_cast<uInt>(size);
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  const size_t written = z.total_out;
  deflateEnd(&z);
  return rc == Z_STREAM_END ? written : 0;
}

}  // namespace hullpack
