// The rare parts of the number scan (lang/number_scan.hpp): numbers of more than 15 digits and
// the `EX` exponent (PM-NC "Fundamentals of NC programming": 1.5EX3 = 1500, 1EX-3 = 0.001).
#include "lang/number_scan.hpp"

#include <charconv>
#include <cmath>

namespace ncoffset::lang {

void convertLongNumber(const char* begin, const DecimalDigits& d, NumberScan& r) {
  // Leading zeros are no significant digits: 0.0000000000000000001 still converts exactly.
  int leading = 0;
  for (const char* p = begin; p < d.end && (*p == '0' || *p == '.'); ++p) leading += *p == '0';
  if (d.digits - leading <= kExactDigits && d.decimals <= 22) {
    r.value = static_cast<double>(d.mantissa) / kPow10[d.decimals];
    return;
  }
  auto res = std::from_chars(begin, d.end, r.value);
  if (res.ec != std::errc()) {
    r.error = "number out of range";
    r.error_at = begin;
  }
}

void applyExponent(NumberScan& r) {
  const char* p = r.end + 2;  // EX
  bool negative = false;
  if (*p == '-' || *p == '+') negative = *p++ == '-';
  if (!isDigit(*p)) {  // 1EX alone is no number, and no number followed by a word EX
    r.error = "number format: EX without its exponent (1.5EX3 = 1500)";
    r.error_at = r.end;
    return;
  }
  long long e = 0;
  int digits = 0;
  while (isDigit(*p)) {
    if (++digits > 18) {
      r.error = "number too long";
      r.error_at = p;
      return;
    }
    e = e * 10 + (*p++ - '0');
  }
  r.end = p;
  if (e > 400) e = 400;
  r.value *= std::pow(10.0, static_cast<double>(negative ? -e : e));
  r.is_int = false;
  if (!std::isfinite(r.value)) {
    r.error = "number out of range";
    r.error_at = p;
  }
}

}  // namespace ncoffset::lang
