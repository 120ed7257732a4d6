// The tool variables of the channel: $P_TOOL.. (W1 1, readable only), the offset memory $TC_..
// (written by TO_INI files and programs), and LENTOAX (W1 2.11).
#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/tool_index.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

using lang::Type;
using lang::Value;

namespace {

[[noreturn]] void edgeMissing(int t, int d) {
  raise(AlarmNumber::EdgeNotExisting, fmt::format("T no. = {}, D no. = {} not existing", t, d));
}

// "$TC_DP12" -> kind "DP", number 12; "$TC_DPV3" -> "DPV", 3; "$TC_DPV" -> "DPV", 0.
bool splitToolName(std::string_view name, std::string_view& kind, int& number) {
  if (name.substr(0, 4) != "$TC_") return false;
  std::string_view rest = name.substr(4);
  size_t digits = rest.find_first_of("0123456789");
  kind = rest.substr(0, digits);
  number = 0;
  if (digits != std::string_view::npos) {
    std::string_view num = rest.substr(digits);
    auto res = std::from_chars(num.data(), num.data() + num.size(), number);
    if (res.ec != std::errc() || res.ptr != num.data() + num.size()) return false;
  }
  return true;
}

// A `$TC_...` variable with its indices checked: tool data `$TC_TPn[t]`/`$TC_TPCn[t]` (n 1..20)
// or edge data `$TC_DPn[t,d]` (1..25), `$TC_DPV[t,d]`, `$TC_DPV3..5`, `$TC_DPVN3..5`,
// `$TC_DPC1..10`. Returns false for names that are no tool variable (alarm 12550 later).
struct ToolVariable {
  std::string_view kind;  // TP, TPC, DP, DPV, DPVN, DPC
  int n = 0;
  int t = 0;
  int d = 0;  // 0 for tool data
};

bool parseToolVariable(std::string_view name, std::span<const Value> idx, bool indexed,
                       const DNumberConfig& dconf, ToolVariable& out) {
  if (!splitToolName(name, out.kind, out.n)) return false;
  const std::string_view k = out.kind;
  const int n = out.n;
  if (k == "TP" || k == "TPC" || k == "TPG") {
    if (n < 1 || n > (k == "TPG" ? 9 : 20)) return false;
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [T]", name));
    out.t = wholeIndex(idx[0], 1, kMaxTool, AlarmNumber::ArrayIndex1, "T");
    return true;
  }
  bool edge = (k == "DP" && n >= 1 && n <= 25) || (k == "DPV" && (n == 0 || (n >= 3 && n <= 5))) ||
              (k == "DPVN" && n >= 3 && n <= 5) || (k == "DPC" && n >= 1 && n <= 10) ||
              (k == "DPCE" && n == 0);
  if (!edge) return false;
  // Flat D numbers (MD18102 = 1): $TC_DPx[d] without T (W1 "Flat D number structure": each
  // syntax loads only with its structure active).
  if (dconf.flat) {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [D] with flat D numbers", name));
    out.d = wholeIndex(idx[0], 1, dconf.max_d, AlarmNumber::ArrayIndex1, "D");
    return true;
  }
  if (!indexed || idx.size() != 2)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [T,D]", name));
  out.t = wholeIndex(idx[0], 1, kMaxTool, AlarmNumber::ArrayIndex1, "T");
  out.d = wholeIndex(idx[1], 1, dconf.max_d, AlarmNumber::ArrayIndex2, "D");
  return true;
}

}  // namespace

int wholeIndex(const Value& v, int lo, int hi, AlarmNumber alarm, const char* what) {
  double x = lang::toNumber(v, what);
  if (x != std::floor(x) || x < lo || x > hi)
    raise(alarm, fmt::format("illegal array index: {} {} outside {}..{}", what, x, lo, hi));
  return static_cast<int>(x);
}

