// Placement stage: a motion in the workpiece coordinate system (WCS) with the frame valid for
// its block becomes an output Segment in MCS (frames applied; MCS = BCS without kinematic
// transformation) or stays in WCS (`--coords wcs`).
#pragma once

#include "ncoffset/channel.hpp"
#include "ncoffset/frame.hpp"
#include "ncoffset/path.hpp"
#include "ncoffset/trc.hpp"

namespace ncoffset::place {

// One motion as the interpreter computed it.
struct MotionBlock {
  Motion motion = Motion::G1;
  Vec3 start;    // WCS
  Vec3 end;      // WCS
  Vec3 centre;   // WCS, arcs
  int applicate = 2;  // arcs: index of the axis perpendicular to the plane (G17: Z)
  Plane plane = Plane::G17;
  TrcSettings trc;    // radius compensation of this block
  int turns = 0;
  Affine frame;  // WCS -> BCS for this block (identity with G53/G153/SUPA and programmed MCS)
  Vec3 tool_offset;  // BCS vector from tool tip to carrier reference point
  double feed = 0;
  bool has_feed = false;
  int line = 0;
  int file = 0;
};

class Placement {
 public:
  Placement(PathSink& sink, CoordSystem coords) : sink_(sink), coords_(coords) {}
  void motion(const MotionBlock& m);

 private:
  PathSink& sink_;
  CoordSystem coords_;
};

}  // namespace ncoffset::place
