// Line normalisation into the block's buffer (src/lang/line_normalize.hpp): the '\0' the
// parser's scans rely on, the buffer that only grows, and the bad column. normalizeLine itself
// is tested with the parser (parser_test.cpp).
#include "lang/line_normalize.hpp"

#include <gtest/gtest.h>

#include <string>

namespace ncoffset::lang {
namespace {

TEST(NormalizeInto, EndsWithANul) {
  std::string buffer;
  size_t len = 0;
  int bad = 0;
  for (std::string text : {"g1 x1", "G1 X10.5 Y-2 F1000", "x1 ; comment", "a", ""}) {
    ASSERT_TRUE(normalizeInto(text, buffer, len, &bad)) << text;
    ASSERT_LT(len, buffer.size()) << text;
    EXPECT_EQ(buffer[len], '\0') << text;
  }
}

TEST(NormalizeInto, BufferOnlyGrows) {
  std::string buffer;
  size_t len = 0;
  ASSERT_TRUE(normalizeInto("G1 X10 Y20 Z30 F1000 ; a long block", buffer, len, nullptr));
  const size_t size = buffer.size();
  ASSERT_TRUE(normalizeInto("x1", buffer, len, nullptr));
  EXPECT_EQ(buffer.size(), size);
  EXPECT_EQ(len, 2u);
  EXPECT_EQ(buffer.substr(0, len), "X1");
  EXPECT_EQ(buffer[len], '\0');
}

TEST(NormalizeInto, LengthUpToTheBadByte) {
  std::string buffer;
  size_t len = 0;
  int bad = 0;
  EXPECT_FALSE(normalizeInto("g1 x\x01", buffer, len, &bad));
  EXPECT_EQ(bad, 5);
  EXPECT_EQ(buffer.substr(0, len), "G1 X");
  // A NUL inside a string is a bad byte too (nothing may end the parser's scans early).
  EXPECT_FALSE(normalizeInto(std::string_view("MSG(\"a\0\")", 9), buffer, len, &bad));
  EXPECT_EQ(bad, 7);
  // Without a place for the column it still reports the failure.
  EXPECT_FALSE(normalizeInto("\x7F", buffer, len, nullptr));
}

TEST(NormalizeInto, PlainLinesOfEveryLength) {
  // The eight-byte copy and the byte-by-byte copy must agree at every length.
  const std::string text = "n10 g1 x10.5 y-2 z3 cr=10 f1000 m3 s2000";
  for (size_t n = 0; n <= text.size(); ++n) {
    std::string lower = text.substr(0, n), upper = lower;
    for (char& c : upper) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    std::string buffer;
    size_t len = 0;
    ASSERT_TRUE(normalizeInto(upper, buffer, len, nullptr));
    EXPECT_EQ(buffer.substr(0, len), upper);
    ASSERT_TRUE(normalizeInto(lower, buffer, len, nullptr));
    EXPECT_EQ(buffer.substr(0, len), upper);
  }
}

}  // namespace
}  // namespace ncoffset::lang
