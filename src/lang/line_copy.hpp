// The copy of a line that the block scans read: parseBlock's (lang/parser.cpp) and the
// interpreter's plain line (interp/plain_line.cpp), both ended by a '\0' so that the scans need
// no length checks (lang/number_scan.hpp).
#pragma once

#include <cstring>
#include <string>
#include <string_view>

namespace ncoffset::lang {

// `text` copied to the beginning of `buffer` with a '\0' after it (the buffer only grows), for
// the scans that rely on that '\0'; the copy's first character.
inline char* copyWritten(std::string_view text, std::string& buffer) {
  const size_t n = text.size();
  if (buffer.size() < n + 1) buffer.resize(n + 1);
  char* const copy = buffer.data();
  // The usual lengths in two (overlapping) groups, no call.
  if (n >= 8 && n <= 16) {
    std::memcpy(copy, text.data(), 8);
    std::memcpy(copy + n - 8, text.data() + n - 8, 8);
  } else if (n > 16 && n <= 32) {
    std::memcpy(copy, text.data(), 16);
    std::memcpy(copy + n - 16, text.data() + n - 16, 16);
  } else if (n >= 4 && n < 8) {
    std::memcpy(copy, text.data(), 4);
    std::memcpy(copy + n - 4, text.data() + n - 4, 4);
  } else {
    std::memcpy(copy, text.data(), n);
  }
  copy[n] = '\0';
  return copy;
}

}  // namespace ncoffset::lang
