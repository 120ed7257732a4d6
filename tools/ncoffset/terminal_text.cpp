#include "terminal_text.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "progress_line.hpp"

namespace ncoffset::cli {

namespace {

// Length of the valid UTF-8 sequence starting at text[i] (2..4 bytes), 0 if there is none.
size_t utf8Length(std::string_view text, size_t i) {
  auto c = static_cast<unsigned char>(text[i]);
  size_t len = c >= 0xC2 && c <= 0xDF   ? 2
               : c >= 0xE0 && c <= 0xEF ? 3
               : c >= 0xF0 && c <= 0xF4 ? 4
                                        : 0;
  if (len == 0 || i + len > text.size()) return 0;
  for (size_t k = 1; k < len; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
  auto c1 = static_cast<unsigned char>(text[i + 1]);
  if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0) || (c == 0xF0 && c1 < 0x90) ||
      (c == 0xF4 && c1 >= 0x90))
    return 0;                             // overlong, surrogate or beyond U+10FFFF
  if (c == 0xC2 && c1 <= 0x9F) return 0;  // a C1 control
  return len;
}

}  // namespace

std::string terminalSafe(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out.push_back(static_cast<char>(c));
      ++i;
    } else if (size_t len = c >= 0x80 ? utf8Length(text, i) : 0) {
      out.append(text.substr(i, len));
      i += len;
    } else {
      fmt::format_to(std::back_inserter(out), "\\x{:02x}", c);
      ++i;
    }
  }
  return out;
}

void printError(std::string_view line) {
  clearProgressLine();
  std::string safe = terminalSafe(line);
  safe.push_back('\n');
  std::fwrite(safe.data(), 1, safe.size(), stderr);
}

std::string sourceContext(const SourceLoc& where, std::string_view source) {
  if (source.empty()) return {};
  const std::string number = std::to_string(where.line);
  const std::string gutter(number.size(), ' ');
  std::string out = " " + number + " | " + terminalSafe(source) + "\n";
  if (where.column <= 0 || static_cast<size_t>(where.column) > source.size() + 1) return out;
  // The caret under the column as the line is shown: a tab stays a tab, an escaped control
  // character takes its \xNN width, a UTF-8 character one place.
  std::string pad;
  for (unsigned char c : terminalSafe(source.substr(0, static_cast<size_t>(where.column) - 1)))
    if (c == '\t')
      pad.push_back('\t');
    else if ((c & 0xC0) != 0x80)
      pad.push_back(' ');
  return out + " " + gutter + " | " + pad + "^\n";
}

void printSourceContext(const SourceLoc& where, std::string_view source) {
  const std::string text = sourceContext(where, source);
  std::fwrite(text.data(), 1, text.size(), stderr);
}

}  // namespace ncoffset::cli
