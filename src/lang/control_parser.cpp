// Control statements (PM-JP "Flexible NC programming", "Program jumps and branches", "Control
// structures", "Definition of user variables"): DEF, IF/WHILE/UNTIL with their condition, FOR,
// CASE with its arms, PROC with its parameters, the jumps GOTOF/GOTOB/GOTO/GOTOC and the
// keywords without arguments (ELSE, ENDIF, ENDWHILE, ENDFOR, REPEAT, LOOP, ENDLOOP).
#include <string>

#include "lang/block_parser.hpp"
#include "lang/reserved_names.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {

bool Parser::typeOf(std::string_view w, VarType& t) {
  if (w == "INT")
    t = VarType::Int;
  else if (w == "REAL")
    t = VarType::Real;
  else if (w == "BOOL")
    t = VarType::Bool;
  else if (w == "STRING")
    t = VarType::String;
  else if (w == "CHAR")
    t = VarType::Char;
  else if (w == "AXIS")
    t = VarType::Axis;
  else if (w == "FRAME")
    t = VarType::Frame;
  else
    return false;
  return true;
}

int Parser::jumpTarget() {
  skipSpaces();
  if ((peek() == 'N' && isDigit(peek(1))) || (peek() == ':' && isDigit(peek(1)))) {
    ++i_;
    Node n;
    n.kind = NodeKind::BlockNo;
    n.number = static_cast<double>(readInteger());
    return addNode(n);
  }
  if (isDigit(peek())) {
    Node n;
    n.kind = NodeKind::BlockNo;
    n.number = static_cast<double>(readInteger());
    return addNode(n);
  }
  if (!isAlpha(peek()) && peek() != '"') syntax("jump destination expected");
  return expression();
}

void Parser::controlStatement(std::string_view kw, int col) {
  Stmt st;
  st.kind = StmtKind::Keyword;
  st.name = kw;
  st.column = col;
  if (kw == "DEF") {
    definition(col);
    return;
  }
  if (kw == "IF" || kw == "WHILE" || kw == "UNTIL") {
    st.expr = expression();
    b_.stmts.push_back(st);
    return;
  }
  if (JumpKind j = jumpKind(kw); j != JumpKind::None) {
    st.jump = j;
    st.target = jumpTarget();
    b_.stmts.push_back(st);
    skipSpaces();
    if (i_ < s_.size()) syntax("nothing may follow the jump destination in its block");
    return;
  }
  if (kw == "FOR") {
    forStatement(st);
    return;
  }
  if (kw == "CASE") {
    expect('(', "'(' after CASE");
    st.expr = expression();
    expect(')', "')'");
    skipSpaces();
    if (!wordAhead("OF")) syntax("OF expected in CASE");
    i_ += 2;
    b_.stmts.push_back(st);
    caseArms();
    return;
  }
  if (kw == "PROC" || kw == "EXTERN" || kw == "MCALL" || kw == "CALL" || kw == "PCALL" ||
      kw == "EXTCALL") {
    callStatement(st);
    return;
  }
  b_.stmts.push_back(st);  // ELSE, ENDIF, ENDWHILE, ENDFOR, REPEAT, LOOP, ENDLOOP
}

// FOR <variable> = <start> TO <end>
void Parser::forStatement(Stmt& st) {
  skipSpaces();
  if (!isAlpha(peek())) syntax("loop variable expected after FOR");
  std::string_view var = ident();
  Node t;
  if (isRParamName(var)) {
    t.kind = NodeKind::RParam;
    t.number = parseDigits(var.substr(1));
  } else {
    t.kind = NodeKind::Name;
    t.text = var;
  }
  st.target = addNode(t);
  expect('=', "'=' after the FOR variable");
  st.expr = expression();
  skipSpaces();
  if (!wordAhead("TO")) syntax("TO expected in FOR");
  i_ += 2;
  st.expr2 = expression();
  b_.stmts.push_back(st);
}

void Parser::caseArms() {
  while (true) {
    skipSpaces();
    if (i_ >= s_.size()) return;
    Stmt arm;
    arm.kind = StmtKind::CaseArm;
    arm.column = column();
    if (wordAhead("DEFAULT")) {
      i_ += 7;
      arm.expr = -1;
    } else {
      arm.expr = unary();
    }
    skipSpaces();
    if (!isAlpha(peek())) syntax("GOTOF/GOTOB expected in CASE");
    std::string_view kw = ident();
    arm.jump = jumpKind(kw);
    if (arm.jump == JumpKind::None) syntax("GOTOF/GOTOB expected in CASE");
    arm.name = kw;
    arm.target = jumpTarget();
    b_.stmts.push_back(arm);
  }
}

