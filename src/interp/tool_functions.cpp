// The predefined functions of the D-number management and the tool environments (W1 2.1.5,
// 2.10; PM Job planning "Free assignment of D numbers", "Tool environments"): their
// parameters, VAR results and status values. The offset memory does the work
// (src/tool/d_numbers.cpp, src/tool/tool_environment.cpp); docs/tool-offsets.md sections 13-14.
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/settcor.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

namespace {

bool omitted(std::span<const Value> args, size_t k) {
  return k >= args.size() || args[k].type == Type::Empty;
}

// A whole-number parameter (T, D, CE); omitted: `fallback`.
int wholeArg(std::span<const Value> args, size_t k, std::string_view fn, int fallback) {
  if (omitted(args, k)) return fallback;
  const double x = lang::toNumber(args[k], "parameter");
  if (x != std::floor(x) || std::fabs(x) > 1e9)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {} parameter {} = {} must be whole", fn, k + 1, x));
  return static_cast<int>(x);
}

std::string textArg(std::span<const Value> args, size_t k, std::string_view fn) {
  if (omitted(args, k)) return {};
  if (!args[k].isText())
    raise(AlarmNumber::WrongCallParams,
          fmt::format("{}: parameter {} must be a STRING", fn, k + 1));
  return args[k].str;
}

void wantArgs(std::span<const Value> args, size_t lo, size_t hi, std::string_view fn) {
  if (args.size() < lo || args.size() > hi)
    raise(AlarmNumber::WrongCallParams,
          fmt::format("wrong number of parameters in call of {}", fn));
}

}  // namespace

void Interpreter::configureDNumbers() {
  tool::DNumberConfig c;
  c.flat = data_.get("$MN_MM_TYPE_OF_CUTTING_EDGE") != 0;
  c.max_d = static_cast<int>(data_.get("$MN_MM_MAX_CUTTING_EDGE_NO"));
  c.max_per_tool = static_cast<int>(data_.get("$MN_MM_MAX_CUTTING_EDGE_PERTOOL"));
  tools_.configure(c);
}

void Interpreter::storeCallArgument(std::string_view fn, size_t k, const Value& v, bool required) {
  for (const lang::Node& n : block_.nodes) {
    if (n.kind != lang::NodeKind::Call || n.text != fn || static_cast<int>(k) >= n.b) continue;
    const lang::Node& arg = block_.node(block_.arg(n, static_cast<int>(k)));
    const bool variable = (arg.kind == lang::NodeKind::Name && !arg.text.empty()) ||
                          arg.kind == lang::NodeKind::Index || arg.kind == lang::NodeKind::RParam ||
                          arg.kind == lang::NodeKind::RIndex;
    if (variable) {
      store(arg, v);
      return;
    }
    break;
  }
  if (required)
    raise(AlarmNumber::ParamNotVariable,
          fmt::format("{}: parameter {} is a result (VAR) and must be a variable", fn, k + 1));
}

bool Interpreter::toolFunction(std::string_view name, std::span<const Value> args, Value& out) {
  if (name == "CHKDNO") {
    wantArgs(args, 0, 3, name);
    tool::ToolSelection::DCollision c;
    const bool unique = tools_.checkDNumbers(wholeArg(args, 0, name, 0), wholeArg(args, 1, name, 0),
                                             wholeArg(args, 2, name, 0), c);
    if (!unique) {  // PM: the parameters return what caused the collision
      const int found[3] = {c.t1, c.t2, c.d};
      for (size_t k = 0; k < args.size(); ++k)
        storeCallArgument(name, k, Value::integer(found[k]), false);
    }
    out = Value::boolean(unique);
  } else if (name == "GETDNO") {
    wantArgs(args, 2, 2, name);
    out = Value::integer(tools_.getDNumber(wholeArg(args, 0, name, 0), wholeArg(args, 1, name, 0)));
  } else if (name == "SETDNO") {
    wantArgs(args, 3, 3, name);
    out = Value::boolean(tools_.setDNumber(wholeArg(args, 0, name, 0), wholeArg(args, 1, name, 0),
                                           wholeArg(args, 2, name, 0)));
  } else if (name == "DZERO") {
    wantArgs(args, 0, 0, name);
    tools_.invalidateDNumbers();
    out = Value::empty();
  } else if (name == "GETACTTD" || name == "GETACTT") {
    wantArgs(args, 2, 2, name);
    int t = 0;
    const int status = name == "GETACTTD" ? tools_.toolOfDNumber(wholeArg(args, 1, name, 0), t)
                                          : tools_.toolOfName(textArg(args, 1, name), t);
    storeCallArgument(name, 0, Value::integer(t), true);
    out = Value::integer(status);
  } else if (name == "TOOLENV" || name == "DELTOOLENV" || name == "GETTENV") {
    out = toolEnvironmentCall(name, args);
  } else if (name == "GETTCOR") {
    out = callGettcor(args);
  } else if (name == "SETTCOR") {
    out = callSettcor(args);
  } else {
    return false;
  }
  return true;
}

