// String functions (lang/string_functions.*): the number text NUMBER and ISNUMBER accept, and
// the positions of the search functions.
#include "lang/string_functions.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

TEST(StringFunctions, NumberTextAsTheNcLanguageWritesNumbers) {
  double v = 0;
  EXPECT_TRUE(parseNumberText("12.5", v));
  EXPECT_DOUBLE_EQ(v, 12.5);
  EXPECT_TRUE(parseNumberText("  -1.5EX2 ", v));
  EXPECT_DOUBLE_EQ(v, -150);
  EXPECT_TRUE(parseNumberText(".5", v));
  EXPECT_DOUBLE_EQ(v, 0.5);
  EXPECT_TRUE(parseNumberText("2EX-3", v));
  EXPECT_DOUBLE_EQ(v, 0.002);
  for (const char* bad : {"", " ", "+", "12,5", "1E5", "1.2.3", "1EX", "1EX400", "ABC", "1 2"})
    EXPECT_FALSE(parseNumberText(bad, v)) << bad;
}

TEST(StringFunctions, PositionsFromZeroAndMinusOneWhenNotFound) {
  Value out;
  const std::vector<Value> index_args = {Value::string("A.B.C"), Value::string(".")};
  ASSERT_TRUE(stringFunction("INDEX", index_args, out));
  EXPECT_EQ(out.num, 1);
  ASSERT_TRUE(stringFunction("RINDEX", index_args, out));
  EXPECT_EQ(out.num, 3);
  const std::vector<Value> match_args = {Value::string("ABC"), Value::string("X")};
  ASSERT_TRUE(stringFunction("MATCH", match_args, out));
  EXPECT_EQ(out.num, -1);
  const std::vector<Value> substr_args = {Value::string("ABCDEF"), Value::integer(2),
                                          Value::integer(3)};
  ASSERT_TRUE(stringFunction("SUBSTR", substr_args, out));
  EXPECT_EQ(out.str, "CDE");
  EXPECT_FALSE(stringFunction("SIN", substr_args, out));
  const std::vector<Value> number_args = {Value::integer(5)};
  EXPECT_THROW(stringFunction("TOUPPER", number_args, out), AlarmError);
}

}  // namespace
}  // namespace ncoffset::lang
