#include "out/shortest_number.hpp"

#include <fmt/compile.h>

#include <charconv>
#include <cmath>
#include <cstring>

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
      return writeUnsigned(out, whole);
    }
    const double scaled = a * 1e6 + 0.5;  // < 1e15 + 0.5: exact enough to round
    const auto m = static_cast<unsigned long long>(scaled);
    const double back = static_cast<double>(m) / 1e6;
    if (back == a) {  // the same as (v < 0 ? -back : back) == v
      if (v < 0) *out++ = '-';
      // Integer part below 1e9: 32 bits.
      out = writeUnsigned(out, static_cast<unsigned>(m / 1000000));
      const auto frac = static_cast<unsigned>(m % 1000000);
      if (frac) {
        // Six digits as three pairs, then the trailing zeros cut off.
        *out++ = '.';
        std::memcpy(out, kDigitPairs + 2 * (frac / 10000), 2);
        std::memcpy(out + 2, kDigitPairs + 2 * (frac / 100 % 100), 2);
        std::memcpy(out + 4, kDigitPairs + 2 * (frac % 100), 2);
        out += 6;
        while (out[-1] == '0') --out;  // frac > 0: stops at a non-zero digit
      }
      return out;
    }
  }
  return fmt::format_to(out, FMT_COMPILE("{}"), v);
}

}  // namespace ncoffset::out
