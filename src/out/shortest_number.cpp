#include "out/shortest_number.hpp"

#include <fmt/compile.h>

namespace ncoffset::out {

char* writeShortestSlow(char* out, double v) {
  return fmt::format_to(out, FMT_COMPILE("{}"), v + 0.0);  // -0 prints as 0
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
