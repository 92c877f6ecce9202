// A bounds-checked cursor over text, shared by the project's own OBJ, OFF and VRML parsers.
// It never reads past `end`, parses numbers locale-independently, and counts lines for messages.
#ifndef HULLPACK_TOOLS_IO_TEXT_SCANNER_H_
#define HULLPACK_TOOLS_IO_TEXT_SCANNER_H_

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace hullpack {

class TextScanner {
 public:
  // `first_line`: the number of the text's first line (a part of a larger text starts later).
  TextScanner(const char* begin, const char* end, size_t first_line = 1)
      : p_(begin), end_(end), line_(first_line) {}

  bool AtEnd() const { return p_ >= end_; }
  size_t line() const { return line_; }
  char Peek() const { return p_ < end_ ? *p_ : '\0'; }
  void Advance() {
    if (p_ < end_) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }

  // Skips spaces and tabs (and '\r'), not newlines.
  void SkipBlanks() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r')) ++p_;
  }
  // Skips all white space, newlines included, and `#` comments when `comments` is set.
  void SkipWhitespace(bool comments) {
    while (p_ < end_) {
      const char c = *p_;
      if (c == '\n') {
        ++line_;
        ++p_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == ',') {
        ++p_;
      } else if (comments && c == '#') {
        while (p_ < end_ && *p_ != '\n') ++p_;
      } else {
        break;
      }
    }
  }
  bool AtLineEnd() const { return p_ >= end_ || *p_ == '\n' || *p_ == '#'; }
  const char* position() const { return p_; }
  // Moves to the end of the line (its '\n', or the end of the text), not past it.
  void SkipToLineEnd() {
    const void* nl = std::memchr(p_, '\n', static_cast<size_t>(end_ - p_));
    p_ = nl ? static_cast<const char*>(nl) : end_;
  }
  void SkipLine() {
    while (p_ < end_ && *p_ != '\n') ++p_;
    if (p_ < end_) {
      ++p_;
      ++line_;
    }
  }
  // The next run of non-blank characters (not crossing a newline).
  std::string_view Word() {
    SkipBlanks();
    const char* start = p_;
    while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
    return std::string_view(start, static_cast<size_t>(p_ - start));
  }
  // The rest of the line, trimmed.
  std::string_view RestOfLine() {
    SkipBlanks();
    const char* start = p_;
    while (p_ < end_ && *p_ != '\n') ++p_;
    const char* stop = p_;
    while (stop > start && (stop[-1] == ' ' || stop[-1] == '\t' || stop[-1] == '\r')) --stop;
    return std::string_view(start, static_cast<size_t>(stop - start));
  }

  bool ParseDouble(double* out) {
    const char* start = p_;
    if (start < end_ && *start == '+') ++start;  // from_chars rejects a leading '+'
    auto r = std::from_chars(start, end_, *out);
    if (r.ec != std::errc() && r.ec != std::errc::result_out_of_range) return false;
    p_ = r.ptr;
    return true;
  }
  bool ParseInt64(int64_t* out) {
    const char* start = p_;
    if (start < end_ && *start == '+') ++start;
    auto r = std::from_chars(start, end_, *out);
    if (r.ec != std::errc()) return false;
    p_ = r.ptr;
    return true;
  }
  bool Consume(char c) {
    if (p_ < end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }

 private:
  const char* p_;
  const char* end_;
  size_t line_ = 1;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_TEXT_SCANNER_H_
