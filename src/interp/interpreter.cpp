// Program flow: block loop, control structures, jumps, subprogram calls, variables.
#include "interp/interpreter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include "core/inline_step.hpp"
#include "ncoffset/alarm.hpp"
#include "out/vars_json.hpp"

namespace ncoffset::interp {

using lang::Node;
using lang::NodeKind;
using lang::Stmt;
using lang::StmtKind;
using lang::TextPos;
using lang::Value;

Interpreter::Interpreter(const RunOptions& options, PathSink& sink, core::Stage& first)
    : options_(options),
      first_(first),
      sink_(sink),
      eval_(*this),
      vars_(options.limits, static_cast<size_t>(data_.get("$MC_MM_NUM_R_PARAM"))),
      flow_(options.limits),
      tools_(options.limits.max_tool_edges),
      motion_(first, data_, frames_, tools_) {
  if (options.start) motion_.setStart(*options.start);
  md_max_disc_ = data_.find("$MC_CUTCOM_MAX_DISC");
  md_transverse_ = data_.find("$MC_DIAMETER_AX_DEF");
  md_base_function_mask_ = data_.find("$MA_BASE_FUNCTION_MASK");
  reset_values_[5] = 1;   // G17
  reset_values_[13] = 1;  // G90
  reset_values_[14] = 2;  // G94
  reset_values_[28] = 1;  // DIAMOF
  md_change_mode_ = data_.find("$MC_TOOL_CHANGE_MODE");
  md_change_m_ = data_.find("$MC_TOOL_CHANGE_M_CODE");
  md_default_edge_ = data_.find("$MC_CUTTING_EDGE_DEFAULT");
  sd_mirror_length_ = data_.find("$SC_MIRROR_TOOL_LENGTH");
  sd_mirror_wear_ = data_.find("$SC_MIRROR_TOOL_WEAR");
  sd_cutpos_ = data_.find("$SC_WEAR_SIGN_CUTPOS");
  sd_wear_sign_ = data_.find("$SC_WEAR_SIGN");
  sd_length_const_ = data_.find("$SC_TOOL_LENGTH_CONST");
  sd_length_type_ = data_.find("$SC_TOOL_LENGTH_TYPE");
  md_carriers_ = data_.find("$MN_MM_NUM_TOOL_CARRIER");
  sd_carrier_fine_ = data_.find("$SC_TOCARR_FINE_CORRECTION");
  configureDNumbers();
  syncSumOffsetLimits();
}

Interpreter::~Interpreter() = default;

template <typename F>
decltype(auto) Interpreter::loading(F&& f) {
  const size_t before = flow_.fileCount();
  try {
    return f();
  } catch (const AlarmError&) {
    if (flow_.fileCount() > before) file_ = static_cast<int>(flow_.fileCount()) - 1;
    if (int failed = flow_.takeFailedFile(); failed >= 0) file_ = failed;
    throw;
  }
}

LoadedProgram& Interpreter::load(std::shared_ptr<lang::SourceFile> source, bool init_file) {
  return loading([&]() -> LoadedProgram& { return flow_.load(std::move(source), !init_file); });
}

bool Interpreter::programExists(std::string_view name) {
  return loading([&] { return flow_.find(name) != nullptr; });
}

SourceLoc Interpreter::alarmLoc(const AlarmError& e) const {
  if (e.line() && e.line() != line_) return {fileName(file_), e.line(), e.column()};
  return {fileName(file_), line_, e.column() ? e.column() : column_};
}

std::string Interpreter::alarmSourceLine(const AlarmError& e) const {
  if (!e.line() || e.line() == line_) return std::string(line_text_);
  // Another line of the alarm's file (a structure error found when it was loaded).
  std::string_view text = flow_.text(file_), line;
  lang::TextPos pos;
  while (pos.line < e.line() && lang::nextLine(text, pos, line)) {
  }
  return pos.line == e.line() && lang::nextLine(text, pos, line) ? std::string(line) : "";
}

void Interpreter::executeBlock() {
  const lang::Block& b = block_;
  motion_.settingsMayChange();  // any line but a plain one may change them (motion_plain.cpp;
                                // a plain line's G40/G41/G42 resets them in plainG)
  if (b.stmts.empty() && b.decls.empty()) return;       // empty, comment or label-only line
  words_plain_ ? words_.clearPlain() : words_.clear();  // clearPlain: ten stores, not 300 bytes
  words_plain_ = false;  // until this block is through without an alarm
  ProgramLevel& lvl = flow_.level();
  if (b.plain) [[likely]] {
    executePlainBlock(b);  // plain_line.cpp
    return;
  }
  bool jumped = false;
  for (size_t i = 0; i < b.stmts.size() && !jumped; ++i) {
    const Stmt& st = b.stmts[i];
    column_ = st.column;  // where an alarm of this statement points
    // The definition part: PROC, DEF and EXTERN (PM-JP "Subprogram technique").
    if (st.kind != StmtKind::Keyword ||
        (st.name != "DEF" && st.name != "PROC" && st.name != "EXTERN"))
      lvl.defs_allowed = false;
    switch (st.kind) {
      case StmtKind::Word:
        if (!st.literal) [[unlikely]]
          watchWord(st);
        collectWord(st);
        break;
      case StmtKind::Assign:
        loop_.assignment(b, st);
        assign(st);
        break;
      case StmtKind::Call:
        loop_.dirty();
        namedWord(st);
        break;
      case StmtKind::ProcCall: {
        watchProcCall(st);
        if (isSubprogramName(st.name)) {  // NAME(args), L123(args): a subprogram call
          collectCall(st.name, st.expr);
          break;
        }
        std::vector<Value> args;
        eval_.evalArgs(b, b.node(st.expr), args);
        call(st.name, args);
        break;
      }
      case StmtKind::Keyword:
        watchKeyword(st);
        executeControl(st, i, jumped);
        if (st.name == "CASE") i = b.stmts.size();
        break;
      case StmtKind::CaseArm:
        break;  // read by caseStatement
    }
  }
  if (!jumped) finishBlock();
}

void Interpreter::executeControl(const Stmt& st, size_t index, bool& jumped) {
  const lang::Block& b = block_;
  ProgramLevel& lvl = flow_.level();
  std::string_view kw = st.name;
  if (kw == "DEF") {
    // A GUD definition file or an init file may define global user data anywhere.
    const bool gud = init_file_ && !b.decls.empty() && b.decls.front().global;
    if (!lvl.defs_allowed && !gud)
      raise(AlarmNumber::IllegalDef,
            "illegal DEF instruction: definitions must stand before the first statement of the "
            "program");
    for (const auto& d : b.decls) define(d);
    return;
  }
  if (kw == "DEFINE") {
    macros_.define(b.node(st.target).text, b.node(st.expr).text, init_file_);
    return;
  }
  if (callStatement(st)) return;          // PROC, EXTERN, MCALL, CALL, PCALL
  if (st.jump != lang::JumpKind::None) {  // GOTOF / GOTOB / GOTO / GOTOC
    jump(st, st.jump == lang::JumpKind::Gotoc);
    jumped = true;
    return;
  }
  if (kw == "IF" || kw == "ELSE") {
    ifStatement(st, index, jumped);
    return;
  }
  if (kw == "CASE") {
    caseStatement(st, index, jumped);
    return;
  }
  if (loopStatement(st, jumped)) return;
  raise(AlarmNumber::SyntaxError, fmt::format("unexpected {}", kw));
}

void Interpreter::endProgram() {
  ended_ = true;
  mcall_ = {};  // the program end ends a modal call
}

void Interpreter::returnFromSubprogram() {
  if (flow_.level().section) {
    flow_.leave();  // a repeated section: the next pass, or back after the REPEAT line
    return;
  }
  leaveSubprogram();  // subprogram_call.cpp: the next pass, or the return to the caller
}

void Interpreter::callSubprogram(std::string_view name, long long repeat) {
  const int args = call_args_;
  call_args_ = -1;
  mcall_set_ = false;  // an MCALL in a block with a call: the call is the block's only one
  enterSubprogram(name, repeat, actualArguments(args, false), false);
}

// --- variables ------------------------------------------------------------------------------

void Interpreter::define(const lang::Decl& d) {
  std::string_view name = d.name;
  UserVariable v = vars_.prepare(d);
  const size_t count = v.data.size();
  if (d.init >= 0) {
    v.data[0] = convertForStore(eval_.eval(block_, d.init), d.type, d.string_length, name);
  } else if (d.init_first >= 0) {
    if (static_cast<size_t>(d.init_count) > count && !d.init_rep)
      raise(AlarmNumber::ArrayIndex1,
            fmt::format("illegal array index: {} values for {} elements of {}", d.init_count, count,
                        name));
    if (d.init_rep) {
      if (d.init_count != 1) raise(AlarmNumber::WrongCallParams, "REP takes one value");
      Value x = convertForStore(eval_.eval(block_, block_.args[static_cast<size_t>(d.init_first)]),
                                d.type, d.string_length, name);
      std::fill(v.data.begin(), v.data.end(), x);
    } else {
      for (int k = 0; k < d.init_count; ++k) {
        const int arg = block_.args[static_cast<size_t>(d.init_first + k)];
        const lang::Node& n = block_.node(arg);
        // SET(0,,,9): an omitted value leaves its element at the type's default (PM-JP
        // "Definition and initialization of array variables").
        if (n.kind == lang::NodeKind::Name && n.text.empty()) continue;
        v.data[static_cast<size_t>(k)] =
            convertForStore(eval_.eval(block_, arg), d.type, d.string_length, name);
      }
    }
  }
  for (const auto& x : v.data) VariableStore::checkLimits(v, x, name);
  if (d.global && init_file_)
    vars_.addGlobal(name, std::move(v));
  else
    vars_.add(name, std::move(v));
}

bool Interpreter::read(std::string_view name, std::span<const Value> idx, bool indexed,
                       Value& out) {
  if (UserVariable* v = vars_.find(name)) {
    if (v->isArray()) {
      if (!indexed) {
        out = {lang::Type::ArrayRef, 0, std::string(name), {}};  // whole array: call argument
        return true;
      }
      out = v->data[VariableStore::elementIndex(*v, idx, name)];
    } else {
      if (indexed && readStringChar(*v, idx, name, out)) return true;  // STRG[i]
      if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} is not an array", name));
      out = v->data[0];
    }
    return true;
  }
  if (name[0] == '$' && readCallVariable(name, idx, out)) return true;  // $P_SUBPAR
  if (readSystem(name, idx, indexed, out)) return true;
  if (!indexed && name.size() == 1 &&
      (name[0] == 'X' || name[0] == 'Y' || name[0] == 'Z' || name[0] == 'A' || name[0] == 'B' ||
       name[0] == 'C')) {
    // An axis name as an AXIS value (the rotary axes A, B, C for $TC_CARR21/22 = B).
    out = {lang::Type::Axis, 0, std::string(name), {}};
    return true;
  }
  return false;
}

