// The entry points of lang/parser.hpp: parseBlock (the fast path on the block as written, else
// normalisation and the general parser), the block head every block may start with (PM-NC
// "Program structure": `/` skippable block with its level, `N<no>` or `:<no>` block number,
// `NAME:` label) and scanLineHead for the control-structure pre-scan.
#include "lang/parser.hpp"

#include <cstdio>
#include <string>

#include "lang/block_parser.hpp"
#include "lang/line_copy.hpp"
#include "lang/line_normalize.hpp"
#include "ncoffset/alarm.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset::lang {

static_assert(kMaxExpressionDepth == Limits::kMaxExpressionDepth);

void Parser::syntax(const std::string& what) const {
  std::string near(s_.substr(i_ < s_.size() ? i_ : s_.size(), 24));
  // The column goes with the alarm too, for the caret under the source line.
  throw AlarmError(AlarmNumber::SyntaxError,
                   "syntax error in text at column " + std::to_string(column()) +
                       (near.empty() ? std::string(" (end of block)") : " near '" + near + "'") +
                       ": " + what,
                   0, column());
}

void Parser::parse() {
  skipSpaces();
  if (peek() == '/') {
    b_.skip = true;
    ++i_;
    if (isDigit(peek())) b_.skip_level = s_[i_++] - '0';
    skipSpaces();
  }
  if ((peek() == 'N' && isDigit(peek(1))) || (peek() == ':' && isDigit(peek(1)))) {
    ++i_;
    b_.has_number = true;
    b_.number = readInteger();
    skipSpaces();
  }
  // Label: identifier directly followed by ':'.
  if (isAlpha(peek())) {
    size_t j = i_;
    while (j < s_.size() && isIdentChar(s_[j])) ++j;
    if (j < s_.size() && s_[j] == ':' && j - i_ >= 2) {
      if (j - i_ > 32) syntax("labels have at most 32 characters");
      if (!isLabelStart(s_[i_], s_[i_ + 1]))
        syntax(std::string(s_.substr(i_, j - i_)) +
               ": is no label (a label name starts with two letters or underscores)");
      b_.label = s_.substr(i_, j - i_);
      i_ = j + 1;
    }
  }
  if (simpleWords()) return;
  while (true) {
    skipSpaces();
    if (i_ >= s_.size()) break;
    statement();
  }
}

bool Parser::parseWritten() {
  skipSpaces();
  if (peek() == 'N' && isDigit(peek(1))) {
    // One pass over the digits (the '\0' after the block ends it); more than 18 digits is
    // left to the general path, which raises the alarm.
    size_t j = i_ + 1;
    unsigned long long v = 0;
    while (isDigit(s_[j])) v = v * 10 + static_cast<unsigned>(s_[j++] - '0');
    if (j - i_ - 1 > 18) return false;
    i_ = j;
    b_.has_number = true;
    b_.number = static_cast<long long>(v);
  }
  return simpleWords();
}

namespace {

// The name of a control byte that programs written on other systems hold by mistake.
const char* byteName(unsigned char c) {
  switch (c) {
    case 0x00:
      return " (NUL)";
    case 0x0B:
      return " (vertical tab)";
    case 0x0C:
      return " (form feed)";
    case 0x0D:
      return " (carriage return not followed by a line feed)";
    default:
      return "";
  }
}

}  // namespace

void parseBlock(std::string_view text, int line, Block& out, const ParseLimits& requested) {
  ParseLimits limits = requested;
  if (limits.max_expression_depth > kMaxExpressionDepth)
    limits.max_expression_depth = kMaxExpressionDepth;  // what the stack allows
  out.clear();
  out.line = line;
  // Most blocks of CAM programs (N10 G1 X10.5 Y2 F1000) are plain upper-case words, which
  // normalising would leave as they are: the fast path tries the block as written first.
  const size_t n = text.size();
  copyWritten(text, out.buffer);
  if (Parser(out, std::string_view(out.buffer.data(), n), limits).parseWritten()) return;
  out.clear();
  out.line = line;
  int bad = 0;
  size_t len = 0;
  if (!normalizeInto(text, out.buffer, len, &bad)) {
    unsigned char c = static_cast<unsigned char>(text[static_cast<size_t>(bad - 1)]);
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", c);
    raise(AlarmNumber::BadCharacter, "character " + std::string(hex) + byteName(c) + " at column " +
                                         std::to_string(bad) +
                                         " is not allowed outside comments and strings");
  }
  Parser p(out, std::string_view(out.buffer.data(), len), limits);
  p.parse();
}

LineHead scanLineHead(std::string_view s) {
  LineHead h;
  size_t i = 0;
  auto spaces = [&] {
    while (i < s.size() && s[i] == ' ') ++i;
  };
  spaces();
  if (i < s.size() && s[i] == '/') {
    ++i;
    if (i < s.size() && isDigit(s[i])) ++i;
    spaces();
  }
  if (i + 1 < s.size() && (s[i] == 'N' || s[i] == ':') && isDigit(s[i + 1])) {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i;
    spaces();
  }
  size_t j = i;
  while (j < s.size() && isIdentChar(s[j])) ++j;
  if (j < s.size() && s[j] == ':' && j - i >= 2 && isLabelStart(s[i], s[i + 1])) {
    h.label = s.substr(i, j - i);
    i = j + 1;
    spaces();
    j = i;
    while (j < s.size() && isIdentChar(s[j])) ++j;
  }
  if (i < s.size() && isAlpha(s[i])) h.keyword = s.substr(i, j - i);
  h.has_arguments = !h.keyword.empty() && s.find_first_not_of(' ', j) != std::string_view::npos;
  if (h.keyword == "IF") {
    // IF <cond> GOTOx <target> is a conditional jump, not a structure.
    for (size_t k = j; k + 4 <= s.size(); ++k) {
      if (s.compare(k, 4, "GOTO") == 0 && (k == 0 || !isIdentChar(s[k - 1]))) {
        size_t e = k + 4;
        if (e < s.size() && (s[e] == 'F' || s[e] == 'B' || s[e] == 'C')) ++e;
        if (e >= s.size() || !isIdentChar(s[e])) {
          h.has_goto = true;
          break;
        }
      }
    }
  }
  return h;
}

}  // namespace ncoffset::lang
