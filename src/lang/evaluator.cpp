#include "lang/evaluator.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "lang/string_functions.hpp"
#include "ncoffset/alarm.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::lang {
namespace {

constexpr double kDeg = kRadPerDegree;
constexpr double kIntMax = 2147483647.0;

void checkFinite(double v, const char* what) {
  if (!std::isfinite(v))
    raise(AlarmNumber::Arithmetic,
          fmt::format("arithmetic error in part program: {} gives no finite number", what));
}

Value numeric(Type t, double v, const char* what) {
  checkFinite(v, what);
  if (t == Type::Int && std::fabs(v) > kIntMax) t = Type::Real;
  return {t, v, {}, {}};
}

// Bit operations work on 32-bit integers: larger values are out of range (never a cast of an
// unrepresentable double).
int64_t bitOperand(double v) {
  if (!(std::fabs(v) <= 4294967295.0))
    raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {} in a bit operation", v));
  return static_cast<int64_t>(std::round(v));
}

}  // namespace

const char* typeName(Type t) {
  switch (t) {
    case Type::Int:
      return "INT";
    case Type::Real:
      return "REAL";
    case Type::Bool:
      return "BOOL";
    case Type::Char:
      return "CHAR";
    case Type::String:
      return "STRING";
    case Type::Axis:
      return "AXIS";
    case Type::Frame:
      return "FRAME";
    case Type::Symbol:
      return "name";
    case Type::ArrayRef:
      return "array";
    case Type::Empty:
      return "empty";
  }
  return "?";
}

double toNumber(const Value& v, const char* what) {
  if (v.isNumeric()) return v.num;
  if (v.type == Type::Symbol)
    raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", v.str));
  if (v.type == Type::ArrayRef)
    raise(AlarmNumber::TypeMismatch, fmt::format("array {} used without index", v.str));
  raise(AlarmNumber::TypeMismatch,
        fmt::format("operation not compatible with data type: {} is {}, a number is needed", what,
                    typeName(v.type)));
}

bool toBool(const Value& v) {
  return toNumber(v, "condition") != 0;
}

std::string toText(const Value& v) {
  switch (v.type) {
    case Type::String:
    case Type::Axis:
    case Type::Symbol:
      return v.str;
    case Type::Bool:
      return v.num != 0 ? "TRUE" : "FALSE";
    case Type::Int:
      return fmt::format("{}", static_cast<long long>(v.num));
    case Type::Char:
      return std::string(1, static_cast<char>(v.num));
    case Type::Real:
      return fmt::format("{}", v.num);
    default:
      raise(AlarmNumber::TypeMismatch,
            fmt::format("operation not compatible with data type {}", typeName(v.type)));
  }
}

double roundToInt(double v) {
  return std::round(v);
}

bool realEqual(double a, double b) {
  if (a == b) return true;
  double scale = std::max(std::fabs(a), std::fabs(b));
  return std::fabs(a - b) <= 1e-12 * scale;
}

void Evaluator::DepthGuard::tooDeep() {
  raise(AlarmNumber::ExpressionDepth,
        fmt::format("expression nested deeper than the limit of {}", kMaxExpressionDepth));
}

double Evaluator::number(const Block& b, int n) {
  return toNumber(eval(b, n));
}

void Evaluator::evalArgs(const Block& b, const Node& node, std::vector<Value>& out) {
  out.clear();
  for (int k = 0; k < node.b; ++k) {
    const Node& a = b.node(b.arg(node, k));
    if (a.kind == NodeKind::Name && a.text.empty()) {
      out.push_back(Value::empty());
    } else {
      out.push_back(evalOrSymbol(b, b.arg(node, k)));
    }
  }
}

Value Evaluator::evalOrSymbol(const Block& b, int n) {
  const Node& node = b.node(n);
  if (node.kind == NodeKind::Name) {
    Value v;
    if (env_.read(node.text, {}, false, v)) return v;
    return Value::symbol(std::string(node.text));
  }
  return eval(b, n);
}

