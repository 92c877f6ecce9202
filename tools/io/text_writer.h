// Appends numbers to a text buffer in their shortest exact form (float round-trips bit for bit).
#ifndef HULLPACK_TOOLS_IO_TEXT_WRITER_H_
#define HULLPACK_TOOLS_IO_TEXT_WRITER_H_

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

namespace hullpack {

class TextWriter {
 public:
  TextWriter& operator<<(std::string_view s) {
    out_.append(s.data(), s.size());
    return *this;
  }
  TextWriter& operator<<(char c) {
    out_.push_back(c);
    return *this;
  }
  TextWriter& operator<<(float v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out_.append(buf, static_cast<size_t>(r.ptr - buf));
    return *this;
  }
  TextWriter& operator<<(uint64_t v) {
    char buf[24];
    auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out_.append(buf, static_cast<size_t>(r.ptr - buf));
    return *this;
  }
  TextWriter& operator<<(uint32_t v) { return *this << static_cast<uint64_t>(v); }
  TextWriter& operator<<(int v) {
    char buf[16];
    auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out_.append(buf, static_cast<size_t>(r.ptr - buf));
    return *this;
  }
  std::string& str() { return out_; }

 private:
  std::string out_;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_TEXT_WRITER_H_
