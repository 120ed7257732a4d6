// Executing a block once its words are collected: frame selection and frame commands
// (G500/G54..G57/G505..G599, TRANS/ROT/SCALE/MIRROR and their A forms, G58/G59), tool words,
// feed, the motion, program end and subprogram call (PM-NC "Fundamentals").
#include <fmt/format.h>

#include <cmath>

#include "core/not_modelled.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::AxisMode;
using lang::Stmt;
using lang::Value;

double Interpreter::toMm(double v) const {
  return interp::toMm(modal_, v);
}

// The block's frame words: G54.., TRANS/ROT/.. and G58/G59, G25/G26. True when they took the
// block's axis values (they are no motion target then).
bool Interpreter::blockFrames() {
  bool frames_changed = false;
  if (words_.frame_select) {
    int n = modal_.frame_select == 500  ? 0
            : modal_.frame_select < 100 ? modal_.frame_select - 53
                                        : modal_.frame_select - 500;
    frames_.select(static_cast<size_t>(n));
    frames_changed = true;
  }
  bool axes_consumed = false;
  if (!words_.frame_command.empty()) {
    doFrameCommand();
    axes_.frameCommand(words_.frame_command,
                       modal_.units == Units::G70 || modal_.units == Units::G700);
    frames_changed = true;
    axes_consumed = true;
  } else if (words_.axial_offset == 58 || words_.axial_offset == 59) {
    // G58 replaces the coarse, G59 the fine translation of the programmable frame, per axis.
    for (int i = 0; i < 3; ++i) {
      if (!words_.axis[i]) continue;
      (words_.axial_offset == 58 ? frames_.programmable().coarse : frames_.programmable().fine)[i] =
          toMm(words_.axis_value[i]);
    }
    frames_changed = true;
    axes_consumed = true;
  } else if (words_.axial_offset == 25 || words_.axial_offset == 26) {
    axes_consumed = true;  // G25/G26 axis values are working-area limits, not targets
  }
  if (frames_changed) frames_.update();
  return axes_consumed;
}

void Interpreter::finishBlock() {
  // An alarm of the block as a whole points at its first word.
  column_ = block_.stmts.empty() ? 0 : block_.stmts.front().column;
  // Both steps only for blocks with their words (tested here: no call for the usual block).
  const bool axes_consumed =
      (words_.frame_select || !words_.frame_command.empty() || words_.axial_offset != 0) &&
      blockFrames();
  if (words_.tool || words_.edge || words_.tool_change || words_.sum_offset) executeToolWords();
  if (carrier_.pending) executeCarrierWords();  // TCARR, TCOFR, PAROT, TOROT ... (rare)
  if (words_.rpl && words_.frame_command.empty())
    raise(AlarmNumber::SyntaxError, "RPL= only with ROT or AROT");

  feed_before_ = modal_.feed;
  if (words_.f && !words_.dwell)
    modal_.feed = modal_.units == Units::G700 ? *words_.f * 25.4 : *words_.f;
  if (events_) blockEvents(feed_before_);
  bool any_axis = words_.axis[0] || words_.axis[1] || words_.axis[2];
  bool circle_words = words_.centre[0] || words_.centre[1] || words_.centre[2] || words_.cr ||
                      words_.ar || words_.turn;
  bool is_arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  if (circle_words && !is_arc) [[unlikely]]
    threadLeadWords();  // I, J, K of a thread (threads.cpp); else the circle alarm
  // A circle may consist of its centre alone (full circle) or of AR= with the centre.
  bool moved = false;
  const bool geometry = any_axis || (is_arc && circle_words) || words_.sar != core::SarKind::None;
  bool builds = !axes_consumed && geometry;
  // Contour definitions, CIP/CT, polar coordinates (contour_definition.cpp): only blocks with
  // such words, or while RNDM/CIP/CT/an ANG block is active.
  if ((words_.contour | contour_active_) && contourBlock(axes_consumed, builds, moved)) {
    if (words_.extra_axes) [[unlikely]]
      core::notModelled("an additional axis (A, B, C, ...) in a block with a contour definition",
                        "chamfers, roundings, ANG=, CIP, CT and polar points are built for the "
                        "geometry axes only");
  } else if (words_.extra_axes) [[unlikely]] {  // A, B, C, ...: axis_words.cpp
    moved = axesBlock(axes_consumed, geometry);
  } else if (builds) {
    moved = motion_.buildBlock(words_, modal_, {line_, file_, feed_before_, motion_before_});
  }
  if (moved) without_motion_ = 0;
  if (events_ && stop_after_) stopEvent();
  // A block that reaches the main run without moving (M, S, F, zero-length, ...) between two
  // compensated elements counts against MD20250.
  if (!moved && !block_.stmts.empty() && block_.stmts.front().kind == lang::StmtKind::Word)
    motion_.output().blockWithoutMotion();

  if (words_.end_program || words_.end_subprogram) {
    endWord(words_.end_program);  // section_repeat.cpp
    if (!words_.call.empty())
      raise(AlarmNumber::SyntaxError, "program call and program end in one block");
    motion_before_ = modal_.motion;
    return;
  }
  motion_before_ = modal_.motion;
  if (!words_.call.empty()) {
    callSubprogram(words_.call, words_.repeat.value_or(1));
  } else if (words_.repeat) {
    raise(AlarmNumber::SyntaxError, "pass count P without a subprogram call");
  } else if (mcall_.active) {
    modalCallAfter();
  }
}

