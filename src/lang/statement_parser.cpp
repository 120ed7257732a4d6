// Statements that are no control keywords (PM-NC "Fundamentals of NC programming", "Addresses";
// PM-JP "Flexible NC programming", "Variables"): address words (X10, X=R1+2, M2=6, CR=10,
// X=AC(5)), assignments to R parameters and variables (R1=5, VAR[1]=2, $TC_DP1[1,1]=120),
// procedure calls as statements (MSG(..)) and subprogram calls by name.
#include <string>

#include "lang/block_parser.hpp"

namespace ncoffset::lang {

namespace {

// The operator words (DIV, MOD, AND, ...) at `j`, not followed by a name character. A call of
// its own, not inlined: literalWord runs for every `CR=10` word of a block and stays small.
[[gnu::noinline]] bool operatorWordAt(std::string_view s, size_t j) {
  for (std::string_view w : {"DIV", "MOD", "AND", "OR", "XOR", "B_AND", "B_OR", "B_XOR"}) {
    if (s.compare(j, w.size(), w) == 0 &&
        (j + w.size() >= s.size() || !isIdentChar(s[j + w.size()])))
      return true;
  }
  return false;
}

}  // namespace

void Parser::statement() {
  int col = column();
  char c = peek();
  if (!isAlpha(c)) {
    if (c == '=') syntax("address or variable expected before '='");
    syntax("address or name expected");
  }
  // Single-letter address followed by a plain number: X10, G1, M30, X-5.5, T1, D1, R1=..
  char n1 = peek(1);
  if (c != '$' && c != '_' &&
      (isDigit(n1) ||
       ((n1 == '.' || n1 == '-' || n1 == '+') && (isDigit(peek(2)) || peek(2) == '.')))) {
    numericAddress(col);
    return;
  }
  std::string_view name = ident();
  skipSpaces();
  if (isControlKeyword(name)) {
    controlStatement(name, col);
    return;
  }
  if (peek() == '=' && peek(1) != '=') {
    nameAssignment(name, col);
    return;
  }
  if (peek() == '[') {
    indexedAssignment(name, col);
    return;
  }
  if (peek() == '(') {
    procedureCall(name, col);
    return;
  }
  // Programs are called by names of at least two characters (PM-NC 12/2019 p491): a lone
  // letter is an address whose value is missing.
  if (name.size() == 1) syntax(std::string("value missing after address ") + name[0]);
  Stmt st;
  st.kind = StmtKind::Call;
  st.name = name;
  st.column = col;
  b_.stmts.push_back(st);
}

// `NAME=value` at the '=': an extended address word (CR=5) or an assignment to a variable.
void Parser::nameAssignment(std::string_view name, int col) {
  const bool address = isExtendedAddress(name);
  if (address && literalWord(name, col)) return;
  ++i_;
  int value = expression();
  if (address) {
    addWord(name, -1, value, col, true);
    return;
  }
  Node t;
  t.kind = NodeKind::Name;
  t.text = name;
  Stmt st;
  st.kind = StmtKind::Assign;
  st.name = name;
  st.target = addNode(t);
  st.expr = value;
  st.column = col;
  b_.stmts.push_back(st);
}

// `NAME[indices]=value` at the '[' (or DIAMONA[X], a procedure with its axis in brackets).
void Parser::indexedAssignment(std::string_view name, int col) {
  ++i_;
  auto [first, count] = argList(']');
  if (isAxisProcedure(name)) {
    pushProcedureCall(name, first, count, col);
    return;
  }
  Node t;
  t.kind = name == "R" ? NodeKind::RIndex : NodeKind::Index;
  t.text = name;
  t.a = first;
  t.b = count;
  int target = addNode(t);
  skipSpaces();
  if (peek() != '=' || peek(1) == '=') syntax("'=' expected after indexed variable");
  ++i_;
  Stmt st;
  st.kind = StmtKind::Assign;
  st.name = name;
  st.target = target;
  st.expr = expression();
  st.column = col;
  b_.stmts.push_back(st);
}

// `NAME(args)` as a statement (MSG(..), CHANDATA(..), predefined procedures) at the '('.
void Parser::procedureCall(std::string_view name, int col) {
  ++i_;
  auto [first, count] = argList(')');
  pushProcedureCall(name, first, count, col);
}

// The ProcCall statement of `name` with the arguments [first, first + count).
void Parser::pushProcedureCall(std::string_view name, int first, int count, int col) {
  Node call;
  call.kind = NodeKind::Call;
  call.text = name;
  call.a = first;
  call.b = count;
  Stmt st;
  st.kind = StmtKind::ProcCall;
  st.name = name;
  st.expr = addNode(call);
  st.column = col;
  b_.stmts.push_back(st);
}

// `CR=10`, `DISR=-5.5`: an address with '=' and a plain number, the common case, kept as a
// literal word without an expression node (the same statement the expression path makes, only
// cheaper). Anything else (an operator, a function, 1EX3, AC(..)) takes the expression path.
bool Parser::literalWord(std::string_view name, int col) {
  const size_t save = i_;
  ++i_;  // '='
  bool negative = false;
  if (peek() == '-' || peek() == '+') negative = s_[i_++] == '-';
  if (!(isDigit(peek()) || (peek() == '.' && isDigit(peek(1))))) {
    i_ = save;
    return false;
  }
  bool is_int = false;
  const double v = scanNumber(is_int);
  size_t j = i_;
  while (j < s_.size() && s_[j] == ' ') ++j;
  // `X=7 DIV 3`, `CR=2 MOD 1`: an operator word continues the value (PM-NC p444); only a name
  // that is no operator starts the next word.
  const bool ends =
      j == s_.size() || s_[j] == ';' || (j > i_ && isAlpha(s_[j]) && !operatorWordAt(s_, j));
  if (!ends) {
    i_ = save;
    return false;
  }
  Stmt& st = b_.stmts.emplace_back(wordStmt(name, col, true));
  st.literal = true;
  st.literal_int = is_int;
  st.literal_value = negative ? -v : v;
  return true;
}

Stmt Parser::wordStmt(std::string_view address, int col, bool equals) {
  Stmt st;
  st.kind = StmtKind::Word;
  st.name = address;
  st.column = col;
  st.has_equals = equals;
  return st;
}

void Parser::addWord(std::string_view address, int ext, int value, int col, bool equals) {
  Stmt st = wordStmt(address, col, equals);
  st.ext = ext;
  st.expr = value;
  // X=AC(..) / X=IC(..): absolute or incremental dimension for this word only.
  const Node& v = b_.node(value);
  if (v.kind == NodeKind::Call &&
      (v.text == "AC" || v.text == "IC" || v.text == "DAC" || v.text == "DIC" || v.text == "RAC" ||
       v.text == "RIC" || v.text == "DC" || v.text == "ACP" || v.text == "ACN")) {
    if (v.b != 1) syntax(std::string(v.text) + " takes one value");
    // Diameter/radius and DC/ACP/ACN for one word: axes only (PM-NC "Axis-specific diameter
    // programming", "Absolute dimensions for rotary axes"); a longer name (an axis X1, or CR=)
    // is checked by the interpreter, which knows the axis names.
    // An axis name of several characters carries a digit (X1, AX4); CR=, DISR= are no axes.
    const bool axis_mode = v.text != "AC" && v.text != "IC";
    const bool axis_name = address.size() == 1
                               ? address[0] != 'I' && address[0] != 'J' && address[0] != 'K'
                               : address.find_first_of("0123456789") != std::string_view::npos;
    if (axis_mode && !axis_name)
      syntax(std::string(v.text) + " only with an axis, not with " + std::string(address));
    st.mode = v.text == "AC"    ? AxisMode::AC
              : v.text == "IC"  ? AxisMode::IC
              : v.text == "DAC" ? AxisMode::DAC
              : v.text == "DIC" ? AxisMode::DIC
              : v.text == "RAC" ? AxisMode::RAC
              : v.text == "RIC" ? AxisMode::RIC
              : v.text == "DC"  ? AxisMode::DC
              : v.text == "ACP" ? AxisMode::ACP
                                : AxisMode::ACN;
    st.expr = b_.arg(v, 0);
  }
  b_.stmts.push_back(st);
}

void Parser::numericAddress(int col) {
  std::string_view address = std::string_view(s_).substr(i_, 1);
  ++i_;
  if (address[0] == 'L') {
    // L123(args): a program with a number as its name, called with parameters (PM-JP
    // "Subprogram technique").
    size_t j = i_;
    while (j < s_.size() && isDigit(s_[j])) ++j;
    if (j > i_ && j < s_.size() && s_[j] == '(') {
      const std::string_view name = std::string_view(s_).substr(i_ - 1, j - i_ + 1);
      i_ = j;
      procedureCall(name, col);
      return;
    }
  }
  // The common word (X10, G1, F1000, T1 D1): digits not followed by '=' and no R parameter;
  // one scan decides it. Longer digit runs take the paths below, which report them.
  if (address[0] != 'R') {
    size_t j = i_;
    while (j < s_.size() && isDigit(s_[j])) ++j;
    size_t k = j;
    while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t')) ++k;
    const bool assignment =
        k < s_.size() && s_[k] == '=' && !(k + 1 < s_.size() && s_[k + 1] == '=');
    if (j - i_ <= 18 && !assignment) {
      plainWord(address, col);
      return;
    }
  }
  // R parameter assignment R1=..
  if (address == "R" && isDigit(peek())) {
    size_t start = i_;
    while (isDigit(peek())) ++i_;
    std::string_view digits = std::string_view(s_).substr(start, i_ - start);
    skipSpaces();
    if (peek() != '=' || peek(1) == '=') syntax("'=' expected after R parameter");
    ++i_;
    Node t;
    t.kind = NodeKind::RParam;
    t.number = parseDigits(digits);
    Stmt st;
    st.kind = StmtKind::Assign;
    st.name = "R";
    st.target = addNode(t);
    st.expr = expression();
    st.column = col;
    b_.stmts.push_back(st);
    return;
  }
  // Address extension: M2=6, S1=1000, H2=5, T1=..? (spindle / extension number).
  if ((address == "M" || address == "S" || address == "H" || address == "T" || address == "D" ||
       address == "F") &&
      isDigit(peek())) {
    size_t save = i_;
    long long ext = readInteger();
    skipSpaces();
    if (peek() == '=' && peek(1) != '=') {
      ++i_;
      if (ext > 99) syntax("address extension too large");
      addWord(address, static_cast<int>(ext), expression(), col, true);
      return;
    }
    i_ = save;
  }
  // Address with a numeric suffix and '=': I1=, J1=, K1= (CIP intermediate point) and similar.
  if (isDigit(peek())) {
    size_t save = i_;
    while (isDigit(peek())) ++i_;
    size_t end = i_;
    skipSpaces();
    if (peek() == '=' && peek(1) != '=') {
      ++i_;
      addWord(std::string_view(s_).substr(save - 1, end - save + 1), -1, expression(), col, true);
      return;
    }
    i_ = save;
  }
  plainWord(address, col);
}

// The common plain word (X10, G1, F1000, X-5.5) keeps its value in the statement: no node.
void Parser::plainWord(std::string_view address, int col) {
  bool negative = false;
  if (peek() == '-' || peek() == '+') negative = s_[i_++] == '-';
  bool is_int = false;
  const double v = scanNumber(is_int);
  Stmt& st = b_.stmts.emplace_back();
  st.kind = StmtKind::Word;
  st.name = address;
  st.column = col;
  st.literal = true;
  st.literal_int = is_int;
  st.literal_value = negative ? -v : v;
  // A letter may follow directly (G1X10Y20); anything else must be a separator.
  if (isDigit(peek())) syntax("unexpected digit");
}

}  // namespace ncoffset::lang
