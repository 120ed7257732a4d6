// Subprogram calls (PM-JP "Subprogram technique"): the statements PROC, EXTERN, MCALL, CALL and
// PCALL, entering and leaving a call level (parameters, SAVE, the write-back of VAR parameters)
// and the modal call after a block with a path motion. The arguments and their binding are in
// call_arguments.cpp; the program levels themselves in ProgramFlow.
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "interp/interpreter.hpp"
#include "lang/predefined_names.hpp"
#include "lang/reserved_names.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Node;
using lang::NodeKind;
using lang::Stmt;

void Interpreter::resetCalls() {
  call_frames_.clear();
  call_args_ = -1;
  mcall_set_ = false;
  mcall_ = {};
  modal_depth_ = 0;
  section_end_ = static_cast<size_t>(-1);
  motion_.settingsMayChange();  // a new run: tool or machine data may have changed since
}

// CALL BLOCK <start> TO <end> (a section of this program) and CALL <name> BLOCK <start> TO
// <end> (a section of another program): a program level that runs from the start label (or
// block number) through the end label's block, then returns after the CALL (PM-JP "Indirect
// call of a program part"). A section of the calling program shares its variables.
void Interpreter::callSection(const Stmt& st) {
  const bool own = st.expr >= 0;
  if (own) {
    lang::Value v = eval_.eval(block_, st.expr);
    if (!v.isText() || v.str.empty())
      raise(AlarmNumber::TypeMismatch,
            "operation not compatible with data type: CALL needs a program name (a STRING)");
    std::string name = v.str;
    for (auto& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    enterSubprogram(name, 1, {}, false);
  } else {
    flow_.callProgram(*flow_.level().program);
    call_frames_.emplace_back().own_scope = false;
  }
  CallFrame& f = call_frames_.back();
  if (st.expr2 >= 0) {
    if (!sectionJump(st.expr2))
      raise(AlarmNumber::JumpNotFound,
            "jump destination: the end of the CALL BLOCK section not "
            "found");
    f.section_end = flow_.level().pos.offset;
  }
  if (!sectionJump(st.target))
    raise(AlarmNumber::JumpNotFound,
          "jump destination: the start of the CALL BLOCK section not found");
  section_end_ = f.section_end;
}

bool Interpreter::sectionJump(int target_node) {
  const Node& t = block_.node(target_node);
  const JumpSearch anywhere{false, true, false};  // backward from beyond the end: the file
  const size_t end = static_cast<size_t>(-1);
  if (t.kind == NodeKind::BlockNo)
    return flow_.jumpToBlockNumber(static_cast<long long>(t.number), end, anywhere);
  if (t.kind != NodeKind::Name) return false;
  return flow_.jumpToLabel(std::string(t.text), end, anywhere);
}

void Interpreter::endSection() {
  if (flow_.depth() > 1) leaveSubprogram();
}

bool Interpreter::callStatement(const Stmt& st) {
  const std::string_view kw = st.name;
  if (kw == "PROC") {
    procStatement(st);
    return true;
  }
  if (kw == "EXTERN") {
    // The declaration of a subprogram with parameters: its parameter types (PM-JP "EXTERN").
    ProcSignature decl;
    decl.has_proc = true;
    for (const auto& d : block_.decls)
      decl.params.push_back(
          {std::string(d.name), d.type, d.string_length, {d.dims[0], d.dims[1]}, d.by_ref});
    externs_[std::string(block_.node(st.target).text)] = std::move(decl);
    return true;
  }
  if (kw == "MCALL") {
    modalCallStatement(st);
    return true;
  }
  if (kw == "PCALL") {
    const Node& n = block_.node(st.target);
    collectCall(n.text, n.kind == NodeKind::Call ? st.target : -1);
    return true;
  }
  if (kw == "CALL" || kw == "EXTCALL") {
    indirectCall(st);
    return true;
  }
  return false;
}

// The PROC line itself: the parameters were bound by the call. A main program with parameters
// has no caller: its parameters take their defaults.
void Interpreter::procStatement(const Stmt& st) {
  if (flow_.depth() > 1 || st.ext == 0) return;
  CallFrame main;
  main.signature = &signatureOf(*flow_.level().program);
  bindParameters(main);
}

void Interpreter::modalCallStatement(const Stmt& st) {
  if (st.target < 0) {  // MCALL alone: the modal call ends
    mcall_ = {};
    return;
  }
  const Node& n = block_.node(st.target);
  if (!programExists(n.text) && externs_.find(n.text) == externs_.end())
    raise(AlarmNumber::ProgramNotFound,
          fmt::format("program {} not existing (MCALL; looked for {}.SPF beside the main program)",
                      n.text, n.text));
  ModalCall next;
  next.active = true;
  next.name = std::string(n.text);
  // The arguments are taken when MCALL is programmed (docs/language.md "MCALL").
  if (n.kind == NodeKind::Call) next.args = actualArguments(st.target, true);
  mcall_ = std::move(next);
  mcall_set_ = true;
}

// CALL <name expression>: the program whose name the expression gives (PM-JP "Indirect
// subprogram call").
void Interpreter::indirectCall(const Stmt& st) {
  if (st.target >= 0) {
    callSection(st);
    return;
  }
  lang::Value v = eval_.eval(block_, st.expr);
  if (!v.isText() || v.str.empty())
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: CALL needs a program name (a "
                      "STRING), not {}",
                      lang::typeName(v.type)));
  std::string name = v.str;
  if (st.name == "EXTCALL") {
    // EXTCALL ("/path/PART.SPF"): the program from external storage; ncoffset reads every
    // program from the search path, so the last part of the path without its type names it.
    if (size_t slash = name.find_last_of("/\\"); slash != std::string::npos)
      name.erase(0, slash + 1);
    if (size_t dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.erase(dot);
  }
  for (auto& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (!words_.call.empty())
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined (a block calls one subprogram; CALL {} follows)",
                      words_.call, name));
  call_name_ = std::move(name);
  words_.call = call_name_;
}

