// Fuzz target: the lexer/parser on one block (src/lang). Any input must parse or raise an
// AlarmError; nothing else (no crash, no other exception, no sanitizer report).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  static ncoffset::lang::Block block;  // reused like the interpreter does
  try {
    ncoffset::lang::parseBlock(text, 1, block, {});
  } catch (const ncoffset::AlarmError&) {
  }
  std::string normalized;
  ncoffset::lang::normalizeLine(text, normalized, nullptr);
  (void)ncoffset::lang::scanLineHead(normalized);
  return 0;
}
