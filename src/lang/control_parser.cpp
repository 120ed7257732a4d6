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
  if (kw == "REPEATB" || (kw == "REPEAT" && (skipSpaces(), i_ < s_.size()))) {
    repeatStatement(st);
    return;
  }
  if (kw == "DEFINE") {
    macroDefinition(st);
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

// REPEAT <start> [<end>] [P=<n>] and REPEATB <label> [P=<n>] (PM-JP "Program section
// repetition"): target is the start label, expr2 the end label, expr the pass count.
void Parser::repeatStatement(Stmt& st) {
  auto label = [&] {
    skipSpaces();
    std::string_view name = ident();
    if (name.size() < 2 || !isLabelStart(name[0], name[1]))
      syntax("jump label expected (a label name starts with two letters or underscores)");
    Node n;
    n.kind = NodeKind::Name;
    n.text = name;
    return addNode(n);
  };
  auto passCount = [&] {
    skipSpaces();
    if (peek() != 'P' || (peek(1) != '=' && !isDigit(peek(1)))) return false;
    ++i_;
    if (peek() == '=') ++i_;
    st.expr = expression();
    return true;
  };
  skipSpaces();
  if (!isAlpha(peek())) syntax("jump label expected after " + std::string(st.name));
  st.target = label();
  if (!passCount() && st.name == "REPEAT") {
    skipSpaces();
    if (isAlpha(peek())) {
      st.expr2 = label();
      passCount();
    }
  }
  skipSpaces();
  if (i_ < s_.size()) syntax("nothing may follow the pass count of " + std::string(st.name));
  b_.stmts.push_back(st);
}

// DEFINE <name> AS <text> (PM-JP "Macro technique"): target names the macro, expr holds its
// text as a String node (the rest of the block, upper-cased, without its comment).
void Parser::macroDefinition(Stmt& st) {
  skipSpaces();
  if (!isAlpha(peek()) && peek() != '_') syntax("macro name expected after DEFINE");
  Node name;
  name.kind = NodeKind::Name;
  name.text = ident();
  st.target = addNode(name);
  skipSpaces();
  if (!wordAhead("AS")) syntax("AS expected after the macro name");
  i_ += 2;
  skipSpaces();
  size_t end = s_.size();
  while (end > i_ && (s_[end - 1] == ' ' || s_[end - 1] == '\t')) --end;
  if (end == i_) syntax("macro text expected after AS");
  Node text;
  text.kind = NodeKind::String;
  text.text = s_.substr(i_, end - i_);
  st.expr = addNode(text);
  i_ = s_.size();
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
  size_t at = i_;
  std::string_view w = ident();
  bool global = false;
  if (w == "NCK" || w == "CHAN") {  // global user data (GUD): one channel, so both alike
    global = true;
  } else {
    i_ = at;
  }
  DefAttributes attr;
  while (attribute(attr)) {
  }
  skipSpaces();
  w = ident();
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
  // Attributes may follow the type too (PM-JP "Attributes": DEF CHAN REAL PHU 1 LLI 0 ...).
  while (attribute(attr)) {
  }
  const size_t first_decl = b_.decls.size();
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
  for (size_t k = first_decl; k < b_.decls.size(); ++k) {
    b_.decls[k].global = global;
    b_.decls[k].attributes = attr;
  }
  Stmt st;
  st.kind = StmtKind::Keyword;
  st.name = "DEF";
  st.column = col;
  b_.stmts.push_back(st);
}

// The attributes of a definition (PM-JP "Definition of user variables" / "Attributes"):
// SYNR/SYNW/SYNRW (preprocessing stop), INIPO/INIRE/INICF/PRLOC (when it is initialised), PHU
// <unit>, LLI/ULI <limit>, APR/APW/APRP/APWP/APRB/APWB <level> (access rights). False (and
// nothing read) when the next word is none of them.
bool Parser::attribute(DefAttributes& a) {
  skipSpaces();
  const size_t at = i_;
  std::string_view w = ident();
  if (w == "SYNR" || w == "SYNW" || w == "SYNRW" || w == "INIPO" || w == "INIRE" || w == "INICF" ||
      w == "PRLOC")
    return true;  // no effect on the path: ncoffset has no main run to synchronise with
  const bool limit = w == "LLI" || w == "ULI";
  if (!(limit || w == "PHU" || w == "APR" || w == "APW" || w == "APRP" || w == "APWP" ||
        w == "APRB" || w == "APWB")) {
    i_ = at;
    return false;
  }
  skipSpaces();
  bool negative = false;
  if (peek() == '-' || peek() == '+') negative = s_[i_++] == '-';
  if (!isDigit(peek()) && peek() != '.')
    syntax(std::string("value expected after ") + std::string(w));
  bool is_int = false;
  double v = scanNumber(is_int);
  if (negative) v = -v;
  if (w == "LLI") {
    a.has_lower = true;
    a.lower = v;
  } else if (w == "ULI") {
    a.has_upper = true;
    a.upper = v;
  }
  return true;
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
  if (d.name.size() == 1) checkOneLetterName(d.name[0], d.dims[0] > 0);
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

// A DEF may not define a predefined name (alarm 12170: `DEF REAL CR` would make `CR=5` an
// assignment), and a name must have the form of one (PM-NC "Names": the first two characters
// letters or underscores, at most 31 characters; syntax alarm 12080). One-letter names are
// decided by checkOneLetterName once the dimensions are read.
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

// One-letter names (docs/language.md "Variable names", decision): the PM's two-letter rule is a
// recommendation ("should", PM-NC 12/2019 "Names"); the collision it prevents is with an address
// that has a meaning in the block. So a letter that moves an axis, names a tool, feed, spindle,
// function, block, subprogram, pass count or R parameter is alarm 12170, and so are I, J, K as
// scalars (`K=5` is a circle centre); `K[2]` (an array, always written with `[`) and the letters
// without a meaning in this channel (A B C E O Q U V W) are accepted.
void Parser::checkOneLetterName(char letter, bool array) {
  constexpr std::string_view kAddresses = "DFGHLMNPRSTXYZ";
  bool interpolation = letter == 'I' || letter == 'J' || letter == 'K';
  if (kAddresses.find(letter) == std::string_view::npos && (array || !interpolation)) return;
  raise(AlarmNumber::AlreadyDefined,
        std::string("name ") + letter +
            " defined several times: it is an address letter of the block and cannot be a " +
            (interpolation ? std::string("scalar variable (an array ") + letter + "[n] is allowed)"
                           : std::string("variable")));
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