// DEF [NCK|CHAN] <type> <name>[[dims]][=init], ...
void Parser::definition(int col) {
  skipSpaces();
  std::string_view w = ident();
  if (w == "NCK" || w == "CHAN") {  // global user data: same handling in one channel
    skipSpaces();
    w = ident();
  }
  VarType type;
  if (!typeOf(w, type))
    syntax("data type expected after DEF (INT, REAL, BOOL, STRING, CHAR, AXIS, FRAME)");
  int string_length = 0;
  skipSpaces();
  if (type == VarType::String) {
    if (peek() != '[') syntax("STRING needs a length: STRING[n]");
    ++i_;
    skipSpaces();
    if (!isDigit(peek())) syntax("string length expected");
    long long len = readInteger();
    if (len < 1 || len > 200) syntax("string length must be 1..200");
    string_length = static_cast<int>(len);
    expect(']', "']'");
  }
  while (true) {
    declarator(type, string_length);
    skipSpaces();
    if (peek() == ',') {
      ++i_;
      continue;
    }
    break;
  }
  skipSpaces();
  if (i_ < s_.size()) syntax("unexpected text after DEF");
  Stmt st;
  st.kind = StmtKind::Keyword;
  st.name = "DEF";
  st.column = col;
  b_.stmts.push_back(st);
}

// One variable of a DEF: its name, array dimensions and initial value.
void Parser::declarator(VarType type, int string_length) {
  skipSpaces();
  if (!isAlpha(peek())) syntax("variable name expected in DEF");
  Decl d;
  d.type = type;
  d.string_length = string_length;
  d.column = column();
  d.name = ident();
  checkVariableName(d.name, static_cast<size_t>(d.column - 1));
  skipSpaces();
  if (peek() == '[') {
    ++i_;
    for (int k = 0; k < 3; ++k) {
      skipSpaces();
      if (!isDigit(peek())) syntax("array size must be a number");
      long long n = readInteger();
      if (k == 2) syntax("arrays have at most two dimensions");
      if (n < 1 || n > 1000000000) syntax("array size out of range");
      d.dims[k] = static_cast<int>(n);
      skipSpaces();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      break;
    }
    expect(']', "']'");
  }
  skipSpaces();
  if (peek() == '=' && peek(1) != '=') {
    ++i_;
    skipSpaces();
    if (d.dims[0] > 0)
      arrayInitialiser(d);
    else
      d.init = expression();
  }
  b_.decls.push_back(d);
}

// A DEF may not define a predefined name (alarm 12170: `DEF REAL X` would make `X=5` an
// assignment), and a name must have the form of one (PM-NC "Names": the first two characters
// letters or underscores, at most 31 characters; syntax alarm 12080).
//
// Single letters are address letters too, and the manual's rule excludes them; ncoffset still
// accepts them for now because the shared command-line contract (shared/contract, outside this
// repository) defines `DEF INT K[2]` and `DEF REAL V` (docs/language.md: decision pending).
void Parser::checkVariableName(std::string_view name, size_t at) {
  if (name.size() == 1) return;
  if (isPredefinedName(name))
    raise(AlarmNumber::AlreadyDefined,
          "name " + std::string(name) +
              " defined several times: it is predefined (an address, keyword or predefined "
              "name) and cannot be a variable");
  if (const char* problem = variableNameProblem(name)) {
    i_ = at;  // the alarm names the column of the name
    syntax(problem);
  }
}

// `SET(..)`, `REP(..)` or `(..)` after the '=' of an array.
void Parser::arrayInitialiser(Decl& d) {
  bool rep = wordAhead("REP");
  if (wordAhead("SET") || rep) {
    i_ += 3;
    expect('(', "'('");
  } else if (peek() == '(') {
    ++i_;
  } else {
    syntax("array initialisation needs SET(..), REP(..) or (..)");
  }
  auto [first, count] = argList(')');
  d.init_first = first;
  d.init_count = count;
  d.init_rep = rep;
}

}  // namespace ncoffset::lang