Value Interpreter::toolEnvironmentCall(std::string_view name, std::span<const Value> args) {
  auto& envs = tools_.environments();
  const double capacity = data_.get("$MN_MM_NUM_TOOL_ENV");  // MD18116
  auto find = [&envs](const std::string& n) {
    for (auto it = envs.begin(); it != envs.end(); ++it)
      if (it->name == n) return it;
    return envs.end();
  };
  if (name == "TOOLENV") {
    wantArgs(args, 1, 1, name);
    const std::string env_name = textArg(args, 0, name);
    if (capacity <= 0) return Value::integer(-1);
    if (env_name.empty()) return Value::integer(-3);
    tool::ToolEnvironment env = tools_.currentEnvironment(
        selectionContext().settings, modal_.plane, frames_.active().mirror, frames_.map().linear);
    env.name = env_name;
    if (auto it = find(env_name); it != envs.end()) {
      *it = env;  // the same name again: saved anew
    } else {
      if (static_cast<double>(envs.size()) >= capacity) return Value::integer(-2);
      envs.push_back(env);
    }
    return Value::integer(0);
  }
  if (name == "DELTOOLENV") {
    wantArgs(args, 0, 1, name);
    if (capacity <= 0) return Value::integer(-1);
    if (omitted(args, 0)) {
      envs.clear();  // no name: all tool environments
      return Value::integer(0);
    }
    auto it = find(textArg(args, 0, name));
    if (it == envs.end()) return Value::integer(-2);
    envs.erase(it);
    return Value::integer(0);
  }
  wantArgs(args, 2, 2, name);  // GETTENV(_NAME, _TDDL)
  const std::string env_name = textArg(args, 0, name);
  std::span<Value> tddl = arrayArgument(name, args[1], true, 3, 0, "_TDDL");
  int t = tools_.activeTool(), d = tools_.activeEdge(), dl = 0;
  if (!env_name.empty()) {
    if (capacity <= 0) return Value::integer(-1);
    auto it = find(env_name);
    if (it == envs.end()) return Value::integer(-2);
    t = it->t, d = it->d, dl = it->dl;
  }
  tddl[0] = Value::integer(t), tddl[1] = Value::integer(d), tddl[2] = Value::integer(dl);
  return Value::integer(0);
}

int Interpreter::toolEnvironmentFor(const std::string& stat, tool::ToolEnvironment& env) {
  env = tools_.currentEnvironment(selectionContext().settings, modal_.plane,
                                  frames_.active().mirror, frames_.map().linear);
  if (stat.empty()) return 0;  // the empty name: the current state
  if (data_.get("$MN_MM_NUM_TOOL_ENV") <= 0) return -1;
  for (const auto& e : tools_.environments())
    if (e.name == stat) {
      env = e;
      return 0;
    }
  return -2;
}

Value Interpreter::callGettcor(std::span<const Value> args) {
  static constexpr std::string_view kName = "GETTCOR";
  wantArgs(args, 1, 6, kName);
  std::span<Value> len = arrayArgument(kName, args[0], false, 11, 0, "_LEN");
  const std::string comp = textArg(args, 1, kName);
  tool::ToolEnvironment env;
  if (int st = toolEnvironmentFor(textArg(args, 2, kName), env)) return Value::integer(st);
  env.t = wholeArg(args, 3, kName, env.t);
  env.d = wholeArg(args, 4, kName, env.d);
  env.dl = wholeArg(args, 5, kName, env.dl);
  return Value::integer(tools_.toolCorrection(len, comp, env));
}

// SETTCOR(_CORVAL, _COMP, _CORCOMP, _CORMODE, _GEOAX, _STAT, _T, _D, _DL) (W1 "Changing tool
// components"; docs/tool-offsets.md section 14a): the status as the function value.
Value Interpreter::callSettcor(std::span<const Value> args) {
  static constexpr std::string_view kName = "SETTCOR";
  wantArgs(args, 2, 9, kName);
  tool::SettcorRequest r;
  std::span<Value> val = arrayArgument(kName, args[0], false, 3, 0, "_CORVAL");
  for (size_t k = 0; k < 3; ++k) r.value[k] = lang::toNumber(val[k], "_CORVAL");
  r.comp = textArg(args, 1, kName);
  r.corcomp = wholeArg(args, 2, kName, 0);
  r.cormode = wholeArg(args, 3, kName, 0);
  if (!omitted(args, 4)) {
    const Value& ax = args[4];
    if (ax.type == Type::Axis || ax.type == Type::String || ax.type == Type::Symbol)
      r.geoax = axes_.geometry(ax.str);  // -1: no geometry axis (status -13)
  }
  tool::ToolEnvironment env;
  if (int st = toolEnvironmentFor(textArg(args, 5, kName), env)) return Value::integer(st);
  env.t = wholeArg(args, 6, kName, env.t);
  env.d = wholeArg(args, 7, kName, env.d);
  env.dl = wholeArg(args, 8, kName, env.dl);
  return Value::integer(tools_.setToolCorrection(r, env));
}

}  // namespace ncoffset::interp
