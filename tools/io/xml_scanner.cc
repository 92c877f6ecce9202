#include "io/xml_scanner.h"

#include <algorithm>
#include <cstdint>

namespace hullpack {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool EndsName(char c) { return IsSpace(c) || c == '/' || c == '>' || c == '='; }

void AppendUtf8(uint32_t code, std::string* out) {
  if (code < 0x80) {
    out->push_back(static_cast<char>(code));
  } else if (code < 0x800) {
    out->push_back(static_cast<char>(0xC0 | (code >> 6)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else if (code < 0x10000) {
    out->push_back(static_cast<char>(0xE0 | (code >> 12)));
    out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else {
    out->push_back(static_cast<char>(0xF0 | (code >> 18)));
    out->push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
}

}  // namespace

std::string_view XmlScanner::LocalName(std::string_view qualified) {
  const size_t colon = qualified.find(':');
  return colon == std::string_view::npos ? qualified : qualified.substr(colon + 1);
}

std::string_view XmlScanner::Prefix(std::string_view qualified) {
  const size_t colon = qualified.find(':');
  return colon == std::string_view::npos ? std::string_view() : qualified.substr(0, colon);
}

std::string_view XmlScanner::Attribute(std::string_view name, bool* found) const {
  for (const auto& [key, value] : attributes_) {
    if (key == name) {
      if (found) *found = true;
      return value;
    }
  }
  if (found) *found = false;
  return {};
}

size_t XmlScanner::line() const {
  const size_t stop = std::min(pos_, text_.size());
  return 1 + static_cast<size_t>(std::count(text_.begin(), text_.begin() + stop, '\n'));
}

XmlScanner::Token XmlScanner::Fail(const std::string& what) {
  error_ = what;
  last_ = Token::kError;
  return Token::kError;
}

bool XmlScanner::SkipPast(std::string_view terminator) {
  const size_t at = text_.find(terminator, pos_);
  if (at == std::string_view::npos) return false;
  pos_ = at + terminator.size();
  return true;
}

bool XmlScanner::ParseStartTag() {
  // pos_ is just after '<'.
  const size_t name_start = pos_;
  while (pos_ < text_.size() && !EndsName(text_[pos_])) ++pos_;
  name_ = text_.substr(name_start, pos_ - name_start);
  if (name_.empty()) return false;
  attributes_.clear();
  for (;;) {
    while (pos_ < text_.size() && IsSpace(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) return false;
    if (text_[pos_] == '>') {
      ++pos_;
      pending_end_ = false;
      return true;
    }
    if (text_[pos_] == '/') {
      if (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '>') return false;
      pos_ += 2;
      pending_end_ = true;
      return true;
    }
    const size_t key_start = pos_;
    while (pos_ < text_.size() && !EndsName(text_[pos_])) ++pos_;
    const std::string_view key = text_.substr(key_start, pos_ - key_start);
    while (pos_ < text_.size() && IsSpace(text_[pos_])) ++pos_;
    if (key.empty() || pos_ >= text_.size() || text_[pos_] != '=') return false;
    ++pos_;
    while (pos_ < text_.size() && IsSpace(text_[pos_])) ++pos_;
    if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\'')) return false;
    const char quote = text_[pos_++];
    const size_t close = text_.find(quote, pos_);
    if (close == std::string_view::npos) return false;
    for (const auto& attribute : attributes_) {
      if (attribute.first == key) return false;  // an attribute given twice
    }
    attributes_.emplace_back(key, text_.substr(pos_, close - pos_));
    pos_ = close + 1;
  }
}

XmlScanner::Token XmlScanner::Next() {
  if (last_ == Token::kError) return Token::kError;
  if (pending_end_) {
    pending_end_ = false;
    name_ = stack_.back();
    stack_.pop_back();
    attributes_.clear();
    return last_ = Token::kEnd;
  }
  for (;;) {
    const size_t open = text_.find('<', pos_);
    if (open == std::string_view::npos) {
      pos_ = text_.size();
      if (!stack_.empty()) {
        return Fail("element '" + std::string(stack_.back()) + "' is not closed");
      }
      if (!seen_document_element_) return Fail("no document element");
      return last_ = Token::kDone;
    }
    pos_ = open + 1;
    const std::string_view rest = text_.substr(pos_);
    if (rest.substr(0, 3) == "!--") {
      if (!SkipPast("-->")) return Fail("unterminated comment");
    } else if (rest.substr(0, 8) == "![CDATA[") {
      if (!SkipPast("]]>")) return Fail("unterminated CDATA section");
    } else if (!rest.empty() && rest[0] == '?') {
      if (!SkipPast("?>")) return Fail("unterminated processing instruction");
    } else if (!rest.empty() && rest[0] == '!') {
      // <!DOCTYPE ...>, possibly with an internal subset in brackets.
      const size_t bracket = text_.find('[', pos_);
      const size_t close = text_.find('>', pos_);
      if (bracket != std::string_view::npos && bracket < close) {
        pos_ = bracket;
        if (!SkipPast("]")) return Fail("unterminated document type");
      }
      if (!SkipPast(">")) return Fail("unterminated document type");
    } else if (!rest.empty() && rest[0] == '/') {
      ++pos_;
      const size_t name_start = pos_;
      while (pos_ < text_.size() && !EndsName(text_[pos_])) ++pos_;
      const std::string_view name = text_.substr(name_start, pos_ - name_start);
      while (pos_ < text_.size() && IsSpace(text_[pos_])) ++pos_;
      if (pos_ >= text_.size() || text_[pos_] != '>') return Fail("malformed end tag");
      ++pos_;
      if (stack_.empty() || stack_.back() != name) {
        return Fail("end tag '" + std::string(name) + "' does not match " +
                    (stack_.empty() ? std::string("any open element")
                                    : "'" + std::string(stack_.back()) + "'"));
      }
      stack_.pop_back();
      name_ = name;
      attributes_.clear();
      return last_ = Token::kEnd;
    } else {
      if (!ParseStartTag()) return Fail("malformed start tag");
      if (stack_.empty() && seen_document_element_) return Fail("more than one document element");
      if (stack_.empty()) seen_document_element_ = true;
      stack_.push_back(name_);
      return last_ = Token::kStart;
    }
  }
}

std::string XmlScanner::Decode(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out.push_back(raw[i]);
      continue;
    }
    const size_t semicolon = raw.find(';', i);
    if (semicolon == std::string_view::npos || semicolon - i > 12) {
      out.push_back('&');
      continue;
    }
    const std::string_view entity = raw.substr(i + 1, semicolon - i - 1);
    uint32_t code = 0;
    bool known = true;
    if (entity == "amp") {
      code = '&';
    } else if (entity == "lt") {
      code = '<';
    } else if (entity == "gt") {
      code = '>';
    } else if (entity == "quot") {
      code = '"';
    } else if (entity == "apos") {
      code = '\'';
    } else if (entity.size() > 1 && entity[0] == '#') {
      const bool hex = entity[1] == 'x' || entity[1] == 'X';
      const std::string_view digits = entity.substr(hex ? 2 : 1);
      known = !digits.empty();
      for (char c : digits) {
        int d = -1;
        if (c >= '0' && c <= '9') d = c - '0';
        if (hex && c >= 'a' && c <= 'f') d = c - 'a' + 10;
        if (hex && c >= 'A' && c <= 'F') d = c - 'A' + 10;
        if (d < 0 || code > 0x10FFFF) {
          known = false;
          break;
        }
        code = code * (hex ? 16 : 10) + static_cast<uint32_t>(d);
      }
      if (code == 0 || code > 0x10FFFF) known = false;
    } else {
      known = false;
    }
    if (!known) {
      out.push_back('&');
      continue;
    }
    AppendUtf8(code, &out);
    i = semicolon;
  }
  return out;
}

}  // namespace hullpack
