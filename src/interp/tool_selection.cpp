// Tool selection (W1 1, spec §1.1): T, D, M6 with MD22550/MD22560/MD20270; the offset memory
// $TC_DP.. / $TC_DPV.. / $TC_DPC.. / $TC_TP..; the readable $P_TOOL.. variables; LENTOAX.
#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

namespace {

[[noreturn]] void edgeMissing(int t, int d) {
  raise(alarm_no::kEdgeNotExisting, fmt::format("T no. = {}, D no. = {} not existing", t, d));
}

int wholeIndex(const Value& v, int lo, int hi, int alarm, const char* what) {
  double x = lang::toNumber(v, what);
  if (x != std::floor(x) || x < lo || x > hi)
    raise(alarm, fmt::format("illegal array index: {} {} outside {}..{}", what, x, lo, hi));
  return static_cast<int>(x);
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
                       ToolVariable& out) {
  if (!splitToolName(name, out.kind, out.n)) return false;
  const std::string_view k = out.kind;
  const int n = out.n;
  if (k == "TP" || k == "TPC") {
    if (n < 1 || n > 20) return false;
    if (!indexed || idx.size() != 1)
      raise(alarm_no::kArrayIndex1, fmt::format("{} needs [T]", name));
    out.t = wholeIndex(idx[0], 1, tool::kMaxTool, alarm_no::kArrayIndex1, "T");
    return true;
  }
  bool edge = (k == "DP" && n >= 1 && n <= 25) || (k == "DPV" && (n == 0 || (n >= 3 && n <= 5))) ||
              (k == "DPVN" && n >= 3 && n <= 5) || (k == "DPC" && n >= 1 && n <= 10);
  if (!edge) return false;
  if (!indexed || idx.size() != 2)
    raise(alarm_no::kArrayIndex1, fmt::format("{} needs [T,D]", name));
  out.t = wholeIndex(idx[0], 1, tool::kMaxTool, alarm_no::kArrayIndex1, "T");
  out.d = wholeIndex(idx[1], 1, tool::kMaxEdge, alarm_no::kArrayIndex2, "D");
  return true;
}

}  // namespace

int Interpreter::resolveToolName(const std::string& name) {
  int t = tools_.findByName(name);
  if (!t)
    raise(alarm_no::kToolNotExisting,
          fmt::format("T= \"{}\" not existing (no tool with $TC_TP2=\"{}\")", name, name));
  return t;
}

void Interpreter::executeToolWords() {
  const bool change_on_t = data_.get(md_change_mode_) == 0;
  if (words_.tool) {
    int t = *words_.tool;
    if (t != 0 && !tools_.tool(t))
      raise(alarm_no::kToolNotExisting, fmt::format("T= {} not existing", t));
    if (change_on_t)
      changeTool(t, words_.edge.has_value());
    else
      preselected_tool_ = t;  // MD22550 = 1: T preselects, M6 changes
  }
  if (words_.tool_change && !change_on_t && preselected_tool_ >= 0) {
    changeTool(preselected_tool_, words_.edge.has_value());
    preselected_tool_ = -1;
  }
  if (words_.edge) selectEdge(*words_.edge);
}

void Interpreter::changeTool(int t, bool edge_programmed) {
  active_tool_ = t;
  if (t == 0) {
    selectEdge(0);
    return;
  }
  if (edge_programmed) return;  // the D of the block selects the edge
  // MD20270: 0 no edge, > 0 that edge, -1 keep the old D number.
  int def = static_cast<int>(data_.get(md_default_edge_));
  selectEdge(def < 0 ? active_edge_ : def);
}

void Interpreter::selectEdge(int d) {
  if (d == 0) {
    active_edge_ = 0;
    edge_ = EdgeSnapshot{};
    return;
  }
  const EdgeData* e = tools_.edge(active_tool_, d);
  if (!e) edgeMissing(active_tool_, d);
  active_edge_ = d;
  edge_.valid = true;
  edge_.data = *e;
  edge_.settings.mirror_length = data_.get(sd_mirror_length_) != 0;
  edge_.settings.mirror_wear = data_.get(sd_mirror_wear_) != 0;
  edge_.settings.wear_sign_cutpos = data_.get(sd_cutpos_) != 0;
  edge_.settings.wear_sign = data_.get(sd_wear_sign_) != 0;
  edge_.settings.length_const = static_cast<long>(data_.get(sd_length_const_));
  edge_.settings.length_type = static_cast<long>(data_.get(sd_length_type_));
  edge_.mirrored = ncoffset::chain(iframe_, pframe_).mirror;
  edge_.radius = effectiveLengths(edge_.data, edge_.settings).radius;
  edge_.offset_cached = false;
}

