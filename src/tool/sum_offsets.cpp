// Sum offsets and setup offsets (FM-W1 01/2015 18.11; docs/tool-offsets.md section 10).
#include "tool/sum_offsets.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/tool_index.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

using lang::Value;

bool parseSumOffsetName(std::string_view name, SumOffsetName& out) {
  if (name.size() < 9 || name.substr(0, 4) != "$TC_") return false;
  const std::string_view kind = name.substr(4, 3);
  if (kind != "SCP" && kind != "ECP") return false;
  const std::string_view digits = name.substr(7);
  int n = 0;
  auto res = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (res.ec != std::errc() || res.ptr != digits.data() + digits.size() || digits[0] == '0')
    return false;
  // n = 10 * DL + parameter, parameter 3..11: DL1 is 13..21, DL2 23..31, ..., DL6 63..71.
  const int dl = (n - 3) / 10;
  const int param = n - 10 * dl;
  if (n < 13 || dl > kMaxSumOffsets || param < 3 || param > 11) return false;
  out = {kind == "ECP", dl, param};
  return true;
}

void addSumOffsets(EdgeData& e, const SumOffsetMemory& m, int t, int d, int dl,
                   const SumOffsetLimits& limits, bool sum, bool setup) {
  // Parameter y of a set adds to the wear parameter DP(y + 9): L1 DP12, L2 DP13, L3 DP14,
  // radius DP15, ... (FM-W1 11/2006 2.8: "wear" is DP12..DP20 plus the sum and setup offsets).
  for (bool is_setup : {false, true}) {
    if (is_setup ? !setup || !limits.setup_offsets : !sum) continue;
    if (const SumOffsetMemory::Set* s = m.find(is_setup, t, d, dl))
      for (size_t y = 0; y < s->size(); ++y) e.dp[12 + y] += (*s)[y];
  }
}

void ToolSelection::selectSumOffset(int dl, const SelectionContext& ctx) {
  if (!edge_.valid) return;  // D0 / T0: "no effect" (W1 18.11.4 example 1)
  if (dl > 0) {
    if (dl > sum_limits_.max_per_edge)
      raise(AlarmNumber::SumOffsetIllegal,
            fmt::format("illegal sum offset DL={}: MD18110 allows {} per cutting edge", dl,
                        sum_limits_.max_per_edge));
    if (!sums_.exists(active_tool_, active_edge_, dl))
      raise(AlarmNumber::SumOffsetIllegal,
            fmt::format("sum offset DL={} of T{} D{} not defined ($TC_SCP{}..[{},{}])", dl,
                        active_tool_, active_edge_, dl * 10 + 3, active_tool_, active_edge_));
  }
  active_dl_ = dl;
  // Like a D selection: the edge's data and the setting data as they are now (W1 2.5).
  snapshot(*tools_.edge(active_tool_, active_edge_), ctx);
}

bool ToolSelection::readSumOffset(std::string_view name, std::span<const Value> idx, bool indexed,
                                  Value& out) const {
  SumOffsetName s;
  if (!parseSumOffsetName(name, s)) return false;
  int t = 0, d = 0;
  edgeIndex(name, idx, indexed, t, d);
  if (s.setup && !sum_limits_.setup_offsets)
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined or option/function not available (setup offsets "
                      "need MD18112 bit 4)",
                      name));
  if (!tools_.edge(t, d))
    raise(AlarmNumber::EdgeNotExisting, fmt::format("T no. = {}, D no. = {} not existing", t, d));
  const SumOffsetMemory::Set* set = sums_.find(s.setup, t, d, s.dl);
  out = Value::real(set ? (*set)[static_cast<size_t>(s.param - 3)] : 0.0);
  return true;
}

bool ToolSelection::writeSumOffset(std::string_view name, std::span<const Value> idx, bool indexed,
                                   const Value& v) {
  SumOffsetName s;
  if (!parseSumOffsetName(name, s)) return false;
  int t = 0, d = 0;
  edgeIndex(name, idx, indexed, t, d);
  const double x = lang::toNumber(v, "sum offset");
  if (!(std::fabs(x) <= 1e9))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {}[{},{}] = {}", name, t, d, x));
  // Without setup offsets (MD18112 bit 4 = 0) a tool data backup's empty $TC_ECP.. = 0 loads;
  // a value would be lost, so it is refused.
  if (s.setup && !sum_limits_.setup_offsets) {
    if (x == 0.0) return true;
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined or option/function not available (setup offsets "
                      "need MD18112 bit 4)",
                      name));
  }
  if (s.dl > sum_limits_.max_per_edge)
    raise(AlarmNumber::SumOffsetIllegal,
          fmt::format("illegal sum offset number {} in {}: MD18110 allows {} per cutting edge",
                      s.dl, name, sum_limits_.max_per_edge));
  if (!tools_.edge(t, d))
    raise(AlarmNumber::EdgeNotExisting, fmt::format("T no. = {}, D no. = {} not existing", t, d));
  sums_.forWrite(s.setup, t, d, s.dl)[static_cast<size_t>(s.param - 3)] = x;
  return true;
}

}  // namespace ncoffset::tool