void edgeIndex(std::string_view name, std::span<const Value> idx, bool indexed, int& t, int& d) {
  if (!indexed || idx.size() != 2)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [T,D]", name));
  t = wholeIndex(idx[0], 1, kMaxTool, AlarmNumber::ArrayIndex1, "T");
  d = wholeIndex(idx[1], 1, kMaxEdge, AlarmNumber::ArrayIndex2, "D");
}

bool ToolSelection::read(std::string_view name, std::span<const Value> idx, bool indexed,
                         Plane plane, Value& out) const {
  if (name == "$P_TOOLNO") {
    out = Value::integer(active_tool_);
    return true;
  }
  if (name == "$P_TOOL") {
    out = Value::integer(active_edge_);
    return true;
  }
  if (name == "$P_TOOLP") {
    out = Value::integer(preselected_tool_ >= 0 ? preselected_tool_ : active_tool_);
    return true;
  }
  if (name == "$P_TOOLR") {
    out = Value::real(lengths().radius);
    return true;
  }
  if (name == "$P_TOOLL" || name == "$P_TOOLO") {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [1..3]", name));
    int k = wholeIndex(idx[0], 1, 3, AlarmNumber::ArrayIndex1, "index");
    if (name == "$P_TOOLL") {
      out = Value::real(lengths(plane).total[static_cast<size_t>(k - 1)]);
    } else {
      out = Value::real(orientation(plane)[k - 1]);
    }
    return true;
  }
  if (readActiveOffset(name, idx, indexed, out) || readEnvironment(name, idx, indexed, out))
    return true;
  if (readSumOffset(name, idx, indexed, out)) return true;  // $TC_SCP.., $TC_ECP..
  ToolVariable var;
  if (!parseToolVariable(name, idx, indexed, dconf_, var)) return false;
  const std::string_view kind = var.kind;
  const int n = var.n, t = var.t, d = var.d;
  if (kind == "TP" || kind == "TPC" || kind == "TPG") {
    const Tool* tool = tools_.tool(t);
    if (!tool) raise(AlarmNumber::ToolNotExisting, fmt::format("T= {} not existing", t));
    if (kind == "TP" && n == 2) {
      auto it = tool->name.find(2);
      out = Value::string(it == tool->name.end() ? std::string() : it->second);
      return true;
    }
    auto& m = kind == "TP" ? tool->tp : kind == "TPC" ? tool->tpc : tool->tpg;
    auto it = m.find(n);
    out = Value::real(it == m.end() ? 0.0 : it->second);
    return true;
  }
  const EdgeData* e = tools_.edge(t, d);
  if (!e) edgeMissing(t, d);
  if (kind == "DPCE")
    out = Value::integer(cuttingEdgeNumber(t, d));
  else if (kind == "DP")
    out = Value::real(e->dp[static_cast<size_t>(n)]);
  else if (kind == "DPV" && n == 0)
    out = Value::integer(e->dpv);
  else if (kind == "DPV")
    out = Value::real(n == 3 ? e->dpv3 : n == 4 ? e->dpv4 : e->dpv5);
  else {
    const Tool* tool = tools_.tool(t);
    const auto& m = kind == "DPC" ? tool->edge_user : tool->edge_normal;
    auto it = m.find({d, n});
    out = Value::real(it == m.end() ? 0.0 : it->second);
  }
  return true;
}