Vec3 Interpreter::toolOffset() const {
  if (!edge_.valid) return {};
  if (!edge_.offset_cached || edge_.cached_plane != modal_.plane) {
    edge_.cached_offset = lengthVector(edge_.data, edge_.settings, modal_.plane, edge_.mirrored);
    edge_.cached_plane = modal_.plane;
    edge_.offset_cached = true;
  }
  return edge_.cached_offset;
}

bool Interpreter::readTool(std::string_view name, std::span<const Value> idx, bool indexed,
                           Value& out) {
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
    out = Value::real(edge_.valid ? effectiveLengths(edge_.data, edge_.settings).radius : 0.0);
    return true;
  }
  if (name == "$P_TOOLL" || name == "$P_TOOLO") {
    if (!indexed || idx.size() != 1)
      raise(alarm_no::kArrayIndex1, fmt::format("{} needs [1..3]", name));
    int k = wholeIndex(idx[0], 1, 3, alarm_no::kArrayIndex1, "index");
    if (name == "$P_TOOLL") {
      out = Value::real(
          edge_.valid
              ? effectiveLengths(edge_.data, edge_.settings).total[static_cast<size_t>(k - 1)]
              : 0.0);
    } else {
      Vec3 o = edge_.valid
                   ? toolOrientation(edge_.data, edge_.settings, modal_.plane, edge_.mirrored)
                   : Vec3{};
      if (!edge_.valid) o[planeAxes(modal_.plane).applicate] = 1;
      out = Value::real(o[k - 1]);
    }
    return true;
  }
  ToolVariable var;
  if (!parseToolVariable(name, idx, indexed, var)) return false;
  const std::string_view kind = var.kind;
  const int n = var.n, t = var.t, d = var.d;
  if (kind == "TP" || kind == "TPC") {
    tool::Tool* tool = tools_.tool(t);
    if (!tool) raise(alarm_no::kToolNotExisting, fmt::format("T= {} not existing", t));
    if (kind == "TP" && n == 2) {
      auto it = tool->name.find(2);
      out = Value::string(it == tool->name.end() ? std::string() : it->second);
      return true;
    }
    auto& m = kind == "TP" ? tool->tp : tool->tpc;
    auto it = m.find(n);
    out = Value::real(it == m.end() ? 0.0 : it->second);
    return true;
  }
  const EdgeData* e = tools_.edge(t, d);
  if (!e) edgeMissing(t, d);
  if (kind == "DP")
    out = Value::real(e->dp[static_cast<size_t>(n)]);
  else if (kind == "DPV" && n == 0)
    out = Value::integer(e->dpv);
  else if (kind == "DPV")
    out = Value::real(n == 3 ? e->dpv3 : n == 4 ? e->dpv4 : e->dpv5);
  else {
    const tool::Tool* tool = tools_.tool(t);
    const auto& m = kind == "DPC" ? tool->edge_user : tool->edge_normal;
    auto it = m.find({d, n});
    out = Value::real(it == m.end() ? 0.0 : it->second);
  }
  return true;
}

