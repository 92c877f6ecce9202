// ZIP archives made in memory for the ZIP and 3MF reader tests: stored or deflated entries, and
// the raw fields a test may then damage.
#ifndef HULLPACK_TESTS_TOOLS_IO_ZIP_TEST_UTIL_H_
#define HULLPACK_TESTS_TOOLS_IO_ZIP_TEST_UTIL_H_

#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hullpack::testing {

struct TestZipEntry {
  std::string name;
  std::string data;
  bool deflate = true;
};

inline void PutLe(std::vector<uint8_t>* out, uint64_t value, int width) {
  for (int i = 0; i < width; ++i) out->push_back(static_cast<uint8_t>(value >> (8 * i)));
}

inline std::string RawDeflate(const std::string& data) {
  z_stream s{};
  deflateInit2(&s, 9, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&s, data.size()) + 16, '\0');
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  s.avail_in = static_cast<uInt>(data.size());
  s.next_out = reinterpret_cast<Bytef*>(out.data());
  s.avail_out = static_cast<uInt>(out.size());
  deflate(&s, Z_FINISH);
  out.resize(s.total_out);
  deflateEnd(&s);
  return out;
}

// A ZIP archive of `entries`, with the central directory and its end record after them.
inline std::vector<uint8_t> MakeZip(const std::vector<TestZipEntry>& entries) {
  std::vector<uint8_t> out;
  std::vector<uint8_t> directory;
  for (const TestZipEntry& e : entries) {
    const std::string body = e.deflate ? RawDeflate(e.data) : e.data;
    const uint32_t crc = static_cast<uint32_t>(
        crc32(0L, reinterpret_cast<const Bytef*>(e.data.data()), static_cast<uInt>(e.data.size())));
    const uint16_t method = e.deflate ? 8 : 0;
    const size_t offset = out.size();
    PutLe(&out, 0x04034b50, 4);
    PutLe(&out, 20, 2);
    PutLe(&out, 0, 2);
    PutLe(&out, method, 2);
    PutLe(&out, 0, 4);  // time and date
    PutLe(&out, crc, 4);
    PutLe(&out, body.size(), 4);
    PutLe(&out, e.data.size(), 4);
    PutLe(&out, e.name.size(), 2);
    PutLe(&out, 0, 2);
    out.insert(out.end(), e.name.begin(), e.name.end());
    out.insert(out.end(), body.begin(), body.end());

    PutLe(&directory, 0x02014b50, 4);
    PutLe(&directory, 20, 2);
    PutLe(&directory, 20, 2);
    PutLe(&directory, 0, 2);
    PutLe(&directory, method, 2);
    PutLe(&directory, 0, 4);
    PutLe(&directory, crc, 4);
    PutLe(&directory, body.size(), 4);
    PutLe(&directory, e.data.size(), 4);
    PutLe(&directory, e.name.size(), 2);
    PutLe(&directory, 0, 2);  // extra
    PutLe(&directory, 0, 2);  // comment
    PutLe(&directory, 0, 2);  // disk
    PutLe(&directory, 0, 2);  // internal attributes
    PutLe(&directory, 0, 4);  // external attributes
    PutLe(&directory, offset, 4);
    directory.insert(directory.end(), e.name.begin(), e.name.end());
  }
  const size_t directory_offset = out.size();
  out.insert(out.end(), directory.begin(), directory.end());
  PutLe(&out, 0x06054b50, 4);
  PutLe(&out, 0, 2);
  PutLe(&out, 0, 2);
  PutLe(&out, entries.size(), 2);
  PutLe(&out, entries.size(), 2);
  PutLe(&out, directory.size(), 4);
  PutLe(&out, directory_offset, 4);
  PutLe(&out, 0, 2);
  return out;
}

// A 3MF package whose root model part is `model_xml`, with `extra` parts beside it.
inline std::vector<uint8_t> MakeThreeMf(const std::string& model_xml,
                                        std::vector<TestZipEntry> extra = {}) {
  std::vector<TestZipEntry> entries = {
      {"[Content_Types].xml",
       "<?xml version=\"1.0\" encoding=\"UTF-8\"?><Types "
       "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default "
       "Extension=\"model\" "
       "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>"
       "</Types>"},
      {"_rels/.rels",
       "<?xml version=\"1.0\" encoding=\"UTF-8\"?><Relationships "
       "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
       "Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
       "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>"},
      {"3D/3dmodel.model", model_xml}};
  for (TestZipEntry& e : extra) entries.push_back(std::move(e));
  return MakeZip(entries);
}

}  // namespace hullpack::testing

#endif  // HULLPACK_TESTS_TOOLS_IO_ZIP_TEST_UTIL_H_