Value Interpreter::readR(double number) {
  return Value::real(vars_.r(number));
}

void Interpreter::assign(const Stmt& st) {
  const Node& target = block_.node(st.target);
  if (target.kind == NodeKind::Index &&
      (target.text == "AX" || target.text == "POS" || target.text == "POSA") &&
      !vars_.find(target.text)) {
    // Indirect axis programming AX[axis]=value (PM-JP "Indirect programming"); POS[ax]=,
    // POSA[ax]= positioning axes: the end position as an axis word of the block (docs/
    // language.md "Axes").
    if (target.b != 1) raise(AlarmNumber::ArrayIndex1, "AX[..] takes one axis");
    Stmt word = st;
    Value axis = eval_.evalOrSymbol(block_, block_.arg(target, 0));
    if (!axis.isText()) raise(AlarmNumber::TypeMismatch, "AX[..] needs an axis name");
    // The axis by its configured name (docs/language.md "Axes"): a view of the name the
    // channel keeps, valid for the block.
    const int ax = anyAxis(axis, target.text);
    word.name = ax < 3 ? std::string_view(axes_.geometryNames()[static_cast<size_t>(ax)])
                       : std::string_view(axes_.axes()[static_cast<size_t>(ax - 3)].name);
    const Node& rhs = block_.node(st.expr);
    static constexpr std::pair<std::string_view, lang::AxisMode> kModes[] = {
        {"AC", lang::AxisMode::AC},   {"IC", lang::AxisMode::IC},   {"DAC", lang::AxisMode::DAC},
        {"DIC", lang::AxisMode::DIC}, {"RAC", lang::AxisMode::RAC}, {"RIC", lang::AxisMode::RIC},
        {"DC", lang::AxisMode::DC},   {"ACP", lang::AxisMode::ACP}, {"ACN", lang::AxisMode::ACN}};
    for (const auto& [text, mode] : kModes)
      if (rhs.kind == NodeKind::Call && rhs.text == text && rhs.b == 1) {
        word.mode = mode;
        word.expr = block_.arg(rhs, 0);
      }
    word.kind = StmtKind::Word;
    word.has_equals = false;
    collectWord(word);
    return;
  }
  if (const Node& rhs = block_.node(st.expr);
      rhs.kind == NodeKind::Call && (rhs.text == "SET" || rhs.text == "REP") && arrayListAssign(st))
    return;  // ARRAY[i]=SET(..) / REP(..) (array_assign.cpp)
  Value v = eval_.eval(block_, st.expr);
  store(block_.node(st.target), v);
}

