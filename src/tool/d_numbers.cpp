// D-number management of the TO unit (W1 2.1.5 "Free assignment of D numbers", 2.2 "Flat D
// number structure"; PM Job planning "Free assignment of D numbers, cutting edge numbers"):
// MD18105/MD18106 limits, the cutting edge number CE ($TC_DPCE), CHKDNO, GETDNO, SETDNO, DZERO,
// GETACTTD, GETACTT and $P_AD. docs/tool-offsets.md section 13 explains the decisions.
#include <fmt/format.h>

#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

using lang::Value;

namespace {

bool validD(int d) {
  return d > 0 && d <= kInvalidD;
}

// The first D number that tools a and b (a != b) both use, 0 if none; only `only` when given.
int sharedD(const Tool& a, const Tool& b, int only) {
  for (const auto& [d, e] : a.edges)
    if (validD(d) && (only == 0 || d == only) && b.edges.count(d)) return d;
  return 0;
}

}  // namespace

void ToolSelection::createEdge(int t, int d) {
  if (edges_ >= max_edges_)
    raise(AlarmNumber::TooManyVariables,
          fmt::format("more than {} cutting edges in the tool offset memory", max_edges_));
  Tool& tool = tools_.toolForWrite(t);
  if (!dconf_.flat && tool.edges.size() >= static_cast<size_t>(dconf_.max_per_tool))
    raise(AlarmNumber::ArrayIndex2,
          fmt::format("T{} already has MD18106 $MN_MM_MAX_CUTTING_EDGE_PERTOOL = {} cutting "
                      "edges: D{} cannot be created",
                      t, dconf_.max_per_tool, d));
  ++edges_;
  // W1 2.1.5: the edges of a tool are numbered from CE 1 upwards as they are created.
  auto used = [&tool](int ce) {
    for (const auto& [dd, c] : tool.ce)
      if (c == ce) return true;
    return false;
  };
  int ce = 1;
  while (used(ce)) ++ce;
  tool.ce[d] = ce;
}

int ToolSelection::cuttingEdgeNumber(int t, int d) const {
  if (!dconf_.freeNumbers()) return d;  // W1: with MD18105 <= MD18106 a read returns CE = D
  if (const Tool* tool = tools_.tool(t)) {
    auto it = tool->ce.find(d);
    if (it == tool->ce.end()) it = tool->ce.find(d + kInvalidD);  // the active one after DZERO
    if (it != tool->ce.end()) return it->second;
  }
  return d;
}

void ToolSelection::setCuttingEdgeNumber(int t, int d, double x) {
  if (!dconf_.freeNumbers()) return;  // W1: the write is ignored without an alarm
  if (x != std::floor(x) || x < 1 || x > dconf_.max_per_tool)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: $TC_DPCE[{},{}] = {} (1..MD18106 = {})", t, d, x,
                      dconf_.max_per_tool));
  Tool& tool = tools_.toolForWrite(t);
  const int ce = static_cast<int>(x);
  for (const auto& [dd, c] : tool.ce)
    if (dd != d && c == ce)
      raise(AlarmNumber::ValueRange,
            fmt::format("$TC_DPCE[{},{}] = {}: D{} of T{} already has cutting edge number {}", t, d,
                        ce, dd, t, ce));
  tool.ce[d] = ce;
}

bool ToolSelection::checkDNumbers(int t1, int t2, int d, DCollision& c) const {
  if (!dconf_.freeNumbers() || dconf_.flat) return true;  // W1: no effect then
  const auto& all = tools_.all();
  if (t1 != 0 && !tools_.tool(t1)) {
    c = {t1, t2, d};
    return false;  // invalid parameters: FALSE (PM)
  }
  if (t2 != 0 && !tools_.tool(t2)) {
    c = {t1, t2, d};
    return false;
  }
  for (auto a = all.begin(); a != all.end(); ++a) {
    if (t1 != 0 && a->first != t1) continue;
    for (const auto& [tb, b] : all) {
      if (tb == a->first || (t2 != 0 && tb != t2) || (t1 == 0 && tb < a->first)) continue;
      if (int shared = sharedD(a->second, b, d)) {
        c = {a->first, tb, shared};
        return false;
      }
    }
  }
  return true;
}

int ToolSelection::getDNumber(int t, int ce) const {
  const Tool* tool = tools_.tool(t);
  if (!tool) return 0;
  for (const auto& [d, e] : tool->edges)
    if (cuttingEdgeNumber(t, d) == ce) return d;
  return 0;
}

bool ToolSelection::setDNumber(int t, int ce, int d) {
  if (d < 1 || d > dconf_.max_d)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: SETDNO D number {} (1..MD18105 = {}; a D number "
                      "cannot be set to 0)",
                      d, dconf_.max_d));
  if (!dconf_.freeNumbers() || dconf_.flat) return false;
  const int old = getDNumber(t, ce);
  if (old == 0) return false;  // no data block for T and CE
  if (old == d) return true;
  if (tools_.edge(t, d)) return false;  // two edges of one tool never share a D number
  tools_.renameEdge(t, old, d);
  if (t == active_tool_ && old == active_edge_) active_edge_ = d;  // the active offset stays
  return true;
}

void ToolSelection::invalidateDNumbers() {
  if (!dconf_.freeNumbers() || dconf_.flat) return;
  for (const auto& [t, tool] : tools_.all()) {
    std::vector<int> ds;
    for (const auto& [d, e] : tool.edges)
      if (validD(d)) ds.push_back(d);
    for (int d : ds) tools_.renameEdge(t, d, d + kInvalidD);
  }
}

int ToolSelection::toolOfDNumber(int d, int& t) const {
  t = 0;
  if (d < 1 || d > kInvalidD) return -5;
  if (dconf_.flat) {  // PM: with flat D numbers always T = 1 (no T numbers in the memory)
    if (!tools_.edge(0, d)) return -1;
    t = 1;
    return 0;
  }
  int found = 0;
  for (const auto& [tt, tool] : tools_.all())
    if (tool.edges.count(d) && found++ == 0) t = tt;
  return found == 0 ? -1 : found == 1 ? 0 : -2;
}

int ToolSelection::toolOfName(const std::string& name, int& t) const {
  t = tools_.findByName(name);
  return t ? 0 : -1;
}

bool ToolSelection::readActiveOffset(std::string_view name, std::span<const Value> idx,
                                     bool indexed, Value& out) const {
  if (name == "CHKDNO" && !indexed) {  // CHKDNO without parentheses: all tools (PM)
    DCollision c;
    out = Value::boolean(checkDNumbers(0, 0, 0, c));
    return true;
  }
  if (name != "$P_AD") return false;
  if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_AD needs [1..26]");
  const double n = lang::toNumber(idx[0], "index");
  if (n != std::floor(n) || n < 1 || n > 26)
    raise(AlarmNumber::ArrayIndex1, fmt::format("illegal array index: $P_AD[{}] (1..26)", n));
  const int k = static_cast<int>(n);
  if (!edge_.valid)
    out = Value::real(0);
  else if (k == 26)
    out = Value::integer(cuttingEdgeNumber(edgeOwner(), active_edge_));
  else
    out = Value::real(edge_.data.dp[static_cast<size_t>(k)]);
  return true;
}

}  // namespace ncoffset::tool
