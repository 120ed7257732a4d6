#include "out/shortest_number.hpp"

#include <fmt/compile.h>

#include <charconv>
#include <cmath>

namespace ncoffset::out {

char* writeShortest(char* out, double v) {
  v += 0.0;  // -0 prints as 0
  const double a = std::fabs(v);
  // {fmt} writes fixed notation from 1e-4 up to 1e16; below 1e9 doubles are closer than 1e-6
  // to each other, so a value equal to n / 1e6 (n an integer) has no shorter representation
  // than n / 1e6 with its trailing zeros removed, and that text reads back as n / 1e6 = v
  // (the division is correctly rounded, as is reading the text).
  if (a < 1e9 && (a >= 1e-4 || a == 0)) {
    // Whole numbers (feeds, levels, many programmed points) need no fraction at all.
    const auto whole = static_cast<unsigned>(a);  // a < 1e9 < 2^32
    if (static_cast<double>(whole) == a) {
      if (v < 0) *out++ = '-';
      return std::to_chars(out, out + 10, whole).ptr;
    }
    const double scaled = a * 1e6 + 0.5;  // < 1e15 + 0.5: exact enough to round
    const auto m = static_cast<unsigned long long>(scaled);
    const double back = static_cast<double>(m) / 1e6;
    if (back == a) {  // the same as (v < 0 ? -back : back) == v
      if (v < 0) *out++ = '-';
      // Integer part below 1e9: 32 bits.
      out = std::to_chars(out, out + 10, static_cast<unsigned>(m / 1000000)).ptr;
      unsigned frac = static_cast<unsigned>(m % 1000000);
      if (frac) {
        *out++ = '.';
        int digits = 6;
        for (; frac % 10 == 0; frac /= 10) --digits;  // trailing zeros are not written
        char* const end = out + digits;
        for (char* q = end; q > out; frac /= 10) *--q = static_cast<char>('0' + frac % 10);
        out = end;
      }
      return out;
    }
  }
  return fmt::format_to(out, FMT_COMPILE("{}"), v);
}

}  // namespace ncoffset::out
