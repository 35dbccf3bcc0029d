// xml_escape.cpp: text made safe for SVG and HTML.
#include "amp/viz/xml_escape.hpp"

#include <string>

#include <gtest/gtest.h>

namespace amp::viz {
namespace {

TEST(XmlEscape, EscapesAmpersandAnglesAndDoubleQuotesOnly) {
  EXPECT_EQ(xml_escape("a < b && c > \"d\""), "a &lt; b &amp;&amp; c &gt; &quot;d&quot;");
  EXPECT_EQ(xml_escape(""), "");
  const std::string plain = "prm-l n=0.1 (Isto 2003) 'walls' \xc3\xa9";  // apostrophe and UTF-8 kept
  EXPECT_EQ(xml_escape(plain), plain);
}

TEST(XmlEscape, AlreadyEscapedTextIsEscapedAgain) {
  // No entity is taken for markup: "&lt;" shows as "&lt;" in the picture.
  EXPECT_EQ(xml_escape("&lt;"), "&amp;lt;");
  EXPECT_EQ(xml_escape(std::string("a\0b", 3)), std::string("a\0b", 3));
}

}  // namespace
}  // namespace amp::viz
