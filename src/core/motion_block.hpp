// The block every stage passes on: one motion as the interpreter computed it, with the
// compensation settings, the frame and the tool length vector valid for it (docs/architecture.md).
// Blocks are values: a stage that keeps one keeps a copy; nothing in a block points into
// another stage.
#pragma once

#include <cstdint>

#include "core/block_frame.hpp"
#include "core/compensation.hpp"
#include "ncoffset/geometry.hpp"
#include "ncoffset/path.hpp"

namespace ncoffset::core {

// Which points of a motion radius compensation put on the path of the cutting edge centre S of
// a turning tool, where the placement adds the vector P - S (docs/cutting-edge-positions.md):
// none for a block without compensation, both for the compensated contour, the start only for
// the retraction line, the end only for the approach line.
enum TipAt : std::uint8_t { kTipNone = 0, kTipStart = 1, kTipEnd = 2, kTipBoth = 3 };

struct MotionBlock {
  Motion motion = Motion::G1;
  // (The two flags fill the padding after `motion`.)
  bool has_tip = false;            // the active edge has P != S (turning tool SL 1..8)
  std::uint8_t tip_at = kTipNone;  // set by radius compensation only
  Vec3 start;                      // WCS
  Vec3 end;                        // WCS
  Vec3 centre;                     // WCS, arcs
  int applicate = 2;               // arcs: index of the axis perpendicular to the plane (G17: Z)
  Plane plane = Plane::G17;
  TrcSettings trc;  // radius compensation of this block
  int turns = 0;
  BlockFrame frame;  // WCS -> BCS for this block (none with G53/G153/SUPA and programmed MCS)
  Vec3 tool_offset;  // BCS vector from tool tip to carrier reference point
  Vec3 tip;          // BCS vector P - S of a turning tool (frame mirroring applied)
  double feed = 0;
  FeedUnit feed_unit = FeedUnit::MmPerMin;  // G group 15 of the block
  bool has_feed = false;
  double lead_change = 0;  // G34/G35: F in mm/rev per revolution (feed: the start lead)
  int line = 0;
  int file = 0;
  // The number of the interpreter's motion in the run (1, 2, ...): what the stages make of it
  // keeps it, so the channel orders events against the segments (docs/architecture.md "Events").
  long long seq = 0;
  SarRequest sar;  // smooth approach / retraction of the block (kind None for every other block)
};

// The geometry of a motion without the rest of its block: what radius compensation makes of a
// block (an element, a corner circle) travels as this plus a reference to the block it came from,
// which saves copying a whole block for every compensated element.
struct Geometry {
  Motion motion;
  std::uint8_t tip_at;  // core::TipAt (in the padding after `motion`)
  Vec3 start, end, centre;
  int applicate;
  int turns;
};

inline Geometry geometryOf(const MotionBlock& m) {
  return {m.motion, m.tip_at, m.start, m.end, m.centre, m.applicate, m.turns};
}

// A copy of `like` with the geometry `g`.
inline MotionBlock withGeometry(const MotionBlock& like, const Geometry& g) {
  MotionBlock b = like;
  b.motion = g.motion;
  b.start = g.start;
  b.end = g.end;
  b.centre = g.centre;
  b.applicate = g.applicate;
  b.turns = g.turns;
  b.tip_at = g.tip_at;
  return b;
}

}  // namespace ncoffset::core
