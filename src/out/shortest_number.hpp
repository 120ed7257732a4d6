// Numbers in the output: the shortest decimal that reads back as the same double, exactly as
// {fmt}'s "{}" writes it, with a fast path for the common case of a value with at most six
// decimals (most coordinates of real programs), which needs no floating-point-to-decimal
// conversion at all.
#pragma once

#include <fmt/format.h>

#include <charconv>

namespace ncoffset::out {

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
      return std::to_chars(out, out + 10, whole).ptr;
    }
  }
  return writeShortest(out, v);
}

inline void appendShortest(fmt::memory_buffer& b, double v) {
  char text[32];
  b.append(text, writeShortest(text, v));
}

}  // namespace ncoffset::out
