// The interpreter's side of the endless-loop proof (loop_watch.hpp, docs/limits.md "Endless
// loops"): which statements may make the next pass of a loop differ, and the jumps back.
#include <fmt/format.h>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

namespace {

// The control statements that only choose which block runs next (PM-JP "Program flow
// control"); what they evaluate is checked separately. FOR and ENDFOR count, REPEAT with a label
// repeats a section as a call does: not among them.
bool choosesOnly(const lang::Stmt& st) {
  if (st.jump != lang::JumpKind::None) return true;
  const std::string_view kw = st.name;
  if (kw == "REPEAT") return st.target < 0;
  return kw == "IF" || kw == "ELSE" || kw == "ENDIF" || kw == "WHILE" || kw == "ENDWHILE" ||
         kw == "LOOP" || kw == "ENDLOOP" || kw == "UNTIL" || kw == "CASE";
}

}  // namespace

void Interpreter::watchKeyword(const lang::Stmt& st) {
  if (!choosesOnly(st)) {
    loop_.dirty();
    return;
  }
  loop_.decides(block_, st.expr);  // the condition or CASE selector
  if (st.jump != lang::JumpKind::None) loop_.decides(block_, st.target);
}

void Interpreter::watchWord(const lang::Stmt& st) {
  // A computed M word can end the program (M=R1 with R1 = 30): it decides the way as a
  // condition does. Other words only move or select.
  if (st.name == "M")
    loop_.decides(block_, st.expr);
  else
    loop_.expression(block_, st.expr);
}

void Interpreter::watchProcCall(const lang::Stmt& st) {
  // MSG only shows a text; every other procedure (SETAL, CHANDATA, a subprogram, ...) may change
  // what a later pass does.
  if (st.name != "MSG" || st.expr < 0) {
    loop_.dirty();
    return;
  }
  const lang::Node& call = block_.node(st.expr);
  for (int k = 0; k < call.b; ++k) loop_.expression(block_, block_.arg(call, k));
}

void Interpreter::backEdge(size_t from) {
  const ProgramLevel& lvl = flow_.level();
  if (lvl.pos.offset > from) return;  // a jump forward
  if (loop_.backEdge(lvl.program, flow_.depth(), from, lvl.pos.offset))
    raise(AlarmNumber::EndlessLoop,
          fmt::format("endless loop: lines {} to {} ran twice and changed no variable that a "
                      "condition or jump reads (nothing called, shifted or read from the "
                      "control), so they repeat for ever and the program never ends",
                      lvl.pos.line, line_));
}

// --max-blocks (docs/limits.md "Endless loops"). The automatic limit grows with the program text
// loaded, which a subprogram call or a fed stream may have enlarged since the budget was set: it
// is computed again here, and only a run beyond it is an alarm.
void Interpreter::blockBudgetReached() {
  const Limits& l = options_.limits;
  if (l.max_blocks > 0)
    raise(AlarmNumber::BlockLimit,
          fmt::format("limit of {} executed blocks reached (endless loop?); raise --max-blocks",
                      l.max_blocks));
  const size_t bytes = flow_.loadedBytes();
  const long long budget = l.max_blocks_auto_base + 2 * static_cast<long long>(bytes);
  if (executed_ - run_start_ <= budget) {
    block_budget_ = run_start_ + budget;
    return;
  }
  raise(AlarmNumber::BlockLimit,
        fmt::format("limit of {} executed blocks reached ({} and 2 per byte of the {} bytes of "
                    "program text loaded; endless loop?); raise --max-blocks",
                    budget, l.max_blocks_auto_base, bytes));
}

}  // namespace ncoffset::interp