bool Interpreter::writeTool(std::string_view name, std::span<const Value> idx, bool indexed,
                            const Value& v) {
  if (name == "$P_TOOLNO" || name == "$P_TOOL" || name == "$P_TOOLP" || name == "$P_TOOLR" ||
      name == "$P_TOOLL" || name == "$P_TOOLO")
    raise(alarm_no::kNameNotDefined, fmt::format("{} can only be read", name));
  ToolVariable var;
  if (!parseToolVariable(name, idx, indexed, var)) return false;
  const std::string_view kind = var.kind;
  const int n = var.n, t = var.t, d = var.d;
  if (kind == "TP" && n == 2) {
    // The tool name is a STRING like any other: at most 200 characters (docs/limits.md), with
    // the value range alarm of an over-long string value (variables.cpp).
    std::string text = lang::toText(v);
    if (text.size() > 200)
      raise(alarm_no::kValueRange,
            fmt::format("value range exceeded: string of {} characters does not fit STRING[200] "
                        "{}[{}]",
                        text.size(), name, t));
    tools_.toolForWrite(t).name[2] = std::move(text);
    return true;
  }
  if (kind == "TP" || kind == "TPC") {
    tool::Tool& tool = tools_.toolForWrite(t);
    (kind == "TP" ? tool.tp : tool.tpc)[n] = lang::toNumber(v, "tool parameter");
    return true;
  }
  double x = lang::toNumber(v, "tool parameter");
  if (!(std::fabs(x) <= 1e9) || (kind == "DP" && n == 1 && !(x >= 0 && x <= 9999)) ||
      (kind == "DP" && n == 2 && !(x >= 0 && x <= 9)))
    raise(alarm_no::kValueRange,
          fmt::format("value range exceeded: {}[{},{}] = {}", name, t, d, x));
  if (!tools_.edge(t, d)) {
    if (tool_edges_ >= options_.limits.max_tool_edges)
      raise(alarm_no::kTooManyVariables,
            fmt::format("more than {} cutting edges in the tool offset memory",
                        options_.limits.max_tool_edges));
    ++tool_edges_;
  }
  EdgeData& e = tools_.edgeForWrite(t, d);
  if (kind == "DP") {
    if ((n == 1 || n == 2) && x != std::floor(x))
      raise(alarm_no::kValueRange,
            fmt::format("value range exceeded: {} = {} must be whole", name, x));
    e.dp[static_cast<size_t>(n)] = x;
  } else if (kind == "DPV" && n == 0) {
    e.dpv = static_cast<int>(lang::roundToInt(x));
  } else if (kind == "DPV") {
    (n == 3 ? e.dpv3 : n == 4 ? e.dpv4 : e.dpv5) = x;
  } else {
    tool::Tool& tool = tools_.toolForWrite(t);
    (kind == "DPC" ? tool.edge_user : tool.edge_normal)[{d, n}] = x;
  }
  return true;
}

Value Interpreter::callLentoax(std::span<const Value> args) {
  if (args.size() < 2 || args.size() > 3)
    raise(alarm_no::kWrongCallParams,
          "wrong number of parameters in call of LENTOAX(_AXIND, _MATRIX[, _COORD])");
  auto array = [&](const Value& v, lang::VarType type, int rows, int cols, const char* what) {
    if (v.type != Type::ArrayRef)
      raise(alarm_no::kWrongCallParams, fmt::format("LENTOAX: {} must be an array variable", what));
    UserVariable* var = findVariable(v.str);
    if (!var || var->type != type || var->dims[0] != rows || var->dims[1] != cols)
      raise(alarm_no::kWrongCallParams,
            fmt::format("LENTOAX: {} must be DEF {} {}[{}]", what,
                        type == lang::VarType::Int ? "INT" : "REAL", v.str,
                        cols ? fmt::format("{},{}", rows, cols) : fmt::format("{}", rows)));
    return var;
  };
  UserVariable* axind = array(args[0], lang::VarType::Int, 3, 0, "_AXIND");
  UserVariable* matrix = array(args[1], lang::VarType::Real, 3, 3, "_MATRIX");
  std::string coord = "WCS";
  if (args.size() == 3 && args[2].type != Type::Empty) {
    if (args[2].type != Type::String)
      raise(alarm_no::kWrongCallParams, "LENTOAX: _COORD must be a STRING");
    coord = args[2].str;
  }
  LentoaxResult r;
  std::string upper;
  for (char c : coord)
    upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  bool known = upper == "WCS" || upper == "W" || upper == "MCS" || upper == "M" || upper == "BCS" ||
               upper == "B" || upper == "KCS" || upper == "K" || upper == "TCS" || upper == "T";
  if (!known) return Value::integer(-1);
  if (!edge_.valid) return Value::integer(-2);
  r = lentoax(edge_.data, edge_.settings, modal_.plane, edge_.mirrored, act_.linear, coord);
  for (size_t i = 0; i < 3; ++i) {
    axind->data[i] = Value::integer(r.axind[i]);
    for (size_t k = 0; k < 3; ++k) matrix->data[i * 3 + k] = Value::real(r.matrix[i][k]);
  }
  return Value::integer(r.status);
}

}  // namespace ncoffset::interp
