// Expressions of the NC language (PM-NC "Arithmetic operators and functions", priority table
// p444; PM-JP "Flexible NC programming", "Comparison and logical operations"): operands
// (numbers, 'H..'/'B..' constants, strings, names, R parameters, indexed variables, calls),
// unary operators and binary operators by priority, as nodes of the block.
#include <charconv>
#include <string>
#include <vector>

#include "lang/block_parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {

// Unsigned decimal literal with optional EX exponent (PM-NC: 1.5EX3 = 1500).
int Parser::number(bool negative) {
  bool is_int;
  double v = scanNumber(is_int);
  Node n;
  n.kind = NodeKind::Number;
  n.number = negative ? -v : v;
  n.is_int = is_int;
  return addNode(n);
}

// 'H1F' hexadecimal and 'B101' binary constants.
int Parser::quotedConstant() {
  ++i_;  // '
  char base = peek();
  if (base != 'H' && base != 'B') syntax("'H..' or 'B..' constant expected");
  ++i_;
  size_t start = i_;
  while (i_ < s_.size() && s_[i_] != '\'') ++i_;
  if (i_ >= s_.size()) syntax("unterminated constant");
  unsigned long long v = 0;
  auto res = std::from_chars(s_.data() + start, s_.data() + i_, v, base == 'H' ? 16 : 2);
  if (res.ec != std::errc() || res.ptr != s_.data() + i_) syntax("invalid constant");
  ++i_;
  Node n;
  n.kind = NodeKind::Number;
  n.number = static_cast<double>(v);
  n.is_int = true;
  return addNode(n);
}

int Parser::stringLiteral() {
  ++i_;  // "
  size_t start = i_;
  while (i_ < s_.size() && s_[i_] != '"') ++i_;
  if (i_ >= s_.size()) syntax("unterminated string");
  Node n;
  n.kind = NodeKind::String;
  n.text = std::string_view(s_).substr(start, i_ - start);
  ++i_;
  return addNode(n);
}

// Argument list after '(' or '['; returns first index into args and count.
std::pair<int, int> Parser::argList(char close) {
  std::vector<int> tmp;
  skipSpaces();
  if (peek() == close) {
    ++i_;
    return {static_cast<int>(b_.args.size()), 0};
  }
  while (true) {
    skipSpaces();
    if (peek() == ',' || peek() == close) {
      // Empty argument (optional parameter left out).
      Node n;
      n.kind = NodeKind::Name;
      tmp.push_back(addNode(n));
    } else {
      tmp.push_back(expression());
    }
    skipSpaces();
    if (peek() == ',') {
      ++i_;
      continue;
    }
    if (peek() == close) {
      ++i_;
      break;
    }
    syntax(close == ')' ? "expected ',' or ')'" : "expected ',' or ']'");
  }
  int first = static_cast<int>(b_.args.size());
  b_.args.insert(b_.args.end(), tmp.begin(), tmp.end());
  return {first, static_cast<int>(tmp.size())};
}

int Parser::primary() {
  skipSpaces();
  char c = peek();
  if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(false);
  if (c == '"') return stringLiteral();
  if (c == '\'') return quotedConstant();
  if (c == '(') {
    ++i_;
    int e = expression();
    expect(')', "')'");
    return e;
  }
  if (isAlpha(c)) {
    std::string_view name = ident();
    if (name == "TRUE" || name == "FALSE") {
      Node n;
      n.kind = NodeKind::Bool;
      n.number = name == "TRUE" ? 1 : 0;
      return addNode(n);
    }
    if (isRParamName(name)) {
      Node n;
      n.kind = NodeKind::RParam;
      n.number = parseDigits(name.substr(1));
      return addNode(n);
    }
    skipSpaces();
    if (peek() == '(' || peek() == '[') {
      char open = peek();
      ++i_;
      auto [first, count] = argList(open == '(' ? ')' : ']');
      Node n;
      n.kind = open == '(' ? NodeKind::Call : NodeKind::Index;
      if (open == '[' && name == "R") n.kind = NodeKind::RIndex;
      n.text = name;
      n.a = first;
      n.b = count;
      return addNode(n);
    }
    Node n;
    n.kind = NodeKind::Name;
    n.text = name;
    return addNode(n);
  }
  syntax("operand expected");
}

