// Control statements (PM-JP "Program flow control", "Program jumps"): IF/ELSE/ENDIF, the loops
// WHILE, FOR, REPEAT..UNTIL, LOOP, CASE, and the jumps GOTOF/GOTOB/GOTO/GOTOC. What they mean is
// decided here; ProgramFlow moves the read position.
#include <fmt/format.h>

#include <cctype>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Node;
using lang::NodeKind;
using lang::Stmt;
using lang::StmtKind;
using lang::Value;

void Interpreter::ifStatement(const Stmt& st, size_t index, bool& jumped) {
  const lang::Block& b = block_;
  std::string_view kw = st.name;
  if (kw == "IF") {
    bool cond = lang::toBool(eval_.eval(b, st.expr));
    if (index + 1 < b.stmts.size() && b.stmts[index + 1].jump != lang::JumpKind::None) {
      // IF <condition> GOTOx <target>: a conditional jump.
      if (cond) {
        jump(b.stmts[index + 1], b.stmts[index + 1].jump == lang::JumpKind::Gotoc);
        jumped = true;
      } else {
        jumped = true;  // the rest of the block is the jump: nothing else to do
        finishBlock();
      }
      return;
    }
    if (index != 0) raise(AlarmNumber::ControlNesting, "IF must stand at the start of its block");
    const auto& l = link();
    if (!cond) {
      flow_.continueAfter(l.partner);  // after ELSE, or after ENDIF
      jumped = true;
    }
    return;
  }
  if (kw == "ELSE") {
    flow_.continueAfter(link().partner);  // the true branch ran: skip to after ENDIF
    jumped = true;
    return;
  }
}

// The loop statements; false for any other keyword.
bool Interpreter::loopStatement(const Stmt& st, bool& jumped) {
  const lang::Block& b = block_;
  ProgramLevel& lvl = flow_.level();
  std::string_view kw = st.name;
  if (kw == "REPEATB" || (kw == "REPEAT" && st.target >= 0)) {
    repeatSection(st, jumped);
    return true;
  }
  if (kw == "ENDIF" || kw == "REPEAT" || kw == "LOOP") {
    link();
    return true;
  }
  if (kw == "WHILE") {
    const auto& l = link();
    if (!lang::toBool(eval_.eval(b, st.expr))) {
      flow_.continueAfter(l.partner);
      jumped = true;
    }
    return true;
  }
  if (kw == "ENDWHILE") {
    lvl.pos = link().partner;  // back to the WHILE: its condition is evaluated again
    jumped = true;
    backEdge(line_pos_.offset);
    return true;
  }
  if (kw == "FOR") {
    const auto& l = link();
    const Node& target = b.node(st.target);
    Value counter;
    if (for_continue_ == line_pos_.offset) {
      for_continue_ = static_cast<size_t>(-1);
      Value now = target.kind == NodeKind::RParam ? readR(target.number) : eval_.eval(b, st.target);
      counter = Value::real(lang::toNumber(now) + 1);
    } else {
      counter = eval_.eval(b, st.expr);
    }
    store(target, counter);
    double end = lang::toNumber(eval_.eval(b, st.expr2), "FOR end value");
    Value now = target.kind == NodeKind::RParam ? readR(target.number) : eval_.eval(b, st.target);
    if (lang::toNumber(now) > end && !lang::realEqual(lang::toNumber(now), end)) {
      flow_.continueAfter(l.partner);
      jumped = true;
    }
    return true;
  }
  if (kw == "ENDFOR") {
    const auto& l = link();
    for_continue_ = l.partner.offset;
    lvl.pos = l.partner;
    jumped = true;
    return true;
  }
  if (kw == "UNTIL") {
    const auto& l = link();
    if (!lang::toBool(eval_.eval(b, st.expr))) {
      flow_.continueAfter(l.partner);
      jumped = true;
      backEdge(line_pos_.offset);
    }
    return true;
  }
  if (kw == "ENDLOOP") {
    flow_.continueAfter(link().partner);
    jumped = true;
    backEdge(line_pos_.offset);
    return true;
  }
  return false;
}

void Interpreter::caseStatement(const Stmt& st, size_t index, bool& jumped) {
  const lang::Block& b = block_;
  Value sel = eval_.eval(b, st.expr);
  for (size_t k = index + 1; k < b.stmts.size(); ++k) {
    const Stmt& arm = b.stmts[k];
    if (arm.kind != StmtKind::CaseArm) break;
    bool hit = arm.expr < 0;
    loop_.decides(b, arm.expr);
    if (!hit) {
      Value v = eval_.eval(b, arm.expr);
      hit = (v.isText() || sel.isText()) ? lang::toText(v) == lang::toText(sel)
                                         : lang::realEqual(lang::toNumber(v), lang::toNumber(sel));
    }
    if (hit) {
      jump(arm, arm.jump == lang::JumpKind::Gotoc);
      jumped = true;
      return;
    }
  }
  return;  // no arm and no DEFAULT: continue with the next block
}

void Interpreter::jump(const Stmt& st, bool quiet) {
  // A jump ends the block: its other words are executed first.
  finishBlock();
  if (ended_) return;
  jumpTo(st.jump, st.target, quiet);
}

void Interpreter::jumpTo(lang::JumpKind kind, int target_node, bool quiet) {
  const Node& target = block_.node(target_node);
  const size_t here = line_pos_.offset;
  JumpSearch search;
  using lang::JumpKind;
  search.forward = kind != JumpKind::Gotob;
  search.backward = kind != JumpKind::Gotof;
  search.here_too = kind != JumpKind::Gotof && kind != JumpKind::Gotob;
  std::string label;
  long long block_no = -1;
  if (target.kind == NodeKind::BlockNo) {
    block_no = static_cast<long long>(target.number);
  } else if (target.kind != NodeKind::Name || vars_.find(target.text)) {
    // A STRING variable may hold a block number ("N200" or ":200") instead of a label.
    Value v = eval_.eval(block_, target_node);
    if (v.isText() && v.str.size() > 1 && (v.str[0] == 'N' || v.str[0] == 'n' || v.str[0] == ':') &&
        v.str.find_first_not_of("0123456789", 1) == std::string::npos && v.str.size() < 19)
      block_no = std::stoll(v.str.substr(1));
  }
  if (block_no >= 0) {
    if (flow_.jumpToBlockNumber(block_no, here, search)) return backEdge(here);
    label = fmt::format("N{}", block_no);
  } else {
    if (target.kind == NodeKind::Name) {
      // A label, or a STRING variable holding one.
      UserVariable* v = vars_.find(target.text);
      label = v && !v->isArray() && v->type == lang::VarType::String ? v->data[0].str
                                                                     : std::string(target.text);
    } else {
      label = lang::toText(eval_.eval(block_, target_node));
    }
    for (auto& c : label) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (flow_.jumpToLabel(label, here, search)) return backEdge(here);
  }
  if (quiet) return;  // GOTOC: continue with the next block
  raise(AlarmNumber::JumpNotFound, fmt::format("jump destination {} not found ({} search)", label,
                                               kind == JumpKind::Gotof   ? "forward"
                                               : kind == JumpKind::Gotob ? "backward"
                                                                         : "forward and backward"));
}

}  // namespace ncoffset::interp
