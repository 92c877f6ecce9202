#include "io/zip_archive.h"

#include <zlib.h>

#include <algorithm>
#include <limits>

namespace hullpack {
namespace {

constexpr uint32_t kEndOfCentralDirectory = 0x06054b50;
constexpr uint32_t kZip64EndLocator = 0x07064b50;
constexpr uint32_t kZip64End = 0x06064b50;
constexpr uint32_t kCentralHeader = 0x02014b50;
constexpr uint32_t kLocalHeader = 0x04034b50;
constexpr size_t kEndSize = 22;
constexpr size_t kCentralHeaderSize = 46;
constexpr size_t kLocalHeaderSize = 30;
constexpr uint16_t kStored = 0;
constexpr uint16_t kDeflated = 8;
// Deflate cannot expand data by more than about 1032 to 1; a larger declared size is a lie.
constexpr uint64_t kMaxDeflateRatio = 1032;

// Little-endian fields at checked offsets: every read is of [offset, offset + width) inside the
// span the reader was given, else `ok` turns false and reads return 0.
class FieldReader {
 public:
  FieldReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  bool ok() const { return ok_; }
  uint64_t Read(uint64_t offset, int width) {
    if (!ok_ || offset > size_ || static_cast<uint64_t>(width) > size_ - offset) {
      ok_ = false;
      return 0;
    }
    uint64_t value = 0;
    for (int i = width - 1; i >= 0; --i) value = (value << 8) | data_[offset + i];
    return value;
  }
  uint16_t U16(uint64_t offset) { return static_cast<uint16_t>(Read(offset, 2)); }
  uint32_t U32(uint64_t offset) { return static_cast<uint32_t>(Read(offset, 4)); }
  uint64_t U64(uint64_t offset) { return Read(offset, 8); }

 private:
  const uint8_t* data_;
  size_t size_;
  bool ok_ = true;
};

char LowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool EqualPartNames(std::string_view a, std::string_view b) {
  if (!a.empty() && a.front() == '/') a.remove_prefix(1);
  if (!b.empty() && b.front() == '/') b.remove_prefix(1);
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (LowerAscii(a[i]) != LowerAscii(b[i])) return false;
  }
  return true;
}

// Applies the ZIP64 extra field (id 1) of a central header: it holds, in this order, the 64-bit
// value of each of the three fields that the header marks as 0xFFFFFFFF.
bool ApplyZip64Extra(FieldReader& in, uint64_t extra, uint64_t extra_end, ZipEntry* entry) {
  while (extra + 4 <= extra_end) {
    const uint16_t id = in.U16(extra);
    const uint16_t length = in.U16(extra + 2);
    const uint64_t body = extra + 4;
    if (body + length > extra_end) return false;
    if (id == 1) {
      uint64_t at = body;
      for (uint64_t* field :
           {&entry->uncompressed_size, &entry->compressed_size, &entry->local_header_offset}) {
        if (*field != 0xFFFFFFFFu) continue;
        if (at + 8 > body + length) return false;
        *field = in.U64(at);
        at += 8;
      }
      return in.ok();
    }
    extra = body + length;
  }
  return true;
}

}  // namespace

Result<ZipArchive> ZipArchive::Open(const uint8_t* data, size_t size, const std::string& name) {
  auto fail = [&name](const std::string& what) {
    return Status(StatusCode::kParseError, name + ": not a readable ZIP archive: " + what);
  };
  FieldReader in(data, size);
  if (size < kEndSize) return fail("too short");
  // The end record sits before a comment of at most 65535 bytes.
  size_t end = std::numeric_limits<size_t>::max();
  const size_t lowest = size - kEndSize > 0xFFFF ? size - kEndSize - 0xFFFF : 0;
  for (size_t at = size - kEndSize + 1; at-- > lowest;) {
    if (in.U32(at) == kEndOfCentralDirectory && at + kEndSize + in.U16(at + 20) == size) {
      end = at;
      break;
    }
  }
  if (end == std::numeric_limits<size_t>::max()) return fail("no end of central directory");
  if (in.U16(end + 4) != 0 || in.U16(end + 6) != 0) return fail("multi-disk archives are not read");
  uint64_t count = in.U16(end + 10);
  uint64_t directory_size = in.U32(end + 12);
  uint64_t directory_offset = in.U32(end + 16);
  if (end >= 20 && in.U32(end - 20) == kZip64EndLocator) {
    const uint64_t record = in.U64(end - 20 + 8);
    if (in.U32(record) != kZip64End) return fail("bad ZIP64 end of central directory");
    count = in.U64(record + 32);
    directory_size = in.U64(record + 40);
    directory_offset = in.U64(record + 48);
  }
  if (!in.ok() || directory_offset > size || directory_size > size - directory_offset) {
    return fail("the central directory lies outside the file");
  }
  // Each central header takes at least 46 bytes, which bounds a forged entry count.
  if (count > directory_size / kCentralHeaderSize) return fail("bad entry count");

  ZipArchive archive;
  archive.data_ = data;
  archive.size_ = size;
  archive.name_ = name;
  archive.entries_.reserve(static_cast<size_t>(count));
  uint64_t at = directory_offset;
  const uint64_t directory_end = directory_offset + directory_size;
  for (uint64_t i = 0; i < count; ++i) {
    if (at + kCentralHeaderSize > directory_end || in.U32(at) != kCentralHeader) {
      return fail("bad central directory entry " + std::to_string(i));
    }
    ZipEntry entry;
    const uint16_t flags = in.U16(at + 8);
    entry.method = in.U16(at + 10);
    entry.crc32 = in.U32(at + 16);
    entry.compressed_size = in.U32(at + 20);
    entry.uncompressed_size = in.U32(at + 24);
    const uint16_t name_length = in.U16(at + 28);
    const uint16_t extra_length = in.U16(at + 30);
    const uint16_t comment_length = in.U16(at + 32);
    entry.local_header_offset = in.U32(at + 42);
    const uint64_t name_start = at + kCentralHeaderSize;
    const uint64_t extra_start = name_start + name_length;
    const uint64_t next = extra_start + extra_length + comment_length;
    if (next > directory_end) return fail("bad central directory entry " + std::to_string(i));
    entry.name.assign(reinterpret_cast<const char*>(data + name_start), name_length);
    if (!ApplyZip64Extra(in, extra_start, extra_start + extra_length, &entry)) {
      return fail("bad ZIP64 sizes of '" + entry.name + "'");
    }
    if (flags & 1) {
      return Status(StatusCode::kUnsupported, name + ": '" + entry.name + "' is encrypted");
    }
    archive.entries_.push_back(std::move(entry));
    at = next;
  }
  if (!in.ok()) return fail("truncated central directory");
  return archive;
}

