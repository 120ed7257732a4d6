// Parameter transfer (PM-JP "Subprogram technique", "Parameter transfer"): the actual
// arguments of a call taken in the caller's scope, the formal parameters of the called
// program's PROC header, and the binding of one to the other in the new level's scope:
// call by value (a converted copy), call by reference (VAR: the caller's variable), left-out
// arguments (the type's initial value; alarm 14010 for VAR and AXIS).
#include <fmt/format.h>

#include "interp/interpreter.hpp"
#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Node;
using lang::NodeKind;
using lang::Value;

std::vector<CallArg> Interpreter::actualArguments(int args_node, bool modal) {
  std::vector<CallArg> out;
  if (args_node < 0) return out;
  const Node& call = block_.node(args_node);
  for (int k = 0; k < call.b; ++k) {
    const Node& n = block_.node(block_.arg(call, k));
    CallArg a;
    a.modal = modal;
    if (n.kind == NodeKind::Name && n.text.empty()) {
      out.push_back(a);  // NAME(1,,3): left out
      continue;
    }
    UserVariable* var = nullptr;
    if (!modal && (n.kind == NodeKind::Name || n.kind == NodeKind::Index)) var = vars_.find(n.text);
    if (var && n.kind == NodeKind::Name) {
      a.kind = CallArg::Kind::Variable;
      a.var = var;
    } else if (var) {
      std::vector<Value> idx;
      eval_.evalArgs(block_, n, idx);
      a.kind = CallArg::Kind::Element;
      a.var = var;
      a.offset = VariableStore::elementIndex(*var, idx, n.text);
    } else if (!modal && n.kind == NodeKind::RParam) {
      a.kind = CallArg::Kind::RParam;
      a.r = n.number;
      vars_.r(a.r);  // range check now, in the caller's block
    } else if (!modal && n.kind == NodeKind::RIndex && n.b == 1) {
      a.kind = CallArg::Kind::RParam;
      a.r = lang::roundToInt(eval_.number(block_, block_.arg(n, 0)));
      vars_.r(a.r);
    } else {
      a.kind = CallArg::Kind::Value;
      a.value = eval_.eval(block_, block_.arg(call, k));
    }
    out.push_back(std::move(a));
  }
  return out;
}

// The PROC header of a program: its first block with statements (read once per program).
const ProcSignature& Interpreter::signatureOf(const LoadedProgram& prog) {
  if (auto it = signatures_.find(prog.file_id); it != signatures_.end()) return it->second;
  ProcSignature sig;
  std::string_view text;
  lang::TextPos pos;
  lang::TextPos at;
  while (at = pos, lang::nextLine(prog.source->text(), pos, text)) {
    if (!text.empty() && text.front() == '%') continue;  // archive header
    try {
      lang::parseBlock(text, at.line, scan_block_, {options_.limits.max_expression_depth});
    } catch (const AlarmError&) {
      // The alarm names the subprogram's line, as when the block is executed.
      file_ = prog.file_id;
      line_ = at.line;
      line_text_ = text;
      column_ = 0;
      throw;
    }
    if (scan_block_.stmts.empty() && scan_block_.decls.empty()) continue;
    const lang::Stmt& st = scan_block_.stmts.front();
    if (st.kind == lang::StmtKind::Keyword && st.name == "PROC") {
      sig.has_proc = true;
      sig.attributes = st.expr2;
      for (const auto& d : scan_block_.decls)
        sig.params.push_back(
            {std::string(d.name), d.type, d.string_length, {d.dims[0], d.dims[1]}, d.by_ref});
    }
    break;
  }
  return signatures_.emplace(prog.file_id, std::move(sig)).first->second;
}

namespace {

// "CYCLE801.SPF (built-in)" -> "CYCLE801"
std::string_view cycleName(std::string_view source_name) {
  return source_name.substr(0, source_name.find('.'));
}

}  // namespace

