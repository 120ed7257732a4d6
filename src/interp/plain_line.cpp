// The per-block fast paths of the interpreter for the blocks CAM systems write (docs/performance.md
// sections 25, 27 and 30): plain blocks (Parser::simpleWords) collected without looking at
// statement kinds, and plain lines of X, Y, Z, G0..G3, F and CR= words collected as they are
// scanned, with no statement at all. Each hands whatever it does not know to the general path;
// tests/interp/fast_path_test.cpp compares them with it.

#include <cstdint>

#include "core/inline_step.hpp"
#include "interp/interpreter.hpp"
#include "lang/line_copy.hpp"
#include "lang/number_scan.hpp"

namespace ncoffset::interp {

// The commonest words of plain blocks collected inline: X, Y, Z, G0..G3, F and CR=, as
// letterWord, gCode and extendedWord collect them, without the call; a G word sets `motion`.
// False: collectWord takes the word (and raises any alarm).
NCOFFSET_INLINE_STEP bool Interpreter::plainWord(std::string_view name, double value, bool is_int,
                                                 Motion& motion) {
  if (name.size() != 1) {
    if (name != "CR" || words_.cr || vars_.find(name)) return false;
    words_.cr = value;  // the circle radius (extendedWord)
    return true;
  }
  const char c = name[0];
  if (c >= 'X' && c <= 'Z') {
    const int i = c - 'X';
    if (words_.axis[i]) return false;  // programmed twice: collectWord's alarm
    words_.axis[i] = true;
    words_.axis_value[i] = value;
    words_.axis_mode[i] = lang::AxisMode::Default;
    return true;
  }
  if (c == 'G' && is_int && value >= 0 && value <= 3) {
    motion = static_cast<Motion>(static_cast<int>(value));  // G0 G1 G2 G3
    words_.motion_word = true;
    return true;
  }
  if (c == 'F' && value >= 0 && value <= 1e9) {
    words_.f = value;
    return true;
  }
  return false;
}

// executeBlock for a plain block (words_ already cleared): only address words with a plain
// number (G1 X10 CR=5), no definition, jump or expression among them.
void Interpreter::executePlainBlock(const lang::Block& b) {
  flow_.level().defs_allowed = false;
  bool all_plain = true;
  for (const lang::Stmt& st : b.stmts) {
    if (!plainWord(st.name, st.literal_value, st.literal_int, modal_.motion)) {
      column_ = st.column;  // plainWord raises no alarm: only collectWord needs the column
      all_plain = false;
      collectWord(st);
    }
  }
  // Block end writes to words_ only in a contour definition, a carrier change or MCALL.
  all_plain = all_plain && !contour_active_ && !carrier_.pending && !mcall_.active;
  all_plain ? finishPlainBlock(b.stmts.front().column) : finishBlock();
  words_plain_ = all_plain;
}

namespace {

// One word of a plain line at `p` (no blank before it): X, Y, Z, G or F with a number, or CR=
// with a number, the number of at most kExactDigits digits; its end after the blanks behind
// it in `next`. Stricter than Parser::simpleWords: what follows a number directly must be the
// next word's letter, which the next call checks (so "1EX3", "X1=2" and "X1;" fail there);
// CR=10 must be followed by a blank or the end, as simpleWords requires.
struct LineWord {
  std::string_view name;
  double value = 0;
  bool is_int = false;
  const char* next = nullptr;
};

NCOFFSET_INLINE_STEP bool scanLineWord(const char* p, LineWord& w) {
  const char c = *p;
  const char* const word = p;
  size_t len = 1;
  if ((c >= 'X' && c <= 'Z') || c == 'G' || c == 'F') {
    ++p;
  } else if (c == 'C' && p[1] == 'R' && p[2] == '=') {
    len = 2;
    p += 3;
  } else {
    return false;
  }
  bool negative = false;
  if (*p == '-' || *p == '+') negative = *p++ == '-';
  const lang::DecimalDigits digits = lang::scanDigits(p);
  if (digits.digits == 0 || digits.digits > lang::kExactDigits) return false;
  p = digits.end;
  if (len == 2 && *p != ' ' && *p != '\t' && *p != '\0') return false;
  while (*p == ' ' || *p == '\t') ++p;
  const double v = lang::exactValue(digits);
  w.name = std::string_view(word, len);
  w.value = negative ? -v : v;
  w.is_int = !digits.point;
  w.next = p;
  return true;
}

}  // namespace

// plainLine without the test for lines refused before.
NCOFFSET_INLINE_STEP bool Interpreter::scanPlainLine(std::string_view text) {
  const char* const base = lang::copyWritten(text, line_copy_);
  const char* p = base;
  while (*p == ' ' || *p == '\t') ++p;
  if (*p == 'N' && lang::isDigit(p[1])) {  // the block number (more than 18 digits: alarm)
    const char* q = p + 1;
    while (lang::isDigit(*q)) ++q;
    if (q - p - 1 > 18) return false;
    p = q;
    while (*p == ' ' || *p == '\t') ++p;
  }
  LineWord w;
  if (!scanLineWord(p, w)) return false;  // also an empty line or a comment
  plain_column_ = static_cast<int>(p - base) + 1;
  // Only plainWord's fields now (9 stores): executeBlock clears the rest if the line is not
  // plain after all, the end below if it is.
  const bool was_plain = words_plain_;
  words_.clearPlain();
  Motion motion = modal_.motion;
  while (plainWord(w.name, w.value, w.is_int, motion)) {
    p = w.next;
    if (*p == '\0') {
      if (p != base + text.size()) return false;  // a '\0' inside the line
      if (!was_plain) words_.clearExceptPlain();  // after a block of other words
      modal_.motion = motion;
      flow_.level().defs_allowed = false;
      return true;
    }
    if (!scanLineWord(p, w)) return false;
  }
  return false;
}

// Parser::parseWritten, Parser::simpleWords and executePlainBlock in one pass, for a line whose
// every word plainWord collects (an optional block number first): the same number scan, the
// same words in the same order, and finishPlainBlock (by finishPlainLine) under the same
// conditions. It accepts no line that simpleWords would not (scanLineWord is stricter). False
// leaves the line to the parser and executeBlock; words_ then holds what it held with
// plainWord's fields changed, which executeBlock clears (words_plain_ as before), and the modal
// motion is as before.
bool Interpreter::plainLine(std::string_view text) {
  if (contour_active_ || carrier_.pending || mcall_.active) [[unlikely]]
    return false;
  // A line refused before (a loop's lines: refused once, not on every pass), by the address
  // of its text. A stale entry (the text's memory reused) only sends a line to the general
  // path, which is never wrong.
  const char*& refused = refused_[(reinterpret_cast<std::uintptr_t>(text.data()) >> 4) % 32];
  if (refused == text.data()) return false;
  if (scanPlainLine(text)) return true;
  refused = text.data();
  return false;
}

void Interpreter::finishPlainLine() {
  words_plain_ = false;  // until the block is through without an alarm (executeBlock)
  finishPlainBlock(plain_column_);
  words_plain_ = true;
}

}  // namespace ncoffset::interp