void Interpreter::store(const Node& target, const Value& v) {
  if (target.kind == NodeKind::RParam || target.kind == NodeKind::RIndex) {
    if (target.kind == NodeKind::RIndex && target.b != 1)
      raise(AlarmNumber::SyntaxError, "R[..] takes one index");
    double n = target.kind == NodeKind::RParam
                   ? target.number
                   : lang::roundToInt(eval_.number(block_, block_.arg(target, 0)));
    vars_.r(n);  // range check before the type check
    if (!v.isNumeric())
      raise(AlarmNumber::TypeMismatch,
            fmt::format("operation not compatible with data type: R{} takes a number, not {}", n,
                        lang::typeName(v.type)));
    vars_.setR(n, v.num);
    return;
  }
  std::vector<Value> idx;
  bool indexed = target.kind == NodeKind::Index;
  if (indexed) eval_.evalArgs(block_, target, idx);
  if (UserVariable* var = vars_.find(target.text)) {
    size_t at = 0;
    if (var->isArray()) {
      if (!indexed)
        raise(AlarmNumber::TypeMismatch, fmt::format("array {} used without index", target.text));
      at = VariableStore::elementIndex(*var, idx, target.text);
    } else if (indexed) {
      if (writeStringChar(*var, idx, target.text, v)) return;  // STRG[i]=c (string_chars.cpp)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} is not an array", target.text));
    }
    Value x = convertForStore(v, var->type, var->string_length, target.text);
    VariableStore::checkLimits(*var, x, target.text);
    var->data[at] = std::move(x);
    return;
  }
  writeSystem(target.text, idx, indexed, v);
}

