// The parser of one block (lang/parser.hpp has the entry points). Its parts are in separate
// files, one concern each:
//   parser.cpp             parseBlock, the block head (skip level, block number, label)
//   simple_words.cpp       the fast path for blocks of plain address words (G1 X10 CR=5)
//   expression_parser.cpp  operands and operators by priority (PM-NC "Arithmetic operators")
//   statement_parser.cpp   address words, assignments, calls
//   control_parser.cpp     DEF, IF/WHILE/UNTIL, FOR, CASE and the jumps
//   call_parser.cpp        PROC with its parameters, EXTERN, MCALL, CALL, PCALL
// and, shared with other users: line_normalize.cpp (upper case, comment cut, bad bytes),
// lexical.hpp (character classes, name lists), number_scan.hpp (the one scan of numbers).
// Small helpers that every part uses are inline here. Member functions declared `inline` below
// are defined and used in their own file only: the compiler may then inline them into their
// callers as it could when the parser was one file (the general path costs no more calls).
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include "lang/block.hpp"
#include "lang/lexical.hpp"
#include "lang/number_scan.hpp"
#include "lang/parser.hpp"

namespace ncoffset::lang {

class Parser {
 public:
  // `text`: the block (normalised, or as written for parseWritten), followed by a '\0'.
  Parser(Block& b, std::string_view text, const ParseLimits& limits)
      : b_(b), s_(text), limits_(limits) {}

  // The whole normalised block; throws AlarmError.
  inline void parse();
  // parse() for a block as written (not normalised): only blocks the fast path takes entirely,
  // with at most a block number N.. in front (no skip level, label or anything that could
  // raise an alarm). False: nothing is decided, the block must be normalised and parsed.
  inline bool parseWritten();

 private:
  Block& b_;
  const std::string_view s_;
  const ParseLimits& limits_;
  size_t i_ = 0;
  int depth_ = 0;

  // --- shared helpers (inline) ----------------------------------------------------------------
  char peek(size_t k = 0) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  void skipSpaces() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
  }
  int column() const { return static_cast<int>(i_) + 1; }
  // Alarm 12080 naming the column and the text near it.
  [[noreturn]] void syntax(const std::string& what) const;
  void expect(char c, const char* what) {
    skipSpaces();
    if (peek() != c) syntax(std::string("expected ") + what);
    ++i_;
  }
  std::string_view ident() {
    size_t j = i_;
    while (j < s_.size() && isIdentChar(s_[j])) ++j;
    std::string_view v = s_.substr(i_, j - i_);
    i_ = j;
    return v;
  }
  long long readInteger() {
    long long v = 0;
    int digits = 0;
    while (isDigit(peek())) {
      if (++digits > 18) syntax("number too long");
      v = v * 10 + (s_[i_++] - '0');
    }
    return v;
  }
  int addNode(const Node& n) {
    b_.nodes.push_back(n);
    return static_cast<int>(b_.nodes.size()) - 1;
  }
  // The number at the current position (lang/number_scan.hpp), moving past it.
  double scanNumber(bool& is_int) {
    const NumberScan r = lang::scanNumber(s_.data() + i_);
    if (r.error) {
      i_ = static_cast<size_t>(r.error_at - s_.data());
      syntax(r.error);
    }
    i_ = static_cast<size_t>(r.end - s_.data());
    is_int = r.is_int;
    return r.value;
  }
  // The word `w` at the current position, not followed by a name character.
  bool wordAhead(std::string_view w) const {
    if (s_.compare(i_, w.size(), w) != 0) return false;
    size_t j = i_ + w.size();
    return j >= s_.size() || !isIdentChar(s_[j]);
  }
  // R1, R99: an R parameter written as a name.
  static bool isRParamName(std::string_view v) {
    if (v.size() < 2 || v[0] != 'R') return false;
    for (char c : v.substr(1))
      if (!isDigit(c)) return false;
    return true;
  }
  double parseDigits(std::string_view v) const {
    if (v.size() > 9) syntax("R parameter number too large");
    double r = 0;
    for (char c : v) r = r * 10 + (c - '0');
    return r;
  }

  // --- simple_words.cpp -------------------------------------------------------------------------
  bool simpleWords();

  // --- expression_parser.cpp --------------------------------------------------------------------
  int expression() { return binary(0); }
  inline int number(bool negative);
  int quotedConstant();
  int stringLiteral();
  std::pair<int, int> argList(char close);
  int primary();
  int unary();
  inline bool binaryOp(Op& op, int& prio, size_t& len) const;
  // Counts one nesting level against ParseLimits::max_expression_depth (alarm 99003).
  void enter() {
    if (++depth_ > limits_.max_expression_depth) depthAlarm();
  }
  [[noreturn]] void depthAlarm() const;
  void leave() { --depth_; }
  int binary(int min_prio);

  // --- statement_parser.cpp ---------------------------------------------------------------------
  void statement();
  inline void nameAssignment(std::string_view name, int col);
  void indexedAssignment(std::string_view name, int col);
  void procedureCall(std::string_view name, int col);
  void pushProcedureCall(std::string_view name, int first, int count, int col);
  inline bool literalWord(std::string_view name, int col);
  static inline Stmt wordStmt(std::string_view address, int col, bool equals);
  void addWord(std::string_view address, int ext, int value, int col, bool equals);
  void numericAddress(int col);
  inline void plainWord(std::string_view address, int col);

  // --- control_parser.cpp -----------------------------------------------------------------------
  int jumpTarget();
  void controlStatement(std::string_view kw, int col);
  void repeatStatement(Stmt& st);
  bool attribute(DefAttributes& a);
  void macroDefinition(Stmt& st);
  void forStatement(Stmt& st);
  static bool typeOf(std::string_view w, VarType& t);
  void caseArms();
  void definition(int col);
  void declarator(VarType type, int string_length);
  void checkVariableName(std::string_view name, size_t at);
  void checkOneLetterName(char letter, bool array);
  void arrayInitialiser(Decl& d);

  // --- call_parser.cpp --------------------------------------------------------------------------
  void callStatement(Stmt& st);
  void procHeader(Stmt& st);
  void programWithParameters(Stmt& st, bool formal);
  void parameterList(bool named);
  void formalParameter(bool named);
  int programName(bool path);
  void callBlockRange(Stmt& st);
};

}  // namespace ncoffset::lang
