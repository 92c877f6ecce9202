// Reading the entries of a ZIP archive held in memory: the container of 3MF files (and of other
// Open Packaging Convention documents). Stored and deflated entries, ZIP64 sizes and offsets;
// no encryption, no multi-disk archives.
// Trust model: any byte sequence is safe. Every offset and size is checked against the archive,
// an entry inflates to exactly its declared size (never more than deflate can produce from its
// compressed bytes) and its CRC-32 must match.
#ifndef HULLPACK_TOOLS_IO_ZIP_ARCHIVE_H_
#define HULLPACK_TOOLS_IO_ZIP_ARCHIVE_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct ZipEntry {
  std::string name;  // as stored: '/'-separated, no leading '/'
  uint16_t method = 0;
  uint32_t crc32 = 0;
  uint64_t compressed_size = 0;
  uint64_t uncompressed_size = 0;
  uint64_t local_header_offset = 0;
};

class ZipArchive {
 public:
  // Reads the central directory of the archive at `data` (which must outlive this object).
  // `name` is used in messages.
  static Result<ZipArchive> Open(const uint8_t* data, size_t size, const std::string& name);

  const std::vector<ZipEntry>& entries() const { return entries_; }
  // The entry whose name equals `name` ignoring ASCII case and a leading '/' (part names of the
  // Open Packaging Conventions compare so), or nullptr.
  const ZipEntry* Find(std::string_view name) const;
  // The entry's bytes, inflated and checked.
  Result<std::vector<uint8_t>> Read(const ZipEntry& entry) const;

 private:
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  std::string name_;
  std::vector<ZipEntry> entries_;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_ZIP_ARCHIVE_H_