bool ToolSelection::write(std::string_view name, std::span<const Value> idx, bool indexed,
                          const Value& v) {
  if (name == "$P_TOOLNO" || name == "$P_TOOL" || name == "$P_TOOLP" || name == "$P_TOOLR" ||
      name == "$P_TOOLL" || name == "$P_TOOLO")
    raise(AlarmNumber::NameNotDefined, fmt::format("{} can only be read", name));
  if (writeSumOffset(name, idx, indexed, v)) return true;  // $TC_SCP.., $TC_ECP..
  ToolVariable var;
  if (!parseToolVariable(name, idx, indexed, dconf_, var)) return false;
  const std::string_view kind = var.kind;
  const int n = var.n, t = var.t, d = var.d;
  if (kind == "TP" && n == 2) {
    // The tool name is a STRING like any other: at most 200 characters (docs/limits.md), with
    // the value range alarm of an over-long string value (variables.cpp).
    std::string text = lang::toText(v);
    if (text.size() > 200)
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: string of {} characters does not fit STRING[200] "
                        "{}[{}]",
                        text.size(), name, t));
    tools_.toolForWrite(t).name[2] = std::move(text);
    return true;
  }
  if (kind == "TPG") {
    writeGrindingData(t, n, lang::toNumber(v, "grinding data"));
    return true;
  }
  if (kind == "TP" || kind == "TPC") {
    Tool& tool = tools_.toolForWrite(t);
    (kind == "TP" ? tool.tp : tool.tpc)[n] = lang::toNumber(v, "tool parameter");
    return true;
  }
  double x = lang::toNumber(v, "tool parameter");
  if (!(std::fabs(x) <= 1e9) || (kind == "DP" && n == 1 && !(x >= 0 && x <= 9999)) ||
      (kind == "DP" && n == 2 && !(x >= 0 && x <= 9)))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {}[{},{}] = {}", name, t, d, x));
  if (!tools_.edge(t, d)) createEdge(t, d);
  EdgeData& e = tools_.edgeForWrite(t, d);
  if (kind == "DPCE") {
    setCuttingEdgeNumber(t, d, x);
  } else if (kind == "DP") {
    if ((n == 1 || n == 2) && x != std::floor(x))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: {} = {} must be whole", name, x));
    e.dp[static_cast<size_t>(n)] = x;
    chainGrindingEdges(t, d, n);  // $TC_TPG2 (W4)
  } else if (kind == "DPV" && n == 0) {
    e.dpv = static_cast<int>(lang::roundToInt(x));
  } else if (kind == "DPV") {
    (n == 3 ? e.dpv3 : n == 4 ? e.dpv4 : e.dpv5) = x;
  } else {
    Tool& tool = tools_.toolForWrite(t);
    (kind == "DPC" ? tool.edge_user : tool.edge_normal)[{d, n}] = x;
  }
  return true;
}

Value ToolSelection::callLentoax(std::span<const Value> args, const ArrayLookup& array, Plane plane,
                                 const Mat3& frame_linear) const {
  if (args.size() < 2 || args.size() > 3)
    raise(AlarmNumber::WrongCallParams,
          "wrong number of parameters in call of LENTOAX(_AXIND, _MATRIX[, _COORD])");
  std::span<Value> axind = array(args[0], true, 3, 0, "_AXIND");
  std::span<Value> matrix = array(args[1], false, 3, 3, "_MATRIX");
  std::string coord = "WCS";
  if (args.size() == 3 && args[2].type != Type::Empty) {
    if (args[2].type != Type::String)
      raise(AlarmNumber::WrongCallParams, "LENTOAX: _COORD must be a STRING");
    coord = args[2].str;
  }
  std::string upper;
  for (char c : coord)
    upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  bool known = upper == "WCS" || upper == "W" || upper == "MCS" || upper == "M" || upper == "BCS" ||
               upper == "B" || upper == "KCS" || upper == "K" || upper == "TCS" || upper == "T";
  if (!known) return Value::integer(-1);
  if (!edge_.valid) return Value::integer(-2);
  LentoaxResult r = lentoax(edge_.data, edge_.settings, plane, edge_.mirrored, frame_linear, coord,
                            carrier_rotation_);
  for (size_t i = 0; i < 3; ++i) {
    axind[i] = Value::integer(r.axind[i]);
    for (size_t k = 0; k < 3; ++k) matrix[i * 3 + k] = Value::real(r.matrix[i][k]);
  }
  return Value::integer(r.status);
}

}  // namespace ncoffset::tool