int Parser::unary() {
  skipSpaces();
  char c = peek();
  Op op = Op::None;
  if (c == '-') {
    op = Op::Neg;
    ++i_;
  } else if (c == '+') {
    op = Op::Plus;
    ++i_;
  } else if (wordAhead("NOT")) {
    op = Op::Not;
    i_ += 3;
  } else if (wordAhead("B_NOT")) {
    op = Op::BNot;
    i_ += 5;
  }
  if (op == Op::None) return primary();
  enter();
  int operand = unary();
  leave();
  Node n;
  n.kind = NodeKind::Unary;
  n.op = op;
  n.a = operand;
  return addNode(n);
}

namespace {

// An operator written with symbols (`*`, `==`, `<<`, `:`): its length, 0 if `c d` is none.
size_t symbolOperator(char c, char d, Op& op, int& prio) {
  auto is = [&](Op o, int p, size_t len) {
    op = o;
    prio = p;
    return len;
  };
  switch (c) {
    case '*':
      return is(Op::Mul, 10, 1);
    case '/':
      return is(Op::Div, 10, 1);
    case '+':
      return is(Op::Add, 9, 1);
    case '-':
      return is(Op::Sub, 9, 1);
    case '=':
      return d == '=' ? is(Op::Eq, 1, 2) : 0;
    case '<':
      if (d == '>') return is(Op::Ne, 1, 2);
      if (d == '=') return is(Op::Le, 1, 2);
      if (d == '<') return is(Op::Concat, 2, 2);
      return is(Op::Lt, 1, 1);
    case '>':
      if (d == '=') return is(Op::Ge, 1, 2);
      if (d == '<') return is(Op::Ne, 1, 2);
      return is(Op::Gt, 1, 1);
    case ':':
      return is(Op::Chain, 0, 1);
    default:
      return 0;
  }
}

}  // namespace

// Binary operator at the current position and its priority (PM-NC 12/2019 p444: higher binds
// tighter; comparisons bind weakest, then the frame chain ':').
bool Parser::binaryOp(Op& op, int& prio, size_t& len) const {
  const char c = peek();
  len = symbolOperator(c, peek(1), op, prio);
  if (len > 0) return true;
  struct W {
    std::string_view w;
    Op op;
    int prio;
  };
  static constexpr W kWords[] = {
      {"DIV", Op::IntDiv, 10}, {"MOD", Op::Mod, 10}, {"B_AND", Op::BAnd, 8}, {"B_XOR", Op::BXor, 7},
      {"B_OR", Op::BOr, 6},    {"AND", Op::And, 5},  {"XOR", Op::Xor, 4},    {"OR", Op::Or, 3}};
  switch (c) {  // the first letters of the operator words: no comparison for other names
    case 'A':
    case 'B':
    case 'D':
    case 'M':
    case 'O':
    case 'X':
      break;
    default:
      return false;
  }
  for (const W& w : kWords) {
    if (wordAhead(w.w)) {
      op = w.op;
      prio = w.prio;
      len = w.w.size();
      return true;
    }
  }
  return false;
}

void Parser::depthAlarm() const {
  raise(AlarmNumber::ExpressionDepth, "expression nested deeper than the limit of " +
                                          std::to_string(limits_.max_expression_depth) +
                                          " (--max-expression-depth)");
}

int Parser::binary(int min_prio) {
  enter();
  int left = unary();
  while (true) {
    skipSpaces();
    Op op;
    int prio;
    size_t len;
    if (!binaryOp(op, prio, len) || prio < min_prio) break;
    i_ += len;
    int right = binary(prio + 1);
    Node n;
    n.kind = NodeKind::Binary;
    n.op = op;
    n.a = left;
    n.b = right;
    left = addNode(n);
  }
  leave();
  return left;
}

}  // namespace ncoffset::lang
