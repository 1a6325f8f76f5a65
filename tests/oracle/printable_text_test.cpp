#include "printable_text.h"

#include <gtest/gtest.h>

namespace fosssim {
namespace {

TEST(PrintableText, KeepsValidUtf8NewlinesAndTabs) {
  EXPECT_EQ(printable_text("résidu ≥ 1e-10\n\tok"), "résidu ≥ 1e-10\n\tok");
  EXPECT_EQ(printable_text("emoji \xF0\x9F\x98\x80"), "emoji \xF0\x9F\x98\x80");
}

TEST(PrintableText, EscapesControlCharactersAndInvalidBytes) {
  EXPECT_EQ(printable_text(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable_text("bell\x07 escape\x1b[31m cr\r"), "bell\\x07 escape\\x1b[31m cr\\x0d");
  EXPECT_EQ(printable_text("\xff\xfe"), "\\xff\\xfe");
  // A sequence cut short, an overlong '/', a surrogate, and a C1 control (U+0085).
  EXPECT_EQ(printable_text("\xE2\x82"), "\\xe2\\x82");
  EXPECT_EQ(printable_text("\xC0\xAF"), "\\xc0\\xaf");
  EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xed\\xa0\\x80");
  EXPECT_EQ(printable_text("\xC2\x85"), "\\xc2\\x85");
}

TEST(PrintableText, LastLinesKeepsTheEndAndMarksTheCut) {
  EXPECT_EQ(last_lines("a\nb\nc\n", 2), "...\nb\nc");
  EXPECT_EQ(last_lines("a\nb\nc", 3), "a\nb\nc");
  EXPECT_EQ(last_lines("", 3), "");
  EXPECT_EQ(first_line("one\ntwo"), "one");
  EXPECT_EQ(indent_lines("a\nb", "> "), "> a\n> b\n");
}

}  // namespace
}  // namespace fosssim