// --- --vars ---------------------------------------------------------------------------------

void Interpreter::writeVariablesJson(std::ostream& out) const {
  out::VariablesReport report;
  for (size_t i = 0; i < vars_.rCount(); ++i)
    if (vars_.rWritten(i)) report.r.emplace_back(i, vars_.rValue(i));
  // The active tool as the $P_TOOL.. system variables show it (docs/tool-offsets.md).
  const EffectiveLengths l = tools_.lengths();
  report.tool = {tools_.activeTool(),
                 tools_.activeEdge(),
                 {l.total[0], l.total[1], l.total[2]},
                 l.radius,
                 tools_.orientation(modal_.plane),
                 tools_.lengthVector(modal_.plane)};
  for (size_t k = 0; k < 26; ++k) {
    Value v;
    const Value index = Value::integer(static_cast<double>(k + 1));
    tools_.read("$P_AD", std::span<const Value>(&index, 1), true, modal_.plane, v);
    report.tool.active_offset[k] = v.num;
  }
  report.tool.environments = static_cast<int>(tools_.environments().size());
  report.offsets = offsetReadout();
  report.approach = motion_.approachPoints();
  for (const auto& [k, v] : vars_.globals()) report.variables[k] = &v;
  for (const auto& [k, v] : vars_.mainVariables()) report.variables[k] = &v;
  out::writeVariablesJson(out, report);
}

}  // namespace ncoffset::interp
