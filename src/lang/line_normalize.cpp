// Line normalisation (lang/line_normalize.hpp): upper case outside strings, the comment cut,
// tabs as blanks, and the check that nothing but printable ASCII stands outside
// comments and strings (alarm 99011 in parseBlock). Plain lines are copied eight bytes at a
// time: most blocks of CAM programs are already upper case and need no change.
#include "lang/line_normalize.hpp"

#include <cstdint>
#include <cstring>

#include "lang/parser.hpp"

namespace ncoffset::lang {
namespace {
// Byte classes for normalizeLine: 0 = not allowed outside strings/comments, 1 = copy as is,
// 2 = ';' (comment starts), 3 = '"' (string starts), 4 = tab, to blank.
struct ByteTable {
  unsigned char cls[256];
  char upper[256];
  constexpr ByteTable() : cls(), upper() {
    for (int c = 0; c < 256; ++c) {
      cls[c] = (c >= 32 && c <= 126) ? 1 : 0;
      upper[c] = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    }
    cls[static_cast<int>(';')] = 2;
    cls[static_cast<int>('"')] = 3;
    // A tab is a blank. CR, FF and VT are not: a CR that ends a line never gets here (nextLine
    // takes it with the LF), and one inside a line would make two lines of one for the reader.
    cls[static_cast<int>('\t')] = 4;
    upper[static_cast<int>('\t')] = ' ';
  }
};
constexpr ByteTable kBytes;
}  // namespace

bool normalizeInto(std::string_view text, std::string& out, size_t& len, int* bad_column) {
  const size_t n = text.size();
  if (out.size() < n + 1) out.resize(n + 1);
  char* const begin = out.data();
  char* dst = begin;
  size_t k = 0;
  // Eight bytes at a time while they are plain upper-case text (0x20..0x5F, no ';' or '"').
  constexpr std::uint64_t kOnes = 0x0101010101010101ULL, kHigh = 0x8080808080808080ULL;
  auto hasLess = [](std::uint64_t x, unsigned n) { return (x - kOnes * n) & ~x & kHigh; };
  auto hasZero = [](std::uint64_t x) { return (x - kOnes) & ~x & kHigh; };
  auto plain = [&](size_t at, std::uint64_t& w) {
    std::memcpy(&w, text.data() + at, 8);
    return !(hasLess(w, 0x20) || ((w + kOnes * (0x80 - 0x60)) | w) & kHigh ||
             hasZero(w ^ (kOnes * ';')) || hasZero(w ^ (kOnes * '"')));
  };
  while (k + 8 <= n) {
    std::uint64_t w;
    if (!plain(k, w)) break;
    std::memcpy(dst, &w, 8);
    dst += 8;
    k += 8;
  }
  // The rest of a plain line as one more (overlapping) group of eight.
  if (k < n && n >= 8 && k + 8 > n) {
    std::uint64_t w;
    if (plain(n - 8, w)) {
      std::memcpy(begin + (n - 8), &w, 8);
      begin[n] = '\0';
      len = n;
      return true;
    }
  }
  while (k < n) {
    auto c = static_cast<unsigned char>(text[k]);
    switch (kBytes.cls[c]) {
      case 1:
      case 4:
        *dst++ = kBytes.upper[c];
        ++k;
        continue;
      case 2:
        k = n;
        continue;  // comment: the rest of the line
      case 3: {
        *dst++ = '"';
        ++k;
        while (k < n && text[k] != '"') {
          if (text[k] == '\0') {
            if (bad_column) *bad_column = static_cast<int>(k) + 1;
            len = static_cast<size_t>(dst - begin);
            return false;
          }
          *dst++ = text[k++];
        }
        if (k < n) *dst++ = text[k++];
        continue;
      }
      default:
        if (bad_column) *bad_column = static_cast<int>(k) + 1;
        len = static_cast<size_t>(dst - begin);
        return false;
    }
  }
  *dst = '\0';
  len = static_cast<size_t>(dst - begin);
  return true;
}

bool normalizeLine(std::string_view text, std::string& out, int* bad_column) {
  size_t len = 0;
  const bool ok = normalizeInto(text, out, len, bad_column);
  out.resize(len);
  return ok;
}

}  // namespace ncoffset::lang