Value Evaluator::eval(const Block& b, int n) {
  const Node& node = b.node(n);
  switch (node.kind) {
    case NodeKind::Number:
      return node.is_int && std::fabs(node.number) <= kIntMax ? Value::integer(node.number)
                                                              : Value::real(node.number);
    case NodeKind::Bool:
      return Value::boolean(node.number != 0);
    case NodeKind::String:
      return Value::string(std::string(node.text));
    case NodeKind::BlockNo:
      return Value::integer(node.number);
    case NodeKind::RParam:
      return env_.readR(node.number);
    case NodeKind::RIndex: {
      if (node.b != 1) raise(AlarmNumber::SyntaxError, "R[..] takes one index");
      const DepthGuard guard(depth_);
      return env_.readR(roundToInt(number(b, b.arg(node, 0))));
    }
    case NodeKind::Name: {
      Value v;
      if (node.text.empty()) raise(AlarmNumber::SyntaxError, "value missing");
      if (!env_.read(node.text, {}, false, v))
        raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", node.text));
      return v;
    }
    case NodeKind::Index: {
      const DepthGuard guard(depth_);
      std::vector<Value> idx;
      evalArgs(b, node, idx);
      Value v;
      if (!env_.read(node.text, idx, true, v))
        raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", node.text));
      return v;
    }
    case NodeKind::Call: {
      if (node.text == "AC" || node.text == "IC")
        raise(AlarmNumber::SyntaxError,
              fmt::format("{}(..) is only allowed as the whole value of an address", node.text));
      const DepthGuard guard(depth_);
      std::vector<Value> args;
      evalArgs(b, node, args);
      return function(node.text, args);
    }
    case NodeKind::Unary: {
      const DepthGuard guard(depth_);
      Value v = eval(b, node.a);
      switch (node.op) {
        case Op::Neg:
          return numeric(v.type == Type::Int ? Type::Int : Type::Real, -toNumber(v), "negation");
        case Op::Plus:
          return numeric(v.type == Type::Int ? Type::Int : Type::Real, toNumber(v), "+");
        case Op::Not:
          return Value::boolean(!toBool(v));
        case Op::BNot:
          return Value::integer(
              static_cast<double>(~static_cast<int32_t>(bitOperand(toNumber(v)))));
        default:
          break;
      }
      raise(AlarmNumber::SyntaxError, "bad unary operator");
    }
    case NodeKind::Binary: {
      if (b.node(node.a).kind == NodeKind::Binary) return binaryChain(b, n);
      const DepthGuard guard(depth_);  // the usual `a op b`: no chain to walk
      Value l = eval(b, node.a);
      Value r = eval(b, node.b);
      return binary(node.op, l, r);
    }
  }
  raise(AlarmNumber::SyntaxError, "bad expression");
}

// A chain of left-associative operators (1+2+3 is ((1+2)+3)) is as deep as it is long, and a
// block of 65,536 characters holds 30,000 of them: the left operands are walked in a loop, not
// by recursion, in the order recursion would take (leftmost operand first, then each right
// operand and its operator). Right operands, unary operands and arguments recurse; the parser
// bounds their nesting (ParseLimits::max_expression_depth).
Value Evaluator::binaryChain(const Block& b, int n) {
  const DepthGuard guard(depth_);
  constexpr int kShort = 16;  // the usual chain; longer ones continue in `spine_long`
  int spine_short[kShort];
  std::vector<int> spine_long;
  int count = 0;
  int leaf = n;
  for (; b.node(leaf).kind == NodeKind::Binary; leaf = b.node(leaf).a, ++count) {
    if (count < kShort) {
      spine_short[count] = leaf;
    } else {
      if (count == kShort) spine_long.assign(spine_short, spine_short + kShort);
      spine_long.push_back(leaf);
    }
  }
  const int* spine = count <= kShort ? spine_short : spine_long.data();
  Value left = eval(b, leaf);
  for (int k = count - 1; k >= 0; --k) {
    const Node& node = b.node(spine[k]);
    Value right = eval(b, node.b);
    left = binary(node.op, left, right);
  }
  return left;
}

Value Evaluator::binary(Op op, const Value& l, const Value& r) {
  if (op == Op::Chain) return env_.chain(l, r);
  if (op == Op::Concat) return Value::string(toText(l) + toText(r));
  if (op == Op::Eq || op == Op::Ne) {
    bool eq;
    if (l.isText() || r.isText()) {
      if (!(l.isText() && r.isText()))
        raise(AlarmNumber::TypeMismatch,
              "operation not compatible with data type: comparing text with a number");
      eq = l.str == r.str;
    } else {
      eq = realEqual(toNumber(l), toNumber(r));
    }
    return Value::boolean(op == Op::Eq ? eq : !eq);
  }
  double a = toNumber(l), c = toNumber(r);
  bool ints = (l.type == Type::Int || l.type == Type::Bool || l.type == Type::Char) &&
              (r.type == Type::Int || r.type == Type::Bool || r.type == Type::Char);
  Type nt = ints ? Type::Int : Type::Real;
  switch (op) {
    case Op::Add:
      return numeric(nt, a + c, "+");
    case Op::Sub:
      return numeric(nt, a - c, "-");
    case Op::Mul:
      return numeric(nt, a * c, "*");
    case Op::Div:
      if (c == 0)
        raise(AlarmNumber::Arithmetic, "arithmetic error in part program: division by zero");
      return numeric(Type::Real, a / c, "/");
    case Op::IntDiv:
      if (std::trunc(c) == 0)
        raise(AlarmNumber::Arithmetic, "arithmetic error in part program: DIV by zero");
      return numeric(Type::Int, std::trunc(a / c), "DIV");
    case Op::Mod:
      if (c == 0) raise(AlarmNumber::Arithmetic, "arithmetic error in part program: MOD by zero");
      return numeric(nt, a - c * std::trunc(a / c), "MOD");
    case Op::BAnd:
    case Op::BOr:
    case Op::BXor: {
      int64_t x = bitOperand(a), y = bitOperand(c);
      int64_t z = op == Op::BAnd ? (x & y) : op == Op::BOr ? (x | y) : (x ^ y);
      return Value::integer(static_cast<double>(z));
    }
    case Op::And:
      return Value::boolean(a != 0 && c != 0);
    case Op::Or:
      return Value::boolean(a != 0 || c != 0);
    case Op::Xor:
      return Value::boolean((a != 0) != (c != 0));
    case Op::Lt:
      return Value::boolean(a < c && !realEqual(a, c));
    case Op::Gt:
      return Value::boolean(a > c && !realEqual(a, c));
    case Op::Le:
      return Value::boolean(a < c || realEqual(a, c));
    case Op::Ge:
      return Value::boolean(a > c || realEqual(a, c));
    default:
      break;
  }
  raise(AlarmNumber::SyntaxError, "bad operator");
}

