// Events for machine simulations (PathSink::tool, mFunction, dwell, spindle, feed): what a block
// switches besides its motion. Called only when the sink wants events, so a block without these
// words costs one flag test. The channel orders each event against the segments (it arrives
// before the segments of its block's motion, M0/M1 after them).
#include <cmath>

#include "interp/interpreter.hpp"

namespace ncoffset::interp {

void Interpreter::mFunctionEvent(double m, int ext) {
  const int number = static_cast<int>(std::fmin(m, 2e9));
  const bool master = ext <= 1;
  // The tool change M code (M6) is a tool event; M2, M17, M30 end the (sub)program: the run's
  // end is PathSink::finish, not an event.
  if (master && m == data_.get(md_change_m_)) return;
  if (ext <= 0 && (number == 2 || number == 17 || number == 30)) return;
  if (ext <= 0 && (number == 0 || number == 1)) {
    stop_after_ = true;  // a programmed stop acts at the end of the block (PM-F "M0, M1")
    stop_m_ = number;
    return;
  }
  sink_.mFunction({line_, file_, number, ext > 0 ? ext : 0});
}

void Interpreter::spindleEvent(double s, int ext) {
  // In a G4 block S is the dwell in revolutions; which one it is is known once the block's words
  // are collected (blockEvents).
  dwell_s_ = s;
  dwell_s_ext_ = ext > 0 ? ext : 0;
  has_s_ = true;
}

void Interpreter::toolEvent() {
  ToolEvent e;
  e.line = line_;
  e.file = file_;
  e.edge = tools_.hasEdge() ? tools_.activeEdge() : 0;
  e.radius = tools_.lengths().radius;  // the whole radius, also with CUT2DD
  e.length = tools_.lengthVector(modal_.plane);
  if (words_.tool) {
    e.word = ToolEvent::Word::T;
    e.tool = *words_.tool;
    e.changed = tools_.activeTool() == *words_.tool;
    sink_.tool(e);
  }
  e.tool = tools_.activeTool();
  e.changed = words_.tool_change;
  if (words_.tool_change) {
    e.word = ToolEvent::Word::M6;
    sink_.tool(e);
  }
  if (words_.edge) {
    e.word = ToolEvent::Word::D;
    sink_.tool(e);
  }
}

void Interpreter::blockEvents(double feed_before) {
  if (words_.dwell) {
    DwellEvent d{line_, file_, 0, 0};
    if (words_.f) d.seconds = *words_.f;
    if (has_s_) d.revolutions = dwell_s_;
    if (words_.f || has_s_) sink_.dwell(d);
  } else if (has_s_) {
    sink_.spindle({line_, file_, dwell_s_, dwell_s_ext_});
  }
  has_s_ = false;
  if (modal_.feed != feed_before) sink_.feed({line_, file_, modal_.feed});
  // A frame change: one integer comparison per block; a frame programmed again with the same
  // values (the same map) is no change.
  const core::BlockFrame& frame = frames_.blockFrame();
  if (frame.state() != event_frame_.state()) [[unlikely]] {
    if (!frame.sameAs(event_frame_)) sink_.frame({line_, file_, frame.map()});
    event_frame_ = frame;
  }
}

void Interpreter::stopEvent() {
  stop_after_ = false;
  sink_.mFunction({line_, file_, stop_m_, 0});
}

}  // namespace ncoffset::interp