const ZipEntry* ZipArchive::Find(std::string_view name) const {
  for (const ZipEntry& entry : entries_) {
    if (EqualPartNames(entry.name, name)) return &entry;
  }
  return nullptr;
}

Result<std::vector<uint8_t>> ZipArchive::Read(const ZipEntry& entry) const {
  auto fail = [this, &entry](const std::string& what) {
    return Status(StatusCode::kParseError, name_ + ": '" + entry.name + "': " + what);
  };
  FieldReader in(data_, size_);
  const uint64_t header = entry.local_header_offset;
  if (in.U32(header) != kLocalHeader) return fail("no local header where the directory says");
  const uint64_t start = header + kLocalHeaderSize + in.U16(header + 26) + in.U16(header + 28);
  if (!in.ok() || start > size_ || entry.compressed_size > size_ - start) {
    return fail("its data lies outside the file");
  }
  const uint8_t* compressed = data_ + start;
  if (entry.method != kStored && entry.method != kDeflated) {
    return Status(StatusCode::kUnsupported,
                  name_ + ": '" + entry.name + "' uses compression method " +
                      std::to_string(entry.method) + " (reads stored and deflated entries)");
  }
  if (entry.method == kStored && entry.compressed_size != entry.uncompressed_size) {
    return fail("a stored entry whose sizes differ");
  }
  if (entry.uncompressed_size > entry.compressed_size * kMaxDeflateRatio + 1024 ||
      entry.uncompressed_size > std::numeric_limits<size_t>::max() / 2) {
    return fail("declares more bytes than its data can hold");
  }
  std::vector<uint8_t> out(static_cast<size_t>(entry.uncompressed_size));
  if (entry.method == kStored) {
    std::copy(compressed, compressed + out.size(), out.begin());
  } else {
    z_stream stream{};
    if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) return fail("zlib could not start");
    uint64_t in_left = entry.compressed_size;
    uint64_t out_left = out.size();
    stream.next_in = const_cast<Bytef*>(compressed);
    stream.next_out = out.data();
    constexpr uint64_t kStep = 1u << 30;  // zlib counts in 32-bit lengths
    int code = Z_OK;
    bool too_long = false;
    for (;;) {
      if (out_left == 0) {
        // Full: the stream must end here without another byte.
        uint8_t spare = 0;
        stream.next_out = &spare;
        stream.avail_out = 1;
        stream.avail_in = static_cast<uInt>(std::min(in_left, kStep));
        code = inflate(&stream, Z_NO_FLUSH);
        too_long = stream.avail_out == 0;
        break;
      }
      const uInt in_now = static_cast<uInt>(std::min(in_left, kStep));
      const uInt out_now = static_cast<uInt>(std::min(out_left, kStep));
      stream.avail_in = in_now;
      stream.avail_out = out_now;
      code = inflate(&stream, Z_NO_FLUSH);
      in_left -= in_now - stream.avail_in;
      out_left -= out_now - stream.avail_out;
      if (code != Z_OK) break;
    }
    inflateEnd(&stream);
    if (code != Z_STREAM_END || out_left != 0 || too_long) {
      return fail(too_long ? "inflates to more bytes than declared"
                           : "damaged or truncated deflate data");
    }
  }
  uLong crc = crc32(0L, Z_NULL, 0);
  for (size_t done = 0; done < out.size();) {
    const uInt now = static_cast<uInt>(std::min<size_t>(out.size() - done, 1u << 30));
    crc = crc32(crc, out.data() + done, now);
    done += now;
  }
  if (static_cast<uint32_t>(crc) != entry.crc32) return fail("CRC-32 mismatch");
  return out;
}

}  // namespace hullpack
