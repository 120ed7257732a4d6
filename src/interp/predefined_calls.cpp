// The predefined names without code of their own (lang/predefined_names.hpp, docs/names.md):
// what a bare name, a call, an assignment or a read of one does, SETAL (PM-JP "Programming
// alarms") and ISVAR (PM-JP "Check availability of a variable").
#include <fmt/format.h>

#include <cmath>

#include "core/not_modelled.hpp"
#include "interp/interpreter.hpp"
#include "lang/predefined_names.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::findPredefinedName;
using lang::NameClass;
using lang::PredefinedName;
using lang::Value;

namespace {

// Alarm 99010 for a (c) name: "NAME is not modelled by ncoffset: why".
[[noreturn]] void notModelledName(const PredefinedName& p, std::string_view written) {
  core::notModelled(written, p.why);
}

// SETAL(number[, text]): the cycle alarms are 60000..69999 (PM-JP "SETAL"); the program stops
// with the alarm, as on the control (its reaction is the cycle alarm's: NC stop).
[[noreturn]] void setAlarm(std::span<const Value> args) {
  if (args.empty() || args.size() > 2)
    raise(AlarmNumber::WrongCallParams, "SETAL takes an alarm number and an optional text");
  const double n = lang::toNumber(args[0], "alarm number");
  if (!(n >= 60000 && n <= 69999) || n != std::floor(n))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: SETAL({}) (cycle alarms 60000..69999)", n));
  std::string text = fmt::format("cycle alarm {} set by SETAL", static_cast<int>(n));
  if (args.size() == 2 && args[1].type != lang::Type::Empty) text += ": " + lang::toText(args[1]);
  throw AlarmError(static_cast<AlarmNumber>(static_cast<int>(n)), text);
}

}  // namespace

bool Interpreter::predefinedWord(std::string_view name) {
  if (name == "DZERO") {  // W1 2.1.5: invalidates every D number of the TO unit
    tools_.invalidateDNumbers();
    return true;
  }
  const PredefinedName* p = findPredefinedName(name);
  if (!p) {
    // SETINT(3) PRIO=1 RETRACT: the name is the interrupt routine, assigned, not called (PM-JP
    // "Interrupt routines"); interrupts are never triggered here.
    for (const lang::Stmt& st : block_.stmts)
      if (st.kind == lang::StmtKind::ProcCall && st.name == "SETINT") return true;
    return false;
  }
  if (p->cycle && programExists(name)) return false;
  if (p->cls == NameClass::NotModelled) notModelledName(*p, name);
  if (name == "SETAL") raise(AlarmNumber::WrongCallParams, "SETAL needs an alarm number");
  return true;
}

bool Interpreter::predefinedCall(std::string_view name, std::span<const Value> args, Value& out) {
  if (name == "ISVAR") {
    out = isVar(args);
    return true;
  }
  if (name == "SETAL") setAlarm(args);
  if (name == "_NCO_NOT_MODELLED" && args.size() == 1 && args[0].isText())  // built-in cycles
    raise(AlarmNumber::NotModelled,
          fmt::format("{} of this standard cycle: not modelled by ncoffset", args[0].str));
  const PredefinedName* p = findPredefinedName(name);
  if (!p || (p->cycle && programExists(name))) return false;
  if (p->cls == NameClass::NotModelled) notModelledName(*p, name);
  if (name == "WRITE" || name == "DELETE") fileErrorZero(name);
  out = Value::empty();
  return true;
}

// WRITE(err, "file", "text") / DELETE(err, "file") (PM-JP "Writing / deleting a file"): the
// control sets the error variable, 0 when the file operation succeeded, which is what the
// program sees on a machine with its memory in order; ncoffset writes no file.
void Interpreter::fileErrorZero(std::string_view name) {
  for (const lang::Stmt& st : block_.stmts) {
    if (st.kind != lang::StmtKind::ProcCall || st.name != name) continue;
    const lang::Node& call = block_.node(st.expr);
    if (call.b < 1)
      raise(AlarmNumber::WrongCallParams, fmt::format("{} needs its error variable", name));
    const lang::Node& err = block_.node(block_.arg(call, 0));
    if (err.kind == lang::NodeKind::Name && err.text.empty())
      raise(AlarmNumber::WrongCallParams, fmt::format("{} needs its error variable", name));
    if (err.kind == lang::NodeKind::Name || err.kind == lang::NodeKind::Index ||
        err.kind == lang::NodeKind::RParam || err.kind == lang::NodeKind::RIndex)
      store(err, Value::integer(0));
    else
      raise(AlarmNumber::WrongCallParams,
            fmt::format("{}: the first parameter is the error variable (a variable)", name));
    return;
  }
}

bool Interpreter::predefinedAssign(std::string_view name, const Value& v) {
  const PredefinedName* p = findPredefinedName(name);
  if (!p) return false;
  if (p->cls == NameClass::NotModelled &&
      !(p->zero_accepted && v.isNumeric() && std::fabs(v.num) < 1e-12))
    notModelledName(*p, fmt::format("{}=", name));
  if (p->cls != NameClass::NotModelled && !v.isNumeric() && v.type != lang::Type::Empty &&
      !v.isText())
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {} takes a value", name));
  return true;
}

bool Interpreter::predefinedRead(std::string_view name) {
  const PredefinedName* p = findPredefinedName(name);
  if (!p || p->cls != NameClass::NotModelled) return false;
  notModelledName(*p, name);
}

// ISVAR("name"): TRUE when the name is a variable the channel knows: a user variable, an R
// parameter, machine or setting data, or a system variable ncoffset models. Indices written
// with the name ("$P_UIFR[1]") are not checked.
Value Interpreter::isVar(std::span<const Value> args) {
  if (args.size() != 1 || !args[0].isText())
    raise(AlarmNumber::WrongCallParams, "ISVAR takes one STRING (the variable's name)");
  std::string name = args[0].str;
  for (char& c : name)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  if (const size_t bracket = name.find('['); bracket != std::string::npos) name.resize(bracket);
  if (name == "$AA_IW" || name == "$AA_IM") return Value::boolean(true);  // no implicit stop
  if (name.size() >= 2 && name.size() <= 10 && name[0] == 'R' &&
      name.find_first_not_of("0123456789", 1) == std::string::npos)
    return Value::boolean(std::stod(name.substr(1)) < static_cast<double>(vars_.rCount()));
  if (vars_.find(name) || data_.find(name) >= 0) return Value::boolean(true);
  if (name.empty() || name[0] != '$') return Value::boolean(false);
  // A system variable: known when one of the read forms (no index, [X], [1]) gives a value or
  // an alarm other than 12550 (an index alarm means the name exists).
  const Value forms[2] = {Value::symbol("X"), Value::integer(1)};
  for (int form = 0; form < 3; ++form) {
    try {
      Value v;
      if (form == 0 ? read(name, {}, false, v) : read(name, {&forms[form - 1], 1}, true, v))
        return Value::boolean(true);
    } catch (const AlarmError& e) {
      if (e.alarm() != AlarmNumber::NameNotDefined) return Value::boolean(true);
    }
  }
  return Value::boolean(false);
}

}  // namespace ncoffset::interp
