// Numbers in the output: the shortest decimal that reads back as the same double, exactly as
// {fmt}'s "{}" writes it, with a fast path for the common case of a value with at most six
// decimals (most coordinates of real programs), which needs no floating-point-to-decimal
// conversion at all.
#pragma once

#include <fmt/format.h>

#include <charconv>
#include <cstring>

namespace ncoffset::out {

// "00" "01" ... "99": decimal digits two at a time.
inline constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Writes v < 10000 in decimal and returns the end.
inline char* writeBelow10000(char* out, unsigned v) {
  if (v < 100) {
    if (v < 10) {
      *out = static_cast<char>('0' + v);
      return out + 1;
    }
    std::memcpy(out, kDigitPairs + 2 * v, 2);
    return out + 2;
  }
  const unsigned hi = v / 100, lo = v % 100;
  if (hi < 10) {
    *out++ = static_cast<char>('0' + hi);
  } else {
    std::memcpy(out, kDigitPairs + 2 * hi, 2);
    out += 2;
  }
  std::memcpy(out, kDigitPairs + 2 * lo, 2);
  return out + 2;
}

// Writes v in decimal and returns the end; below 1e8 (coordinates, line numbers, feeds) from
// the pair table without a loop.
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

// Writes v at `out` (room for 32 characters) and returns the end.
char* writeShortest(char* out, double v);

// The same, with whole numbers below 1e9 (feeds, levels, many programmed points) written here
// without a call: for writers that put out many numbers per row.
inline char* writeShortestInline(char* out, double v) {
  const double a = v < 0 ? -v : v;
  if (a < 1e9) {
    const auto whole = static_cast<unsigned>(a);
    if (static_cast<double>(whole) == a) {
      if (v < 0 && whole != 0) *out++ = '-';  // -0 prints as 0
      return writeUnsigned(out, whole);
    }
  }
  return writeShortest(out, v);
}

inline void appendShortest(fmt::memory_buffer& b, double v) {
  char text[32];
  b.append(text, writeShortest(text, v));
}

}  // namespace ncoffset::out
