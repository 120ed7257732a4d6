// The fast path for the blocks CAM systems write (`G1 X10.5 Y-2 F1000`, `G3 X5 Y5 CR=10`; PM-NC
// "Fundamentals of NC programming", "Addresses"): only address words with a plain number,
// single letters (X10) or extended addresses with '=' (CR=10). It makes the same statements the
// general path makes for these words, with the same number scan (lang/number_scan.hpp); at the
// first thing it does not know it drops what it made and returns false, and the general path
// parses the block from the same position (and reports any error).
#include "lang/block_parser.hpp"

namespace ncoffset::lang {

bool Parser::simpleWords() {
  // A '\0' follows the block's last character (normalizeInto lets no other '\0' through),
  // which ends every scan below without a length check.
  const char* const base = s_.data();
  const char* p = base + i_;
  const size_t first = b_.stmts.size();
  auto isBlank = [](char c) { return c == ' ' || c == '\t'; };
  auto isLetter = [](char c) { return c >= 'A' && c <= 'Z'; };
  auto give_up = [&] {
    b_.stmts.resize(first);
    return false;
  };
  while (isBlank(*p)) ++p;
  while (*p != '\0') {
    const char* const word = p;
    if (!isLetter(*p)) return give_up();
    ++p;
    while (isLetter(*p)) ++p;
    const std::string_view name(word, static_cast<size_t>(p - word));
    const bool equals = name.size() > 1;
    if (equals) {
      // CR=10: an extended address directly followed by '=' (no '==').
      if (*p != '=' || p[1] == '=' || !isExtendedAddress(name)) return give_up();
      ++p;
    }
    bool negative = false;
    if (*p == '-' || *p == '+') negative = *p++ == '-';
    // Only numbers that convert exactly inline; longer ones take the general path.
    const DecimalDigits digits = scanDigits(p);
    if (digits.digits == 0 || digits.digits > kExactDigits) return give_up();
    p = digits.end;
    // What may follow: the end, a blank, or (single letters only: G1X10) the next address
    // but not an exponent (1EX3). After single letters a '=' makes an assignment (R1=5,
    // M2=6, I1=5).
    const char* next = p;
    while (isBlank(*next)) ++next;
    if (equals) {
      if (next == p && *p != '\0') return give_up();
    } else {
      if (next == p && *p != '\0' && (!isLetter(*p) || (p[0] == 'E' && p[1] == 'X')))
        return give_up();
      if (*next == '=' || (*word == 'R' && isDigit(word[1]))) return give_up();
    }
    const double v = exactValue(digits);
    Stmt st;
    st.kind = StmtKind::Word;
    st.name = name;
    st.column = static_cast<int>(word - base) + 1;
    st.has_equals = equals;
    st.literal = true;
    st.literal_int = !digits.point;
    st.literal_value = negative ? -v : v;
    b_.stmts.push_back(st);
    p = next;
  }
  if (p != base + s_.size()) return give_up();  // a '\0' inside the block (not normalised)
  i_ = s_.size();
  b_.plain = true;
  return true;
}

}  // namespace ncoffset::lang
