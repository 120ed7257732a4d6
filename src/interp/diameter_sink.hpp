// The transverse axis as diameter values (--diameter, docs/turning.md): a stage between the
// SwitchSink and the run's sink, put in only with --diameter (the usual run pays nothing).
#pragma once

#include <string>

#include "ncoffset/path.hpp"

namespace ncoffset {

// Positions and centres times 2. Lines stay lines; an arc's drawing would be an ellipse, which
// is why the drawings (SVG, HTML) are never asked for it.
inline Segment asDiameter(Segment s, int axis) {
  s.start[axis] *= 2;
  s.end[axis] *= 2;
  s.centre[axis] *= 2;
  return s;
}

// Doubles the transverse axis of segments and programmed paths; forwards everything else as it
// comes, the events too (they hold no positions: a tool's length vector is an offset of the
// tool, not a position of the axis, and stays as the tool data give it).
class DiameterSink final : public PathSink {
 public:
  PathSink* next = nullptr;
  int axis = 0;
  void segment(const Segment& s) override { next->segment(asDiameter(s, axis)); }
  void message(const SourceLoc& l, const std::string& t) override { next->message(l, t); }
  void warning(const SourceLoc& l, int n, const std::string& t) override { next->warning(l, n, t); }
  void programmed(const Segment& s) override { next->programmed(asDiameter(s, axis)); }
  bool wantsProgrammed() const override { return next && next->wantsProgrammed(); }
  bool wantsEvents() const override { return next && next->wantsEvents(); }
  void tool(const ToolEvent& e) override { next->tool(e); }
  void mFunction(const MFunctionEvent& e) override { next->mFunction(e); }
  void dwell(const DwellEvent& e) override { next->dwell(e); }
  void spindle(const SpindleEvent& e) override { next->spindle(e); }
  void feed(const FeedEvent& e) override { next->feed(e); }
  void frame(const FrameEvent& e) override { next->frame(e); }
  void axisNames(const std::vector<std::string>& n) override { next->axisNames(n); }
  void axes(const AxesEvent& e) override { next->axes(e); }
  void finish(const Alarm* a) override { next->finish(a); }
};

}  // namespace ncoffset
