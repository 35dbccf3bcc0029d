// amp::printable and the escaping every amp::Error applies (fuzzing found messages quoting raw bytes
// read from files: a CR from a .cfg line, invalid UTF-8 from a YAML key or a runs.csv cell).
#include "amp/core/error.hpp"

#include <gtest/gtest.h>

namespace amp {
namespace {

TEST(Printable, KeepsAsciiAndWellFormedUtf8) {
  EXPECT_EQ(printable("robot.links[2]: 0.5 m"), "robot.links[2]: 0.5 m");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82");
}

TEST(Printable, EscapesControlBytes) {
  EXPECT_EQ(printable("a\nb\rc\td"), "a\\x0ab\\x0dc\\x09d");
  EXPECT_EQ(printable(std::string_view("x\0y\x7f", 4)), "x\\x00y\\x7f");
}

TEST(Printable, EscapesBytesThatAreNotUtf8) {
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");            // never lead bytes
  EXPECT_EQ(printable("\x80"), "\\x80");                    // a lone continuation byte
  EXPECT_EQ(printable("\xc3"), "\\xc3");                    // a sequence cut short at the end
  EXPECT_EQ(printable("\xe2\x82z"), "\\xe2\\x82z");          // ... or by an ASCII byte
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");            // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");    // a UTF-16 surrogate
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
}

TEST(Error, MessageIsEscaped) {
  const FileError e("map.yaml: unknown field 'wid\xff\nth'");
  EXPECT_STREQ(e.what(), "map.yaml: unknown field 'wid\\xff\\x0ath'");
  const Error& base = e;
  EXPECT_STREQ(base.what(), e.what());
}

}  // namespace
}  // namespace amp
