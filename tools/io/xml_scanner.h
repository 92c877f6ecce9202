// A pull scanner over XML text: element starts with their attributes, and element ends. Text,
// comments, processing instructions, CDATA sections and the document type are skipped; what the
// 3MF reader needs, not a general XML library (no DTD, no validation, entities only in Decode).
// Trust model: any byte sequence is safe; a start tag without its end, or an end tag that does not
// match, is an error with the line it was found on.
#ifndef HULLPACK_TOOLS_IO_XML_SCANNER_H_
#define HULLPACK_TOOLS_IO_XML_SCANNER_H_

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hullpack {

class XmlScanner {
 public:
  enum class Token { kStart, kEnd, kDone, kError };

  explicit XmlScanner(std::string_view text) : text_(text) {}

  // The next element start or end. A tag written `<a/>` gives kStart, then kEnd. kDone once the
  // text ends after its document element closed; kError (see error()) on malformed text, and
  // from then on.
  Token Next();

  // The current element's qualified name ("vertex", "m:color"), for kStart and kEnd.
  std::string_view name() const { return name_; }
  // The part of a qualified name after its prefix ("m:color" -> "color").
  static std::string_view LocalName(std::string_view qualified);
  // The prefix of a qualified name, empty when it has none.
  static std::string_view Prefix(std::string_view qualified);
  // How many elements enclose the current one (the document element has depth 0).
  size_t depth() const { return stack_.size() - (last_ == Token::kStart ? 1 : 0); }
  // The current start tag's attributes, as written (not decoded).
  const std::vector<std::pair<std::string_view, std::string_view>>& attributes() const {
    return attributes_;
  }
  // The raw value of the attribute named `name` (qualified); empty, with *found false, when the
  // tag has none.
  std::string_view Attribute(std::string_view name, bool* found = nullptr) const;

  // `raw` with the five predefined entities and character references replaced.
  static std::string Decode(std::string_view raw);

  const std::string& error() const { return error_; }
  // The line (from 1) where scanning stopped; counted on demand.
  size_t line() const;

 private:
  Token Fail(const std::string& what);
  bool SkipPast(std::string_view terminator);
  bool ParseStartTag();

  std::string_view text_;
  size_t pos_ = 0;
  std::string_view name_;
  std::vector<std::pair<std::string_view, std::string_view>> attributes_;
  std::vector<std::string_view> stack_;
  bool pending_end_ = false;
  bool seen_document_element_ = false;
  Token last_ = Token::kDone;
  std::string error_;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_XML_SCANNER_H_
