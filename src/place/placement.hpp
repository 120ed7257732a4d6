// Placement stage: a motion in the workpiece coordinate system (WCS) with the frame valid for
// its block becomes an output Segment in MCS (frames applied; MCS = BCS without kinematic
// transformation) or stays in WCS (`--coords wcs`).
#pragma once

#include <functional>
#include <string>

#include "ncoffset/channel.hpp"
#include "ncoffset/frame.hpp"
#include "ncoffset/path.hpp"
#include "ncoffset/trc.hpp"

namespace ncoffset::place {

// One motion as the interpreter computed it.
struct MotionBlock {
  Motion motion = Motion::G1;
  Vec3 start;         // WCS
  Vec3 end;           // WCS
  Vec3 centre;        // WCS, arcs
  int applicate = 2;  // arcs: index of the axis perpendicular to the plane (G17: Z)
  Plane plane = Plane::G17;
  TrcSettings trc;  // radius compensation of this block
  int turns = 0;
  Affine frame;  // WCS -> BCS for this block (identity with G53/G153/SUPA and programmed MCS)
  // Blocks with the same serial have the same frame (the interpreter counts its frame changes;
  // 0: frames suppressed): saves comparing frames where they are the same, as they usually are.
  unsigned long long frame_serial = 0;
  bool frame_identity = false;  // `frame` is exactly the identity (set with it; false: apply it)
  Vec3 tool_offset;             // BCS vector from tool tip to carrier reference point
  double feed = 0;
  bool has_feed = false;
  int line = 0;
  int file = 0;
  // Smooth approach / retraction of the block, null for every other block (a pointer: blocks
  // are copied along the pipeline, the request is needed by one stage only).
  const SarRequest* sar = nullptr;
};

class Placement {
 public:
  Placement(PathSink& sink, CoordSystem coords) : sink_(sink), coords_(coords) {}
  // At the start of each run (the sink behind a run may change): how to name files in
  // warnings, and whether the sink draws the programmed path.
  void beginRun(std::function<const std::string&(int)> file_name) {
    file_name_ = std::move(file_name);
    wants_programmed_ = sink_.wantsProgrammed();
  }
  // A motion of the (compensated) path.
  void motion(const MotionBlock& m);
  // The geometry of a motion, with everything else (line, feed, frame, tool) from `like`:
  // saves copying a whole block for every compensated element.
  struct Geometry {
    Motion motion;
    Vec3 start, end, centre;
    int applicate;
    int turns;
  };
  void motion(const MotionBlock& like, const Geometry& g);
  // The programmed motion of a block, for sinks that draw the contour (PathSink::programmed).
  void programmed(const MotionBlock& m) {
    if (wants_programmed_) programmedSegment(m);
  }
  // A warning of the compensation stage (not interrupting).
  void warning(const MotionBlock& m, int number, const std::string& text);

 private:
  void programmedSegment(const MotionBlock& m);
  Segment toSegment(const MotionBlock& m) const;
  Segment toSegment(const MotionBlock& m, const Geometry& g) const;

  PathSink& sink_;
  CoordSystem coords_;
  bool wants_programmed_ = false;
  std::function<const std::string&(int)> file_name_;
};

}  // namespace ncoffset::place
