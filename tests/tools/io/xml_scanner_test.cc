#include "io/xml_scanner.h"

#include <gtest/gtest.h>

#include <string>

namespace hullpack {
namespace {

using Token = XmlScanner::Token;

TEST(XmlScanner, ReportsElementsAndAttributesAndSkipsTheRest) {
  XmlScanner xml(
      "<?xml version=\"1.0\"?>\n<!DOCTYPE model [<!ENTITY x \"y\">]>\n<!-- a <comment> -->\n"
      "<model unit='inch' xmlns:m=\"urn:m\">text<![CDATA[<not/>]]>\n"
      "  <m:color color=\"#FF0000\"/>\n  <b  a = \"1\" >x</b ></model>");
  ASSERT_EQ(xml.Next(), Token::kStart);
  EXPECT_EQ(xml.name(), "model");
  EXPECT_EQ(xml.depth(), 0u);
  EXPECT_EQ(xml.Attribute("unit"), "inch");
  EXPECT_EQ(xml.Attribute("xmlns:m"), "urn:m");
  bool found = true;
  EXPECT_EQ(xml.Attribute("missing", &found), "");
  EXPECT_FALSE(found);
  ASSERT_EQ(xml.Next(), Token::kStart);
  EXPECT_EQ(xml.name(), "m:color");
  EXPECT_EQ(XmlScanner::LocalName(xml.name()), "color");
  EXPECT_EQ(XmlScanner::Prefix(xml.name()), "m");
  EXPECT_EQ(xml.depth(), 1u);
  ASSERT_EQ(xml.Next(), Token::kEnd);  // the self-closed tag's end
  EXPECT_EQ(xml.name(), "m:color");
  ASSERT_EQ(xml.Next(), Token::kStart);
  EXPECT_EQ(xml.Attribute("a"), "1");
  EXPECT_EQ(xml.Next(), Token::kEnd);
  EXPECT_EQ(xml.Next(), Token::kEnd);
  EXPECT_EQ(xml.name(), "model");
  EXPECT_EQ(xml.Next(), Token::kDone);
  EXPECT_EQ(xml.Next(), Token::kDone);
}

TEST(XmlScanner, MalformedTextIsAnErrorWithItsLine) {
  XmlScanner mismatched("<a>\n<b>\n</a>");
  EXPECT_EQ(mismatched.Next(), Token::kStart);
  EXPECT_EQ(mismatched.Next(), Token::kStart);
  EXPECT_EQ(mismatched.Next(), Token::kError);
  EXPECT_EQ(mismatched.error(), "end tag 'a' does not match 'b'");
  EXPECT_EQ(mismatched.line(), 3u);
  EXPECT_EQ(mismatched.Next(), Token::kError);

  XmlScanner unclosed("<a><b/>");
  EXPECT_EQ(unclosed.Next(), Token::kStart);
  EXPECT_EQ(unclosed.Next(), Token::kStart);
  EXPECT_EQ(unclosed.Next(), Token::kEnd);
  EXPECT_EQ(unclosed.Next(), Token::kError);
  EXPECT_EQ(unclosed.error(), "element 'a' is not closed");

  for (const char* bad : {"<a b=\"1\" b=\"2\"/>", "<a b=1/>", "<a b=\"1/>", "<>", "<a/><b/>",
                          "</a>", "<a><!-- x", "<a/ >"}) {
    XmlScanner xml(bad);
    Token t = xml.Next();
    while (t != Token::kError && t != Token::kDone) t = xml.Next();
    EXPECT_EQ(t, Token::kError) << bad;
  }
}

TEST(XmlScanner, EveryTruncationEndsCleanly) {
  const std::string text =
      "<?xml version=\"1.0\"?><model a=\"&amp;\"><!-- c --><v x=\"1\" y='2'/><![CDATA[z]]></model>";
  for (size_t size = 0; size <= text.size(); ++size) {
    const std::string prefix = text.substr(0, size);
    XmlScanner xml(prefix);
    Token t = xml.Next();
    int steps = 0;
    while (t != Token::kError && t != Token::kDone && ++steps < 100) t = xml.Next();
    EXPECT_EQ(t, size == text.size() ? Token::kDone : Token::kError) << size;
  }
}

TEST(XmlScanner, DecodesEntitiesAndCharacterReferences) {
  EXPECT_EQ(XmlScanner::Decode("a &amp; b &lt;&gt; &quot;&apos;"), "a & b <> \"'");
  EXPECT_EQ(XmlScanner::Decode("&#65;&#x42;&#xe9;&#x1F600;"), "AB\xC3\xA9\xF0\x9F\x98\x80");
  // Unknown or malformed references stay as written.
  EXPECT_EQ(XmlScanner::Decode("&nope; &#; &#x110000; & &#0;"), "&nope; &#; &#x110000; & &#0;");
}

}  // namespace
}  // namespace hullpack
