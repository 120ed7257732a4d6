// The one scan of decimal numbers for the block parser (PM-NC "Fundamentals of NC programming":
// digits with at most one decimal point, `.5` and `5.` included; an `EX` exponent, 1.5EX3 =
// 1500). The plain-word fast path and the general parser both use it, so that a number has the
// same value bit for bit whichever path reads it. Numbers of at most 15 digits convert exactly
// inline (Clinger's fast path: the digits as an integer divided by an exact power of ten);
// longer ones go through std::from_chars, out of line.
//
// The scans rely on a character that is no digit, '.', 'E' or sign after the text (the parser's
// '\0' after every block), so they need no length checks.
#pragma once

#include "lang/lexical.hpp"

namespace ncoffset::lang {

// The digits of a number and its point, as scanned.
struct DecimalDigits {
  const char* end = nullptr;        // first character after the digits
  unsigned long long mantissa = 0;  // all digits as one integer (exact up to 19 digits)
  int digits = 0;                   // digits scanned, the point not counted
  int decimals = 0;                 // digits after the point
  bool point = false;
};

// The digits from `p` appended to `mant` (modulo 2^64); `p` is moved behind them. Each digit's
// value is its character minus '0' taken unsigned, which is below 10 for a digit only: one
// test a digit, and the value is not computed twice. `stop` is that value of the character
// behind the digits (scanDigits asks it for the point: no copy of the character kept in the
// loop, one instruction a digit, docs/performance.md §47).
inline unsigned long long appendDigits(const char*& p, unsigned long long mant, unsigned& stop) {
  unsigned digit = static_cast<unsigned char>(*p) - unsigned{'0'};
  while (digit < 10) {
    mant = mant * 10 + digit;
    digit = static_cast<unsigned char>(*++p) - unsigned{'0'};
  }
  stop = digit;
  return mant;
}

// Digits with at most one '.' from `p` (none at all: digits == 0).
[[gnu::always_inline]] inline DecimalDigits scanDigits(const char* p) {
  DecimalDigits d;
  const char* const begin = p;
  unsigned stop = 0;
  unsigned long long mant = appendDigits(p, 0, stop);
  const char* const point = p;
  if (stop == unsigned{'.'} - unsigned{'0'}) {  // *p == '.'
    d.point = true;
    ++p;
    mant = appendDigits(p, mant, stop);
    d.decimals = static_cast<int>(p - point - 1);
  }
  d.end = p;
  d.mantissa = mant;
  d.digits = static_cast<int>(p - begin) - (d.point ? 1 : 0);
  return d;
}

// Numbers of at most this many digits convert exactly by exactValue.
constexpr int kExactDigits = 15;

// Exact powers of ten for Clinger's fast path (mantissa <= 15 digits divided by 10^decimals).
inline constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// The value of `d` when d.digits <= kExactDigits: the mantissa converts exactly as a signed
// number (one instruction), and whole numbers need no division.
inline double exactValue(const DecimalDigits& d) {
  const auto whole = static_cast<double>(static_cast<long long>(d.mantissa));
  return d.decimals == 0 ? whole : whole / kPow10[d.decimals];
}

// A number scanned by scanNumber. `error` (a static text) is set when the text is no valid
// number; `error_at` is then where the parser reports it.
struct NumberScan {
  const char* end = nullptr;
  double value = 0;
  bool is_int = false;  // written without a point and without an exponent
  const char* error = nullptr;
  const char* error_at = nullptr;
};

// The out-of-line parts of scanNumber: numbers longer than kExactDigits, and the exponent.
void convertLongNumber(const char* begin, const DecimalDigits& d, NumberScan& r);
void applyExponent(NumberScan& r);

// An unsigned decimal number at `p` with an optional exponent: `EX` with an optional sign and
// digits (`EX` directly after the digits without them is an error: every character of a block
// must be read as something). At most 20 digits (21 characters with the point).
inline NumberScan scanNumber(const char* p) {
  NumberScan r;
  const DecimalDigits d = scanDigits(p);
  r.end = d.end;
  r.is_int = !d.point;
  if (d.digits == 0) {
    r.error = "number expected";
    r.error_at = p;
    return r;
  }
  if (d.digits + (d.point ? 1 : 0) > 21) {
    r.error = "number with too many digits (at most 20)";
    r.error_at = p;
    return r;
  }
  if (d.digits <= kExactDigits)
    r.value = exactValue(d);
  else
    convertLongNumber(p, d, r);
  if (!r.error && *r.end == 'E' && r.end[1] == 'X') applyExponent(r);
  return r;
}

}  // namespace ncoffset::lang
