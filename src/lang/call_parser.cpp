// Subprogram statements (PM-JP "Subprogram technique"): the PROC header with its formal
// parameters and attributes, the EXTERN declaration, the modal call MCALL, the indirect call
// CALL (with BLOCK .. TO ..) and the call with a path PCALL. What they do is decided by the
// interpreter (interp/subprogram_call.cpp); here they become statements:
//   PROC   target: program name; decls: the formal parameters; ext: their count; expr2: the
//          attribute bits (ProcAttribute)
//   EXTERN target: program name; decls: the parameter types (names empty); ext: their count
//   MCALL  target: the program (Name, or Call with the arguments), -1 for MCALL alone
//   PCALL  target: the program as for MCALL (the path is dropped: the name is the last part)
//   CALL   expr: the program name (an expression, -1 for CALL BLOCK); target and expr2: the
//          first and last label of BLOCK .. TO .. (-1 without)
//   EXTCALL expr: the program name or path (an expression, e.g. ("PART") or "/DIR/PART.SPF")
#include <string>

#include "lang/block_parser.hpp"

namespace ncoffset::lang {

void Parser::callStatement(Stmt& st) {
  const std::string_view kw = st.name;
  if (kw == "PROC") {
    procHeader(st);
    return;
  }
  skipSpaces();
  if (kw == "EXTERN") {
    programWithParameters(st, false);
  } else if (kw == "MCALL") {
    if (i_ < s_.size() && isAlpha(peek())) st.target = programName(false);
  } else if (kw == "PCALL") {
    st.target = programName(true);
  } else if (kw == "EXTCALL") {
    st.expr = expression();
  } else {  // CALL
    if (!wordAhead("BLOCK")) st.expr = expression();
    skipSpaces();
    if (wordAhead("BLOCK")) callBlockRange(st);
  }
  skipSpaces();
  if (i_ < s_.size()) syntax(std::string("unexpected text after ") + std::string(kw));
  b_.stmts.push_back(st);
}

// `<name>[(<parameters>)]` after PROC (`formal`: named parameters) or EXTERN (types only): the
// name in st.target, the parameters as declarations of the block, their count in st.ext.
void Parser::programWithParameters(Stmt& st, bool formal) {
  skipSpaces();
  if (!isAlpha(peek())) syntax("program name expected after " + std::string(st.name));
  Node n;
  n.kind = NodeKind::Name;
  n.text = ident();
  st.target = addNode(n);
  skipSpaces();
  const size_t before = b_.decls.size();
  if (peek() == '(') parameterList(formal);
  st.ext = static_cast<int>(b_.decls.size() - before);
}

// PROC <name>[(<parameters>)] [SAVE] [SBLOF] [DISPLOF] [ACTBLOCNO] [ICYCOF] [PREPRO]
void Parser::procHeader(Stmt& st) {
  programWithParameters(st, true);
  int attributes = 0;
  while (true) {
    skipSpaces();
    if (i_ >= s_.size()) break;
    if (!isAlpha(peek())) syntax("PROC attribute expected (SAVE, SBLOF, DISPLOF, ...)");
    std::string_view a = ident();
    if (a == "SAVE")
      attributes |= kProcSave;
    else if (a == "SBLOF")
      attributes |= kProcSblof;
    else if (a == "DISPLOF")
      attributes |= kProcDisplof;
    else if (a == "ACTBLOCNO")
      attributes |= kProcActblocno;
    else if (a == "ICYCOF")
      attributes |= kProcIcycof;
    else if (a == "PREPRO")
      attributes |= kProcPrepro;
    else
      syntax(std::string("unknown PROC attribute ") + std::string(a));
  }
  st.expr2 = attributes;
  b_.stmts.push_back(st);
}

// `(<parameter>, ...)` at the '(': formal parameters (PROC, named) or their types (EXTERN).
void Parser::parameterList(bool named) {
  ++i_;
  skipSpaces();
  if (peek() == ')') {
    ++i_;
    return;
  }
  while (true) {
    formalParameter(named);
    skipSpaces();
    if (peek() == ',') {
      ++i_;
      continue;
    }
    expect(')', "',' or ')' in the parameter list");
    return;
  }
}

// [VAR] <type>[[<length>]] <name>[[<dims>]]: an open first dimension `[,3]` or `[]` is -1.
void Parser::formalParameter(bool named) {
  skipSpaces();
  Decl d;
  d.column = column();
  if (wordAhead("VAR")) {
    i_ += 3;
    d.by_ref = true;
    skipSpaces();
  }
  if (!isAlpha(peek()) || !typeOf(ident(), d.type))
    syntax("parameter type expected (INT, REAL, BOOL, STRING, CHAR, AXIS, FRAME)");
  skipSpaces();
  if (d.type == VarType::String) {
    expect('[', "'[' with the length of a STRING parameter");
    skipSpaces();
    if (!isDigit(peek())) syntax("string length expected");
    long long len = readInteger();
    if (len < 1 || len > 200) syntax("string length must be 1..200");
    d.string_length = static_cast<int>(len);
    expect(']', "']'");
    skipSpaces();
  }
  if (isAlpha(peek())) {
    d.name = ident();
    checkVariableName(d.name, static_cast<size_t>(d.column - 1));
    skipSpaces();
  } else if (named) {
    syntax("parameter name expected");
  }
  if (peek() == '[') {
    ++i_;
    for (int k = 0; k < 2; ++k) {
      skipSpaces();
      if (k == 0 && (peek() == ',' || peek() == ']')) {
        d.dims[0] = -1;  // open: the caller's array decides
      } else {
        if (!isDigit(peek())) syntax("array size must be a number");
        long long v = readInteger();
        if (v < 1 || v > 1000000000) syntax("array size out of range");
        d.dims[k] = static_cast<int>(v);
      }
      skipSpaces();
      if (peek() != ',') break;
      ++i_;
      if (k == 1) syntax("arrays have at most two dimensions");
    }
    expect(']', "']'");
    if (!d.by_ref) syntax("arrays are passed by reference only: VAR expected");
  }
  b_.decls.push_back(d);
}

// The program of MCALL/PCALL: NAME, L123 or NAME(arguments); with `path`, a leading
// /_N_WKS_DIR/_N_PART_WPD/ path whose last part is the program name (_N_ and _SPF dropped).
int Parser::programName(bool path) {
  skipSpaces();
  if (path && peek() == '/') {
    size_t last = i_;
    while (i_ < s_.size() && (isIdentChar(peek()) || peek() == '/'))
      if (s_[i_++] == '/') last = i_;
    i_ = last;
  }
  if (!isAlpha(peek())) syntax("program name expected");
  std::string_view name = ident();
  if (path) {
    if (name.size() > 3 && name.substr(0, 3) == "_N_") name.remove_prefix(3);
    if (name.size() > 4 &&
        (name.substr(name.size() - 4) == "_SPF" || name.substr(name.size() - 4) == "_MPF"))
      name.remove_suffix(4);
  }
  Node n;
  n.kind = NodeKind::Name;
  n.text = name;
  skipSpaces();
  if (peek() == '(') {
    ++i_;
    auto [first, count] = argList(')');
    n.kind = NodeKind::Call;
    n.a = first;
    n.b = count;
  }
  return addNode(n);
}

// BLOCK <start label> [TO <end label>] of CALL.
void Parser::callBlockRange(Stmt& st) {
  i_ += 5;  // BLOCK
  st.target = jumpTarget();
  skipSpaces();
  if (wordAhead("TO")) {
    i_ += 2;
    st.expr2 = jumpTarget();
  }
}

}  // namespace ncoffset::lang
