#include "out/shortest_number.hpp"

#include <fmt/compile.h>

#include <cmath>

namespace ncoffset::out {

char* writeShortestFmt(char* out, double v) {
  return fmt::format_to(out, FMT_COMPILE("{}"), v + 0.0);  // -0 prints as 0
}

namespace {

// The digits of n > 0 (at most 17: a shortest double significand), right-aligned before `end`;
// returns their start.
char* digitsBefore(char* end, unsigned long long n) {
  while (n >= 100) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * (n % 100), 2);
    n /= 100;
  }
  if (n >= 10) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * n, 2);
    return end;
  }
  *--end = static_cast<char>('0' + n);
  return end;
}

// "e+05", "e-123": {fmt}'s exponent (at least two digits, the sign always).
char* writeExponent(char* out, int e) {
  *out++ = 'e';
  *out++ = e < 0 ? '-' : '+';
  const auto a = static_cast<unsigned>(e < 0 ? -e : e);
  if (a >= 100) {
    out = writeUnsigned(out, a / 100);
    std::memcpy(out, kDigitPairs + 2 * (a % 100), 2);
    return out + 2;
  }
  std::memcpy(out, kDigitPairs + 2 * a, 2);
  return out + 2;
}

// The decimal significand `digits` (len digits) times 10^exponent as {fmt}'s "{}" lays it out:
// fixed notation for a leading digit from 1e-4 up to below 1e16, else d.ddde+XX.
char* layOut(char* out, const char* digits, int len, int exponent) {
  const int lead = exponent + len - 1;  // the power of ten of the leading digit
  if (lead < -4 || lead >= 16) {
    *out++ = digits[0];
    if (len > 1) {
      *out++ = '.';
      std::memcpy(out, digits + 1, static_cast<size_t>(len - 1));
      out += len - 1;
    }
    return writeExponent(out, lead);
  }
  if (exponent >= 0) {  // 1234e5 -> 123400000
    std::memcpy(out, digits, static_cast<size_t>(len));
    std::memset(out + len, '0', static_cast<size_t>(exponent));
    return out + len + exponent;
  }
  const int whole = len + exponent;  // digits before the point
  if (whole > 0) {                   // 1234e-2 -> 12.34
    std::memcpy(out, digits, static_cast<size_t>(whole));
    out[whole] = '.';
    std::memcpy(out + whole + 1, digits + whole, static_cast<size_t>(len - whole));
    return out + len + 1;
  }
  *out++ = '0';  // 1234e-6 -> 0.001234
  *out++ = '.';
  std::memset(out, '0', static_cast<size_t>(-whole));
  out += -whole;
  std::memcpy(out, digits, static_cast<size_t>(len));
  return out + len;
}

}  // namespace

char* writeShortestSlow(char* out, double v) {
  v += 0.0;  // -0 prints as 0
  if (!std::isfinite(v)) [[unlikely]]
    return writeShortestFmt(out, v);
  if (std::signbit(v)) {
    *out++ = '-';
    v = -v;
  }
  // {fmt}'s own shortest-round-trip conversion (Dragonbox), without its formatting machinery:
  // the same decimal, laid out by its rules (docs/performance.md §32).
  const auto dec = fmt::detail::dragonbox::to_decimal(v);
  char digits[24];
  char* const end = digits + sizeof digits;
  const char* first = digitsBefore(end, dec.significand);
  return layOut(out, first, static_cast<int>(end - first), dec.exponent);
}

namespace {

// Decimals of the number text [begin, end) in fixed notation.
int decimalsOf(const char* begin, const char* end) {
  const char* dot = std::find(begin, end, '.');
  return dot == end ? 0 : static_cast<int>(end - dot - 1);
}

}  // namespace

char* writeFixedDecimals(char* out, size_t size, double v, int decimals) {
  auto r = fmt::format_to_n(out, size, "{:.{}f}", v, decimals);
  char* end = out + std::min(r.size, size);
  if (std::find(out, end, '.') != end) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  if (end - out == 2 && out[0] == '-' && out[1] == '0') {  // rounded to zero: no sign
    out[0] = '0';
    end = out + 1;
  }
  return end;
}

char* writeRounded(char* out, double v, int decimals) {
  if (char* end = writeFixed(out, v); end && decimalsOf(out, end) <= decimals) return end;
  const double a = v < 0 ? -v : v;
  char* end = writeShortestSlow(out, v);
  if (!(a < 1e15)) return end;  // huge, infinite or NaN: as without --decimals
  if (std::find(out, end, 'e') == end && decimalsOf(out, end) <= decimals) return end;
  // Below 1e15: at most 15 digits, sign, point and 17 decimals.
  return writeFixedDecimals(out, kRoundedRoom, v, decimals);
}

}  // namespace ncoffset::out
