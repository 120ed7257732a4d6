// Fuzz target: the lexer/parser on one block (src/lang). Any input must parse or raise an
// AlarmError; nothing else (no crash, no other exception, no sanitizer report). And the
// parser's fast path (plain address words, parsed as written) must make exactly the statements
// the general parser makes: with a bare name in front ("CDON ") the same words go through the
// general path, so both parses are compared word by word (tests/lang/parser_test.cpp does the
// same on random blocks).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace {

bool parses(std::string_view text, ncoffset::lang::Block& block) {
  try {
    ncoffset::lang::parseBlock(text, 1, block, {});
    return true;
  } catch (const ncoffset::AlarmError&) {
    return false;
  }
}

// Same words, shifted by `shift` columns (literal values bit for bit).
bool sameWords(const ncoffset::lang::Block& a, const ncoffset::lang::Block& b, size_t from_b,
               int shift) {
  if (a.stmts.size() + from_b != b.stmts.size()) return false;
  for (size_t i = 0; i < a.stmts.size(); ++i) {
    const auto& x = a.stmts[i];
    const auto& y = b.stmts[i + from_b];
    if (x.kind != y.kind || x.name != y.name || x.ext != y.ext || x.mode != y.mode ||
        x.has_equals != y.has_equals || x.literal != y.literal || x.column + shift != y.column)
      return false;
    if (x.literal && (x.literal_int != y.literal_int || x.literal_value != y.literal_value))
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  static ncoffset::lang::Block block, general;  // reused like the interpreter does
  const bool ok = parses(text, block);
  // Compared where the block's head cannot differ: no block number, label or skip level.
  if (ok && !block.has_number && block.label.empty() && !block.skip &&
      parses("CDON " + std::string(text), general) && !sameWords(block, general, 1, 5))
    __builtin_trap();
  std::string normalized;
  ncoffset::lang::normalizeLine(text, normalized, nullptr);
  (void)ncoffset::lang::scanLineHead(normalized);
  return 0;
}
