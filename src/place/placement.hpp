// Placement stage, the last of the chain: a motion in the workpiece coordinate system (WCS) with
// the frame valid for its block becomes an output Segment in MCS (frames applied; MCS = BCS
// without kinematic transformation) or stays in WCS (`--coords wcs`).
#pragma once

#include <functional>
#include <string>

#include "core/stage.hpp"
#include "ncoffset/channel.hpp"
#include "ncoffset/path.hpp"

namespace ncoffset::place {

class Placement final : public core::Stage {
 public:
  Placement(PathSink& sink, CoordSystem coords) : sink_(sink), coords_(coords) {}
  // At the start of each run (the sink behind a run may change): how to name files in
  // warnings, and whether the sink draws the programmed path.
  void beginRun(std::function<const std::string&(int)> file_name) {
    file_name_ = std::move(file_name);
    wants_programmed_ = sink_.wantsProgrammed();
  }
  // A motion of the (compensated) path.
  core::Feedback motion(const core::MotionBlock& m) override;
  void element(const core::MotionBlock& like, const core::Geometry& g) override;
  // The programmed motion of a block, for sinks that draw the contour (PathSink::programmed).
  void programmed(const core::MotionBlock& m) override {
    if (wants_programmed_) programmedSegment(m);
  }
  void warning(const core::MotionBlock& m, int number, const std::string& text) override;
  // The interpreter's motion number (MotionBlock::seq) of the segment being written.
  long long seq() const { return seq_; }

 private:
  void programmedSegment(const core::MotionBlock& m);
  Segment toSegment(const core::MotionBlock& m, const core::Geometry& g) const;
  // P - S at the points of `g` on the path of S (core::TipAt).
  void addTip(Segment& s, const core::MotionBlock& m, const core::Geometry& g) const;

  PathSink& sink_;
  CoordSystem coords_;
  bool wants_programmed_ = false;
  long long seq_ = 0;
  std::function<const std::string&(int)> file_name_;
};

}  // namespace ncoffset::place