namespace {

// The arguments of a predefined function, with the checks every function makes.
struct FunctionArgs {
  std::string_view name;
  std::span<const Value> args;

  void want(size_t n) const {
    if (args.size() != n)
      raise(AlarmNumber::WrongCallParams,
            fmt::format("wrong number of parameters in call of {}: {} expected, {} given", name, n,
                        args.size()));
  }
  double arg(size_t k) const { return toNumber(args[k], "function argument"); }
  void domain(bool ok) const {
    if (!ok)
      raise(AlarmNumber::Arithmetic,
            fmt::format("arithmetic error in part program: argument of {} out of range", name));
  }
  Value real(double v) const { return numeric(Type::Real, v, std::string(name).c_str()); }
};

// SIN, COS, TAN, ASIN, ACOS, ATAN2 (degrees, PM-NC "Arithmetic functions"); false if `f` is
// none of them.
bool trigonometric(const FunctionArgs& f, Value& out) {
  const std::string_view name = f.name;
  if (name == "SIN") {
    f.want(1);
    out = f.real(std::sin(f.arg(0) * kDeg));
  } else if (name == "COS") {
    f.want(1);
    out = f.real(std::cos(f.arg(0) * kDeg));
  } else if (name == "TAN") {
    f.want(1);
    double x = std::fmod(f.arg(0), 180.0);
    f.domain(std::fabs(std::fabs(x) - 90.0) > 1e-12);
    out = f.real(std::tan(f.arg(0) * kDeg));
  } else if (name == "ASIN") {
    f.want(1);
    f.domain(std::fabs(f.arg(0)) <= 1);
    out = f.real(std::asin(f.arg(0)) / kDeg);
  } else if (name == "ACOS") {
    f.want(1);
    f.domain(std::fabs(f.arg(0)) <= 1);
    out = f.real(std::acos(f.arg(0)) / kDeg);
  } else if (name == "ATAN2") {
    f.want(2);
    f.domain(f.arg(0) != 0 || f.arg(1) != 0);
    out = f.real(std::atan2(f.arg(0), f.arg(1)) / kDeg);
  } else {
    return false;
  }
  return true;
}

// SQRT, ABS, POT, TRUNC, ROUND, ROUNDUP, EXP, LN, MINVAL, MAXVAL, STRLEN; false if `f` is none
// of them.
bool arithmetic(const FunctionArgs& f, Value& out) {
  const std::string_view name = f.name;
  if (name == "SQRT") {
    f.want(1);
    f.domain(f.arg(0) >= 0);
    out = f.real(std::sqrt(f.arg(0)));
  } else if (name == "ABS") {
    f.want(1);
    out = numeric(f.args[0].type == Type::Int ? Type::Int : Type::Real, std::fabs(f.arg(0)), "ABS");
  } else if (name == "POT") {
    f.want(1);
    out = f.real(f.arg(0) * f.arg(0));
  } else if (name == "TRUNC") {
    f.want(1);
    out = f.real(std::trunc(f.arg(0)));
  } else if (name == "ROUND") {
    f.want(1);
    out = f.real(std::round(f.arg(0)));
  } else if (name == "ROUNDUP") {
    f.want(1);
    out = f.real(std::ceil(f.arg(0)));
  } else if (name == "EXP") {
    f.want(1);
    out = f.real(std::exp(f.arg(0)));
  } else if (name == "LN") {
    f.want(1);
    f.domain(f.arg(0) > 0);
    out = f.real(std::log(f.arg(0)));
  } else if (name == "MINVAL" || name == "MAXVAL") {
    f.want(2);
    double a = f.arg(0), c = f.arg(1);
    bool ints = f.args[0].type == Type::Int && f.args[1].type == Type::Int;
    double v = name == "MINVAL" ? std::min(a, c) : std::max(a, c);
    out = numeric(ints ? Type::Int : Type::Real, v, "MINVAL/MAXVAL");
  } else if (name == "STRLEN") {
    f.want(1);
    out = Value::integer(static_cast<double>(toText(f.args[0]).size()));
  } else {
    return false;
  }
  return true;
}

}  // namespace

Value Evaluator::function(std::string_view name, std::span<const Value> args) {
  const FunctionArgs f{name, args};
  Value v;
  if (trigonometric(f, v) || arithmetic(f, v) || stringFunction(name, args, v)) return v;
  return env_.call(name, args);
}

}  // namespace ncoffset::lang