void Interpreter::doFrameCommand() {
  Frame& pf = frames_.programmable();
  const std::string_view cmd = words_.frame_command;
  bool any = words_.axis[0] || words_.axis[1] || words_.axis[2] || words_.rpl;
  Vec3 v;
  for (int i = 0; i < 3; ++i)
    if (words_.axis[i]) v[i] = words_.axis_value[i];
  if (words_.rpl && cmd != "ROT" && cmd != "AROT")
    raise(AlarmNumber::SyntaxError, "RPL= only with ROT or AROT");
  if (cmd == "TRANS" || cmd == "ATRANS") {
    Vec3 t{toMm(v.x), toMm(v.y), toMm(v.z)};
    if (cmd == "TRANS") {
      pf = Frame();
      pf.coarse = t;
    } else {
      pf.addTranslation(t);
    }
    return;
  }
  if (cmd == "ROT" || cmd == "AROT") {
    for (double a : {v.x, v.y, v.z, words_.rpl.value_or(0.0)})
      if (!(std::fabs(a) <= 1e6))
        raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: rotation angle {}", a));
    Mat3 r;
    if (words_.rpl) {
      if (words_.axis[0] || words_.axis[1] || words_.axis[2])
        raise(AlarmNumber::SyntaxError, "ROT RPL= cannot be combined with axis angles");
      r = rotationAbout(planeAxes(modal_.plane).applicate, *words_.rpl);
    } else {
      r = rpyMatrix(v);
    }
    if (cmd == "ROT") {
      pf = Frame();
      if (any) pf.rotation = rpyAngles(r);
    } else {
      pf.addRotation(r);
    }
    return;
  }
  if (cmd == "SCALE" || cmd == "ASCALE") {
    Vec3 s{1, 1, 1};
    for (int i = 0; i < 3; ++i) {
      if (!words_.axis[i]) continue;
      if (std::fabs(v[i]) < 1e-12 || !(std::fabs(v[i]) <= 1e6))
        raise(AlarmNumber::ValueRange,
              fmt::format("value range exceeded: scale factor {} of {}", v[i], "XYZ"[i]));
      s[i] = v[i];
    }
    if (cmd == "SCALE") {
      pf = Frame();
      pf.scale = s;
    } else {
      pf.addScale(s);
    }
    return;
  }
  // MIRROR / AMIRROR: the value is arbitrary (write 0); MD10610 = 0: about the programmed axis.
  if (cmd == "MIRROR") pf = Frame();
  for (int i = 0; i < 3; ++i)
    if (words_.axis[i]) pf.addMirror(i);
}

}  // namespace ncoffset::interp
