// The number scan shared by the plain-word fast path and the general parser
// (src/lang/number_scan.hpp): digits and point, the exact inline conversion, long numbers,
// the EX exponent and the errors, and that both parser paths give a number the same bits.
#include "lang/number_scan.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cstring>
#include <string>

#include "lang/parser.hpp"

namespace ncoffset::lang {
namespace {

// The scans need a character after the text that ends them; std::string has its '\0'. (The
// result points into `text`: keep it alive where `end` is used.)
NumberScan scan(const std::string& text) {
  return scanNumber(text.c_str());
}

double fromChars(const std::string& text) {
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

TEST(NumberScan, DigitsAndPoint) {
  const std::string text = "12.5X";
  DecimalDigits d = scanDigits(text.c_str());
  EXPECT_EQ(d.end, text.c_str() + 4);
  EXPECT_EQ(d.mantissa, 125u);
  EXPECT_EQ(d.digits, 3);
  EXPECT_EQ(d.decimals, 1);
  EXPECT_TRUE(d.point);
  d = scanDigits(".5");
  EXPECT_EQ(d.digits, 1);
  EXPECT_EQ(d.decimals, 1);
  d = scanDigits("5.");
  EXPECT_EQ(d.digits, 1);
  EXPECT_EQ(d.decimals, 0);
  EXPECT_TRUE(d.point);
  d = scanDigits("7");
  EXPECT_FALSE(d.point);
  // A second point ends the number.
  const std::string two = "1.2.3";
  EXPECT_EQ(scanDigits(two.c_str()).end, two.c_str() + 3);
  EXPECT_EQ(scanDigits("X").digits, 0);
  EXPECT_EQ(scanDigits(".").digits, 0);
}

// Up to 15 digits the inline conversion is exact: the same double as a correctly rounded
// conversion, wherever the point stands.
TEST(NumberScan, ExactValueIsCorrectlyRounded) {
  const std::string digits = "123456789012345";
  for (size_t len = 1; len <= digits.size(); ++len) {
    for (size_t point = 0; point <= len; ++point) {
      const std::string text = digits.substr(0, point) + "." + digits.substr(point, len - point);
      const NumberScan r = scan(text);
      ASSERT_EQ(r.error, nullptr) << text;
      EXPECT_EQ(r.value, fromChars(text)) << text;
      EXPECT_FALSE(r.is_int);
    }
    const NumberScan whole = scan(digits.substr(0, len));
    EXPECT_EQ(whole.value, fromChars(digits.substr(0, len)));
    EXPECT_TRUE(whole.is_int);
  }
}

TEST(NumberScan, LongNumbers) {
  // More than 15 digits: from_chars, correctly rounded.
  EXPECT_EQ(scan("1234567890123456789").value, 1234567890123456789.0);
  EXPECT_EQ(scan("0.1234567890123456789").value, fromChars("0.1234567890123456789"));
  // Leading zeros are no significant digits.
  EXPECT_EQ(scan("0.0000000000000000001").value, 1e-19);
  EXPECT_EQ(scan("00000000000000000012").value, 12);
  // At most 21 characters, the point included (so 20 digits with a point; the message says 20
  // digits, but 21 without a point pass, as they always did).
  EXPECT_EQ(scan("1234567890.1234567890").error, nullptr);
  EXPECT_EQ(scan("123456789012345678901").error, nullptr);
  EXPECT_STREQ(scan("1234567890.12345678901").error, "number with too many digits (at most 20)");
  EXPECT_STREQ(scan("1234567890123456789012").error, "number with too many digits (at most 20)");
}

TEST(NumberScan, Exponent) {
  const std::string whole = "1.5EX3";
  NumberScan r = scan(whole);
  EXPECT_EQ(r.value, 1500);
  EXPECT_FALSE(r.is_int);
  EXPECT_EQ(r.end, whole.c_str() + whole.size());
  EXPECT_DOUBLE_EQ(scan("1EX-3").value, 0.001);
  EXPECT_EQ(scan("2EX+2").value, 200);
  // EX without digits is no number (issue 14, item 6: 1EX followed by a call of EX.SPF).
  for (const std::string text : {"5EX", "5EXY", "5EX-", "1.5EX+ 3"}) {
    r = scan(text);
    EXPECT_STREQ(r.error, "number format: EX without its exponent (1.5EX3 = 1500)") << text;
    EXPECT_EQ(r.error_at, text.c_str() + text.find('E')) << text;
  }
  EXPECT_STREQ(scan("1EX400").error, "number out of range");
  EXPECT_EQ(scan("1EX-400").value, 0);
  const std::string long_exponent = "1EX1234567890123456789";
  r = scan(long_exponent);
  EXPECT_STREQ(r.error, "number too long");
  EXPECT_EQ(r.error_at, long_exponent.c_str() + 3 + 18);
}

TEST(NumberScan, NoNumber) {
  EXPECT_STREQ(scan("X").error, "number expected");
  EXPECT_STREQ(scan(".").error, "number expected");
  EXPECT_STREQ(scan("").error, "number expected");
}

// The plain-word fast path (X10.5) and the general path (which a leading CDON forces) read a
// number with the same scan: the same bits, and the same choice of INT or REAL.
TEST(NumberScan, FastAndGeneralPathAgree) {
  const char* numbers[] = {"0",
                           "1",
                           "10.5",
                           ".5",
                           "5.",
                           "-0.001",
                           "123456789.123",
                           "999999999999999",
                           "0.1",
                           "+3.25",
                           "0000012.50",
                           "123456789012345.",
                           "1.0000",
                           "-.000001",
                           "42"};
  for (const char* number : numbers) {
    Block fast, general;
    parseBlock(std::string("X") + number, 1, fast);
    parseBlock(std::string("CDON X") + number, 1, general);
    ASSERT_EQ(fast.stmts.size(), 1u) << number;
    ASSERT_EQ(general.stmts.size(), 2u) << number;
    const Stmt& a = fast.stmts[0];
    const Stmt& b = general.stmts[1];
    ASSERT_TRUE(a.literal && b.literal) << number;
    EXPECT_EQ(std::memcmp(&a.literal_value, &b.literal_value, sizeof(double)), 0) << number;
    EXPECT_EQ(a.literal_int, b.literal_int) << number;
  }
}

}  // namespace
}  // namespace ncoffset::lang