// $P_SUBPAR[n]: TRUE when the n-th argument of the current call was given (PM-JP "Incomplete
// parameter transfer"); in the main program FALSE.
bool Interpreter::readCallVariable(std::string_view name, std::span<const lang::Value> idx,
                                   lang::Value& out) {
  if (name != "$P_SUBPAR") return false;
  if (idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_SUBPAR takes one index");
  const double n = lang::toNumber(idx[0], "array index");
  const CallFrame* f = call_frames_.empty() ? nullptr : &call_frames_.back();
  if (f && !f->signature) f = nullptr;  // a CALL BLOCK section of the same program: no call
  const size_t count = f ? f->signature->params.size() : 0;
  if (n != std::floor(n) || n < 1 || n > static_cast<double>(f ? count : 127))
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index: $P_SUBPAR[{}] (parameters 1..{})", n, count));
  const size_t k = static_cast<size_t>(n) - 1;
  out = lang::Value::boolean(f && k < f->args.size() && f->args[k].kind != CallArg::Kind::Omitted);
  return true;
}

bool Interpreter::isSubprogramName(std::string_view name) {
  // L123 is an address with a number, and a program name when it is called (L123(args)).
  const bool l_number = name.size() > 1 && name[0] == 'L' &&
                        name.find_first_not_of("0123456789", 1) == std::string_view::npos;
  if (name == "RET")
    raise(AlarmNumber::NotModelled,
          "RET with parameters (the return to a label or block number, or over several levels) "
          "is not modelled by ncoffset");
  // A predefined procedure (SETAL, WAITM, ...) is never a program of the same name; a standard
  // cycle (CYCLE81, ...) is, where one is there, with its parameters (docs/names.md).
  const lang::PredefinedName* p = lang::findPredefinedName(name);
  if (p && !p->cycle) return false;
  if (!p && !l_number && lang::isPredefinedName(name)) return false;
  return externs_.find(name) != externs_.end() || programExists(name);
}

void Interpreter::collectCall(std::string_view name, int args_node) {
  if (!words_.call.empty())
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined (a block calls one subprogram; {} follows)", words_.call,
                      name));
  words_.call = name;
  call_args_ = args_node;
}

