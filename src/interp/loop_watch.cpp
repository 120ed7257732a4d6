// Which expressions cannot make two passes of a loop differ (loop_watch.hpp).
#include "interp/loop_watch.hpp"

#include <array>
#include <cstdint>
#include <string_view>

namespace ncoffset::interp {

using lang::NodeKind;

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

constexpr std::uint64_t kRBit = std::uint64_t{1} << 63;  // an R parameter: the low bits its number
constexpr std::uint64_t kAnyR = kRBit | (std::uint64_t{1} << 62);  // R[expr]: any R parameter

// FNV-1a of the upper-case name, with the two top bits clear (R keys use them).
std::uint64_t nameKey(std::string_view name) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : name) {
    const char u = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    h = (h ^ static_cast<unsigned char>(u)) * 1099511628211ull;
  }
  return h >> 2;
}

}  // namespace

bool LoopWatch::KeySet::add(Key k) {
  for (size_t i = 0; i < size; ++i)
    if (keys[i] == k) return true;
  if (size == kCapacity) return false;
  keys[size++] = k;
  return true;
}

bool LoopWatch::sameVariable(Key a, Key b) {
  if (a == b) return true;
  return (a == kAnyR && (b & kRBit) != 0) || (b == kAnyR && (a & kRBit) != 0);
}

bool LoopWatch::isRead(Key k) const {
  for (size_t i = 0; i < reads_.size; ++i)
    if (sameVariable(reads_.keys[i], k)) return true;
  return false;
}

bool LoopWatch::assignedIsRead() const {
  for (size_t i = 0; i < assigned_.size; ++i)
    if (isRead(assigned_.keys[i])) return true;
  return false;
}

void LoopWatch::decides(const lang::Block& b, int node) {
  if (node < 0 || !clean_) return;
  if (!pure(b, node)) {
    clean_ = false;
    return;
  }
  reads(b, node);
}

// The variables a pure expression reads (pure() has excluded system variables and calls of
// anything but the arithmetic functions).
void LoopWatch::reads(const lang::Block& b, int node) {
  while (clean_ && b.node(node).kind == NodeKind::Binary) {  // chains in a loop, as pure()
    reads(b, b.node(node).b);
    node = b.node(node).a;
  }
  const lang::Node& n = b.node(node);
  Key key = 0;
  switch (n.kind) {
    case NodeKind::RParam:
      key = kRBit | static_cast<Key>(n.number);
      break;
    case NodeKind::RIndex:
      key = kAnyR;
      break;
    case NodeKind::Name:
    case NodeKind::Index:
      key = nameKey(n.text);
      break;
    case NodeKind::Unary:
      reads(b, n.a);
      return;
    default:
      break;
  }
  if (key != 0 && !reads_.add(key)) clean_ = false;
  if (n.kind == NodeKind::Index || n.kind == NodeKind::RIndex || n.kind == NodeKind::Call)
    for (int k = 0; k < n.b; ++k) reads(b, b.arg(n, k));
}

void LoopWatch::assignment(const lang::Block& b, const lang::Stmt& st) {
  if (!clean_) return;
  const lang::Node& t = b.node(st.target);
  Key key = 0;
  if (t.kind == NodeKind::RParam)
    key = kRBit | static_cast<Key>(t.number);
  else if (t.kind == NodeKind::RIndex)
    key = kAnyR;
  else if ((t.kind == NodeKind::Name || t.kind == NodeKind::Index) && !systemName(t.text))
    key = nameKey(t.text);
  // A system variable or setting datum (SD42940=1) may change what the control does; an index
  // or right-hand side that is not pure may too.
  if (key == 0 || !pure(b, st.expr) || isRead(key) || !assigned_.add(key)) {
    clean_ = false;
    return;
  }
  if (t.kind == NodeKind::Index || t.kind == NodeKind::RIndex)
    for (int k = 0; k < t.b; ++k) expression(b, b.arg(t, k));
}

bool LoopWatch::pure(const lang::Block& b, int node) {
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
