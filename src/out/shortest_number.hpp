// Numbers in the output: the shortest decimal that reads back as the same double, exactly as
// {fmt}'s "{}" writes it, with a fast path for the common case of a value with at most six
// decimals (most coordinates of real programs), which needs no floating-point-to-decimal
// conversion at all.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/inline_step.hpp"

namespace ncoffset::out {

// "00" "01" ... "99": decimal digits two at a time.
inline constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The digits of 0..9999, four bytes each (the number's digits first, zeros after them), and
// their count.
struct FourDigits {
  char text[10000][4] = {};
  unsigned char len[10000] = {};
  constexpr FourDigits() {
    for (int v = 0; v < 10000; ++v) {
      const int n = v < 10 ? 1 : v < 100 ? 2 : v < 1000 ? 3 : 4;
      len[v] = static_cast<unsigned char>(n);
      for (int i = n - 1, rest = v; i >= 0; --i, rest /= 10)
        text[v][i] = static_cast<char>('0' + rest % 10);
      for (int i = n; i < 4; ++i) text[v][i] = '0';
    }
  }
};
inline constexpr FourDigits kFourDigits{};

// Writes v < 10000 in decimal and returns the end: the four bytes of the table at once (room
// for them at `out`; what lies past the digits is overwritten by what follows or cut off),
// without a test of the number of digits or a division (docs/performance.md §43).
inline char* writeBelow10000(char* out, unsigned v) {
  std::memcpy(out, kFourDigits.text[v], 4);
  return out + kFourDigits.len[v];
}

// Writes v in decimal and returns the end (room for ten characters at `out`); below 1e8
// (coordinates, line numbers, feeds) from the tables without a loop.
inline char* writeUnsigned(char* out, unsigned v) {
  if (v < 10000) return writeBelow10000(out, v);
  if (v < 100000000) {
    out = writeBelow10000(out, v / 10000);
    const unsigned low = v % 10000;
    std::memcpy(out, kDigitPairs + 2 * (low / 100), 2);
    std::memcpy(out + 2, kDigitPairs + 2 * (low % 100), 2);
    return out + 4;
  }
  return std::to_chars(out, out + 10, v).ptr;
}

// The text of -9999..9999 at [v + 9999]: the sign and the digits, then zeros, and the length in
// the eighth byte; eight bytes each (a whole number's text for writeFixed<true> in one load, no
// test of the sign, docs/performance.md §49). `field`: a comma before the sign (",-12", a CSV
// field in the same load, writeFixed<true, true>, §51).
struct SignedFourDigits {
  char text[19999][8] = {};
  constexpr explicit SignedFourDigits(bool field) {
    for (int v = -9999; v <= 9999; ++v) {
      char* t = text[v + 9999];
      const int a = v < 0 ? -v : v;
      const int n = a < 10 ? 1 : a < 100 ? 2 : a < 1000 ? 3 : 4;
      const int comma = field ? 1 : 0;
      const int sign = comma + (v < 0 ? 1 : 0);
      if (field) t[0] = ',';
      if (v < 0) t[comma] = '-';
      for (int i = sign + n - 1, rest = a; i >= sign; --i, rest /= 10)
        t[i] = static_cast<char>('0' + rest % 10);
      for (int i = sign + n; i < 7; ++i) t[i] = '0';
      t[7] = static_cast<char>(sign + n);
    }
  }
};
inline constexpr SignedFourDigits kSignedFourDigits{false};
inline constexpr SignedFourDigits kSignedFields{true};

// 0..999 as exactly three digits ("007") and a fourth byte ('0'), four bytes each.
struct ThreeDigits {
  char text[1000][4] = {};
  constexpr ThreeDigits() {
    for (int v = 0; v < 1000; ++v) {
      text[v][0] = static_cast<char>('0' + v / 100);
      text[v][1] = static_cast<char>('0' + v / 10 % 10);
      text[v][2] = static_cast<char>('0' + v % 10);
      text[v][3] = '0';
    }
  }
};
inline constexpr ThreeDigits kThreeDigits{};

// Writes v < 1000 as exactly three digits ("007") and returns the end; the table's four bytes
// at once (room for them at `out`, as writeBelow10000).
inline char* writeThreeDigits(char* out, unsigned v) {
  std::memcpy(out, kThreeDigits.text[v], 4);
  return out + 3;
}

// The trailing zeros of the three digits of 1..999 (of[0] is not used).
struct TrailingZeros {
  unsigned char of[1000] = {};
  constexpr TrailingZeros() {
    for (int i = 1; i < 1000; ++i) of[i] = i % 100 == 0 ? 2 : i % 10 == 0 ? 1 : 0;
  }
};
inline constexpr TrailingZeros kTrailingZeros{};

// v truncated to an int; for |v| >= 2^31 and NaN a value that does not equal v (x86: INT_MIN,
// the conversion's "indefinite integer", never equal to v unless v is -2^31 itself). So a whole
// number's test needs no range test before it: a double equal to an int is written as that
// int's digits by {fmt} too (fixed notation up to 1e16; docs/performance.md §40).
inline int truncatedInt(double v) {
#if defined(__SSE2__)
  return _mm_cvttsd_si32(_mm_set_sd(v));
#else
  return std::fabs(v) < 2147483647.0 ? static_cast<int>(v) : 0;  // 0: v is no int or 0 itself
#endif
}

// The fast path of writeShortest, inline for writers that put out many numbers per row: v in
// fixed notation when it is a whole number or has at most six decimals and lies below 1e9 (the
// coordinates, feeds and centres of real programs), else nullptr.
//
// {fmt} writes fixed notation from 1e-4 up to 1e16; below 1e9 doubles are closer than 1e-6 to
// each other, so a value equal to n / 1e6 (n an integer) has no shorter representation than
// n / 1e6 with its trailing zeros removed, and that text reads back as n / 1e6 = v (the
// division is correctly rounded, as is reading the text).
//
// A whole number is the signed integer conversion of v itself (one instruction each way; -0
// becomes 0, so it prints as 0): no absolute value, no test of the sign before it is known
// to be needed (docs/performance.md §37).
//
// kSmall: only |v| < 10000 (else nullptr, possibly after a '-'; room for eight bytes at `out`),
// without a call (CsvWriter's usual row, §43). kField (with kSmall): a comma before the number
// (the whole number's comma in the table's load, §51).
template <bool kSmall = false, bool kField = false>
NCOFFSET_INLINE_STEP char* writeFixed(char* out, double v) {
  const int whole = truncatedInt(v);
  if (static_cast<double>(whole) == v) {
    if constexpr (kSmall) {  // -9999..9999 from the signed table (eight bytes of room at out)
      const unsigned i = static_cast<unsigned>(whole) + 9999u;  // (wraps: -9999 is 0)
      if (i >= 19999) return nullptr;
      const SignedFourDigits& table = kField ? kSignedFields : kSignedFourDigits;
      std::memcpy(out, table.text[i], 8);
      return out + table.text[i][7];
    }
    auto u = static_cast<unsigned>(whole);
    if (whole < 0) {
      *out++ = '-';
      u = 0u - u;
    }
    return writeUnsigned(out, u);
  }
  const double a = std::fabs(v);
  if (!(a < (kSmall ? 1e4 : 1e9))) return nullptr;  // also NaN
  if (a < 1e-4) return nullptr;                     // {fmt} writes these with an exponent
  static_assert(kSmall || !kField);
  if constexpr (kField) *out++ = ',';
  // Signed 64-bit conversions (one instruction each): m < 1e15 + 1.
  const auto m = static_cast<long long>(a * 1e6 + 0.5);
  if (static_cast<double>(m) / 1e6 != a) return nullptr;  // more than six decimals
  if (v < 0) *out++ = '-';
  const auto whole_part = static_cast<unsigned>(m / 1000000);
  // (Below 10000, the usual coordinate, the short writer: GCC inlines it, and kept the whole
  // writeUnsigned out of line here, §37.)
  if constexpr (kSmall)  // (a < 1e4 and m / 1e6 == a: whole_part < 10000)
    out = writeBelow10000(out, whole_part);
  else
    out = whole_part < 10000 ? writeBelow10000(out, whole_part) : writeUnsigned(out, whole_part);
  const auto frac = static_cast<unsigned>(m % 1000000);  // not 0: v is no whole number
  // Two groups of three digits; at most three decimals (most CAM output) write only the first.
  // Trailing zeros are cut off by the table, without a loop over the digits.
  *out++ = '.';
  const unsigned hi = frac / 1000, lo = frac % 1000;
  out = writeThreeDigits(out, hi);
  if (lo == 0) return out - kTrailingZeros.of[hi];  // hi > 0, as frac > 0
  out = writeThreeDigits(out, lo);
  return out - kTrailingZeros.of[lo];
}

// Every other double, as {fmt}'s "{}" writes it (out of line: the float-to-decimal conversion):
// {fmt}'s shortest decimal (Dragonbox) laid out here, infinities and NaN by {fmt} itself.
char* writeShortestSlow(char* out, double v);
// The same by {fmt}'s "{}" itself: writeShortestSlow's twin (tests).
char* writeShortestFmt(char* out, double v);

// Writes v at `out` (room for 32 characters) and returns the end; the usual numbers inline,
// without a call.
inline char* writeShortest(char* out, double v) {
  if (char* end = writeFixed(out, v)) return end;
  return writeShortestSlow(out, v);
}

inline void appendShortest(fmt::memory_buffer& b, double v) {
  char text[32];
  b.append(text, writeShortest(text, v));
}

// --decimals N: numbers rounded to at most N decimals (0..17), or kShortest (the default).
inline constexpr int kShortest = -1;
inline constexpr int kMaxDecimals = 17;

// Room that writeRounded needs at `out`.
inline constexpr int kRoundedRoom = 40;

// v with at most `decimals` (0..17) decimals, in fixed notation: the shortest text that reads
// back as v where it has that few decimals (and no exponent), else v rounded to `decimals` as
// printf's %.Nf rounds (the exact binary value to the nearest, a tie to even), trailing zeros
// and a trailing point cut off, "-0" written as "0" (so 30.000000000000004 is "30" and
// -7.1e-15 is "0" with 3 decimals). |v| >= 1e15, infinities and NaN as writeShortest writes
// them. Returns the end.
char* writeRounded(char* out, double v, int decimals);

// v rounded to `decimals` in fixed notation ("%.Nf", zeros cut, "-0" as "0") for any finite v;
// `size` bytes at `out`. Returns the end (at most out + size).
char* writeFixedDecimals(char* out, size_t size, double v, int decimals);

// A number for fmt::format_to: "{}" of `value` as it is (kShortest), or writeRounded.
struct Number {
  double value;
  int decimals = kShortest;
};

}  // namespace ncoffset::out

template <>
struct fmt::formatter<ncoffset::out::Number> {
  constexpr auto parse(format_parse_context& ctx) { return ctx.begin(); }
  template <typename Context>
  auto format(const ncoffset::out::Number& n, Context& ctx) const {
    if (n.decimals < 0) return fmt::format_to(ctx.out(), "{}", n.value);
    char text[ncoffset::out::kRoundedRoom];
    const char* end = ncoffset::out::writeRounded(text, n.value, n.decimals);
    return std::copy(static_cast<const char*>(text), end, ctx.out());
  }
};