void Interpreter::enterSubprogram(std::string_view name, long long repeat,
                                  std::vector<CallArg> args, bool modal) {
  auto ext = externs_.find(name);
  if (ext != externs_.end() && args.size() > ext->second.params.size())
    raise(AlarmNumber::TooManyParams,
          fmt::format("number of parameters too high: {} arguments for {} (EXTERN declares {})",
                      args.size(), name, ext->second.params.size()));
  const size_t files_before = flow_.fileCount();
  try {
    flow_.call(name, repeat);
  } catch (const AlarmError&) {
    // An alarm of a program loaded by this call (its structure) belongs to that program.
    if (flow_.fileCount() > files_before) file_ = static_cast<int>(flow_.fileCount()) - 1;
    throw;
  }
  if (ProgramLevel& lvl = flow_.level(); lvl.program->builtin) {
    lvl.report_file = file_;  // the caller's, already its caller's if it is built in too
    lvl.report_line = line_;
    lvl.report_text = line_text_;
  }
  vars_.pushScope();
  CallFrame& f = call_frames_.emplace_back();
  f.modal = modal;
  if (modal) ++modal_depth_;
  f.args = std::move(args);
  f.signature = &signatureOf(*flow_.level().program);
  if (f.signature->attributes & lang::kProcSave) {
    f.save = true;
    f.saved_modal = modal_;
    f.saved_settable = frames_.settableActive();
    f.saved_programmable = frames_.programmable();
  }
  bindParameters(f);
  section_end_ = f.section_end;
}

void Interpreter::leaveSubprogram() {
  motion_.settingsMayChange();  // SAVE restores the G groups (restoreSaved)
  CallFrame& f = call_frames_.back();
  // VAR parameters bound to an array element or an R parameter go back to the caller.
  std::vector<lang::Value> out;
  for (const auto& w : f.write_backs) out.push_back(vars_.find(w.param)->data[0]);
  const bool again = flow_.leave();
  if (again)
    vars_.clearScope();  // the next pass starts without the variables of this one
  else if (f.own_scope)
    vars_.popScope();
  for (size_t k = 0; k < out.size(); ++k) {
    const WriteBack& w = f.write_backs[k];
    if (w.var)
      w.var->data[w.offset] = out[k];
    else
      vars_.setR(w.r, out[k].num);
  }
  if (again) {
    f.write_backs.clear();
    bindParameters(f);  // each pass gets its arguments anew
    return;
  }
  if (f.save) restoreSaved(f);
  if (f.modal) --modal_depth_;
  call_frames_.pop_back();
  section_end_ = call_frames_.empty() ? static_cast<size_t>(-1) : call_frames_.back().section_end;
}

// SAVE: the modal G functions and the frames of the call come back (PM-JP "SAVE"; K2 "Subroutine
// return with SAVE": the settable frame only if another G54.. is active, the programmable frame
// always; basic and system frames are not modelled).
void Interpreter::restoreSaved(const CallFrame& f) {
  const ModalState now = modal_;
  if (now.trc != f.saved_modal.trc)
    raise(AlarmNumber::NotModelled,
          "return from a SAVE subprogram with another tool radius compensation (G40/G41/G42) "
          "than at its call is not modelled by ncoffset");
  modal_ = f.saved_modal;
  tools_.setDifferential(modal_.cut2d_differential);  // group 22 is a G group: restored too
  // Addresses are no G functions: F, DISC=, OFFN=, T and D stay as the subprogram left them.
  modal_.feed = now.feed;
  modal_.disc = now.disc;
  modal_.offn = now.offn;
  modal_.tool = now.tool;
  modal_.edge = now.edge;
  if (now.frame_select != f.saved_modal.frame_select) frames_.settableActive() = f.saved_settable;
  frames_.programmable() = f.saved_programmable;
  frames_.update();
}

// MCALL (PM-JP "Modal subprogram call"): after every block that moves a geometry axis, outside
// the modally called subprogram itself (its blocks and what it calls do not call it again).
void Interpreter::modalCallAfter() {
  loop_.dirty();
  // The block moved the path as finishBlock decides it: axis words that are targets (not of a
  // frame statement, G58/G59 or G25/G26), circle words with G2/G3, or a SAR block.
  const bool axes_consumed = !words_.frame_command.empty() || words_.axial_offset == 58 ||
                             words_.axial_offset == 59 || words_.axial_offset == 25 ||
                             words_.axial_offset == 26;
  const bool circle_words = words_.centre[0] || words_.centre[1] || words_.centre[2] || words_.cr ||
                            words_.ar || words_.turn;
  const bool is_arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  const bool path_block =
      !axes_consumed && (words_.axis[0] || words_.axis[1] || words_.axis[2] ||
                         (is_arc && circle_words) || words_.sar != core::SarKind::None);
  if (mcall_set_) {  // the MCALL block itself
    mcall_set_ = false;
    return;
  }
  if (!path_block || modal_depth_ > 0 || ended_) return;
  enterSubprogram(mcall_.name, 1, mcall_.args, true);
}

}  // namespace ncoffset::interp
