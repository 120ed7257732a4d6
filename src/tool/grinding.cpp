// Grinding tools, types 400..499 (FM W4 "Grinding-specific tool offset and tool monitoring";
// Operator's Guide "Tool data: grinding"): the tool-specific grinding data $TC_TPG1..9.
// Only the chaining rule $TC_TPG2 changes an offset; the monitoring data only set PLC signals
// or limit the spindle speed (W4 17.4: "No error reaction is initiated internally in the
// control system"): stored and readable, path-neutral (docs/tool-offsets.md section 15).
#include <fmt/format.h>

#include <cmath>

#include "ncoffset/alarm.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

namespace {

[[noreturn]] void outOfRange(int t, int n, double x, const char* allowed) {
  raise(AlarmNumber::ValueRange,
        fmt::format("value range exceeded: $TC_TPG{}[{}] = {} ({})", n, t, x, allowed));
}

}  // namespace

void ToolSelection::writeGrindingData(int t, int n, double x) {
  const bool whole = x == std::floor(x);
  // $TC_TPG1 spindle number, $TC_TPG2 chaining bits (bit n-1: $TC_DPn, n = 1..25),
  // $TC_TPG9 the parameter GWPS and monitoring use: 3, 4, 5 length 1..3, 6 radius (0 unset).
  if (n == 1 && !(whole && x >= 0 && x <= 99)) outOfRange(t, n, x, "a spindle number");
  if (n == 2 && !(whole && x >= 0 && x < (1 << 25)))
    outOfRange(t, n, x, "bits 0..24 for $TC_DP1..25");
  if (n == 9 && !(x == 0 || x == 3 || x == 4 || x == 5 || x == 6))
    outOfRange(t, n, x, "3, 4, 5: length 1..3; 6: radius");
  if (!(std::fabs(x) <= 1e9)) outOfRange(t, n, x, "|value| <= 1e9");
  tools_.toolForWrite(t).tpg[n] = x;
}

void ToolSelection::chainGrindingEdges(int t, int d, int n) {
  if (d != 1 && d != 2) return;  // the chain joins the left (D1) and right (D2) wheel edge
  Tool* tool = tools_.tool(t);
  auto rule = tool->tpg.find(2);
  if (rule == tool->tpg.end()) return;
  const EdgeData* left = tools_.edge(t, 1);
  if (!left || left->type() < 400 || left->type() > 499) return;  // grinding tools only
  const long bits = static_cast<long>(rule->second);
  if (!(bits & (1L << (n - 1)))) return;
  const int other = d == 1 ? 2 : 1;
  if (!tools_.edge(t, other)) return;  // chains existing edges; creates none [D]
  tools_.edgeForWrite(t, other).dp[static_cast<size_t>(n)] =
      tools_.edge(t, d)->dp[static_cast<size_t>(n)];
}

}  // namespace ncoffset::tool
