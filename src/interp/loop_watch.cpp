// Which expressions cannot make two passes of a loop differ (loop_watch.hpp).
#include "interp/loop_watch.hpp"

#include <array>
#include <string_view>

namespace ncoffset::interp {

namespace {

// Functions whose value depends only on their arguments (PM-JP "Arithmetic functions").
bool arithmetic(std::string_view name) {
  static constexpr std::array<std::string_view, 18> kPure = {
      "ABS",    "ACOS", "ASIN",  "ATAN2",   "BOUND", "COS",  "EXP",    "LN",  "MAXVAL",
      "MINVAL", "POT",  "ROUND", "ROUNDUP", "SIN",   "SQRT", "STRLEN", "TAN", "TRUNC"};
  for (std::string_view p : kPure)
    if (p == name) return true;
  return false;
}

bool systemName(std::string_view name) {
  return !name.empty() && name.front() == '$';
}

}  // namespace

bool LoopWatch::pure(const lang::Block& b, int node) {
  using lang::NodeKind;
  // A chain of operators of one priority (1+1+...+1) is a left-deep tree as deep as it is long:
  // walk its left operands in a loop, as the evaluator does; the right ones are bounded by
  // --max-expression-depth (docs/limits.md "Expression depth and the stack").
  while (b.node(node).kind == NodeKind::Binary) {
    if (!pure(b, b.node(node).b)) return false;
    node = b.node(node).a;
  }
  const lang::Node& n = b.node(node);
  switch (n.kind) {
    case NodeKind::Number:
    case NodeKind::Bool:
    case NodeKind::String:
    case NodeKind::RParam:
    case NodeKind::BlockNo:
      return true;
    case NodeKind::Name:
      return !systemName(n.text);
    case NodeKind::Unary:
      return pure(b, n.a);
    case NodeKind::Binary:
      return false;  // walked above
    case NodeKind::Call:
      if (!arithmetic(n.text)) return false;
      [[fallthrough]];
    case NodeKind::Index:
    case NodeKind::RIndex:
      if (n.kind == NodeKind::Index && systemName(n.text)) return false;
      for (int k = 0; k < n.b; ++k)
        if (!pure(b, b.arg(n, k))) return false;
      return true;
  }
  return false;
}

}  // namespace ncoffset::interp