void Interpreter::bindParameters(CallFrame& f) {
  const auto& params = f.signature->params;
  if (f.args.size() > params.size()) {
    if (flow_.level().program->builtin)
      // A newer software version of a standard cycle takes more parameters (Operate's CYCLE801
      // with its shear angles, say); their order and meaning are not known here (docs/cycles.md).
      raise(AlarmNumber::NotModelled,
            fmt::format("{} arguments for the standard cycle {}, which ncoffset models with {} "
                        "parameters (PG Cycles 11.02): the newer form of the cycle is not "
                        "modelled; a cycle of that name on the search path is run instead of the "
                        "built-in one",
                        f.args.size(), cycleName(flow_.level().program->source->name()),
                        params.size()));
    raise(AlarmNumber::TooManyParams,
          fmt::format("number of parameters too high: {} arguments for {} formal parameters",
                      f.args.size(), params.size()));
  }
  static const CallArg kOmitted;
  for (size_t i = 0; i < params.size(); ++i)
    bindParameter(params[i], i < f.args.size() ? f.args[i] : kOmitted, i + 1, f);
}

namespace {

bool sameShape(const FormalParameter& p, const UserVariable& v) {
  const bool formal_array = p.dims[0] != 0;
  if (formal_array != v.isArray()) return false;
  if (!formal_array) return true;
  if ((p.dims[1] > 0) != (v.dims[1] > 0)) return false;
  return (p.dims[0] < 0 || p.dims[0] == v.dims[0]) && p.dims[1] == v.dims[1];
}

}  // namespace

void Interpreter::bindParameter(const FormalParameter& p, const CallArg& a, size_t position,
                                CallFrame& f) {
  lang::Decl d;
  d.type = p.type;
  d.name = p.name;
  d.string_length = p.string_length;
  auto typeAlarm = [&](std::string_view what) {
    raise(AlarmNumber::ParamType,
          fmt::format("type of parameter {} ({}) incorrect: {}", position, p.name, what));
  };
  if (a.kind == CallArg::Kind::Omitted) {
    if (p.by_ref || p.type == lang::VarType::Axis)
      raise(AlarmNumber::DefaultParam,
            fmt::format("invalid default parameter in subprogram call: parameter {} ({}) is {} "
                        "and cannot be left out",
                        position, p.name, p.by_ref ? "VAR" : "AXIS"));
    vars_.add(p.name, vars_.prepare(d));  // the type's initial value
    return;
  }
  if (p.by_ref) {
    if (a.modal)
      raise(AlarmNumber::NotModelled,
            fmt::format("MCALL with a VAR parameter ({}) is not modelled by ncoffset", p.name));
    if (a.kind == CallArg::Kind::Value)
      raise(AlarmNumber::ParamNotVariable,
            fmt::format("parameter {} ({}) is not a variable: VAR needs a variable, an array "
                        "element or an R parameter",
                        position, p.name));
    if (a.kind == CallArg::Kind::Variable) {
      if (a.var->type != p.type) typeAlarm("VAR needs a variable of the same type");
      if (!sameShape(p, *a.var)) typeAlarm("the array dimensions differ");
      UserVariable alias;
      alias.ref = a.var;
      alias.type = p.type;
      vars_.add(p.name, std::move(alias));
      return;
    }
    if (p.dims[0] != 0) typeAlarm("an array needs a whole array");
    const bool r = a.kind == CallArg::Kind::RParam;
    if (r ? p.type != lang::VarType::Real : a.var->type != p.type)
      typeAlarm("VAR needs a variable of the same type");
    UserVariable copy = vars_.prepare(d);
    copy.data[0] = r ? Value::real(vars_.r(a.r)) : a.var->data[a.offset];
    vars_.add(p.name, std::move(copy));
    f.write_backs.push_back({p.name, r ? nullptr : a.var, a.offset, a.r});
    return;
  }
  Value v = a.value;
  if (a.kind == CallArg::Kind::Variable) {
    if (a.var->isArray()) typeAlarm("an array is passed with VAR only");
    v = a.var->data[0];
  } else if (a.kind == CallArg::Kind::Element) {
    v = a.var->data[a.offset];
  } else if (a.kind == CallArg::Kind::RParam) {
    v = Value::real(vars_.r(a.r));
  }
  UserVariable var = vars_.prepare(d);
  try {
    var.data[0] = convertForStore(v, p.type, p.string_length, p.name);
  } catch (const AlarmError& e) {
    if (e.number() != static_cast<int>(AlarmNumber::TypeMismatch)) throw;
    typeAlarm(fmt::format("{} given for {}", lang::typeName(v.type), varTypeName(p.type)));
  }
  vars_.add(p.name, std::move(var));
}

}  // namespace ncoffset::interp
