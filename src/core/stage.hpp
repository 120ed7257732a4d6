// The interface between the stages of the channel (docs/architecture.md): the interpreter hands
// motion blocks to smooth approach, which hands them to radius compensation, which hands them to
// the placement, which writes segments to the PathSink. `Channel` wires the chain; a stage knows
// only the `Stage&` after it. Blocks go one way, block by block; what the control feeds back to
// the interpreter (the end point of a retraction whose end is implicit, $P_APR/$P_AEP/$P_APDV)
// comes back as the value `motion` returns.
#pragma once

#include <optional>
#include <string>

#include "core/motion_block.hpp"
#include "geom/contour.hpp"

namespace ncoffset::core {

// $P_APR, $P_AEP (WCS) and $P_APDV of the last evaluated smooth approach (W1 2.4.4).
struct ApproachPoints {
  Vec3 apr;            // P3: where the approach curve starts (uncompensated)
  Vec3 aep;            // P4: the contour's start point
  bool valid = false;  // $P_APDV: the values belong to the last approach
};

// What a stage feeds back to the interpreter for one block.
struct Feedback {
  // User-provided, so that `return {}` (every stage, every block) only clears the two flags of
  // the optionals: value-initialising the aggregate zeroed all its 96 bytes (16 instructions a
  // return, docs/performance.md §26).
  Feedback() {}  // NOLINT(modernize-use-equals-default)
  // Where the tool is after the block when that differs from the programmed end point (a SAR
  // retraction whose end point is implicit), WCS.
  std::optional<Vec3> end_point;
  // Set when the approach points changed with this block (an approach was evaluated or began).
  std::optional<ApproachPoints> approach;
};

class Stage {
 public:
  virtual ~Stage() = default;
  // A motion block, in program order.
  virtual Feedback motion(const MotionBlock& m) = 0;
  // A compensated element: the plane element `e` (program coordinates, in `like`'s plane) with
  // everything else (the applicate, line, feed, frame, tool) from `like`, and which of its points
  // get a turning tool's P - S (`tip_at`). Radius compensation hands over its window's element
  // itself, no geometry built from it (docs/performance.md §37). By default a copy of `like` with
  // planeGeometry(like, e, tip_at) goes to motion().
  virtual void element(const MotionBlock& like, const geom::Element& e, std::uint8_t tip_at);
  // The programmed (uncompensated) motion of a block, for sinks that draw the contour.
  virtual void programmed(const MotionBlock&) {}
  // A warning that does not stop the run, at the block `at`.
  virtual void warning(const MotionBlock& at, int number, const std::string& text) = 0;
  // A block that reached the main run without any motion (counts against MD20250 / MD20202).
  virtual void blockWithoutMotion() {}
  // A preprocessor stop (STOPRE, or a main-run variable read); `alarm`: SD42480
  // STOP_CUTCOM_STOPRE = 1. Returns where the tool stands after it (WCS) when that is not the
  // programmed end point (active radius compensation ends on the normal, W1 2.4.11).
  virtual std::optional<Vec3> preprocessorStop(bool /*alarm*/) { return std::nullopt; }
  // End of the program: everything held back is written.
  virtual void flush() {}
};

// The geometry of plane element `e` (program coordinates) as a motion of block `like`: lines
// stay G0/G1 (a G2/G3 block whose element became a line is G1), an arc's centre lies at its
// start's applicate.
inline Geometry planeGeometry(const MotionBlock& like, const geom::Element& e,
                              std::uint8_t tip_at) {
  const PlaneAxes pa = planeAxes(like.plane);
  Geometry g{like.motion, tip_at, like.start, like.end, like.centre, like.applicate, like.turns};
  g.start[pa.abscissa] = e.p0.a;
  g.start[pa.ordinate] = e.p0.o;
  g.end[pa.abscissa] = e.p1.a;
  g.end[pa.ordinate] = e.p1.o;
  if (e.arc) {
    g.motion = e.ccw ? Motion::G3 : Motion::G2;
    g.centre[pa.abscissa] = e.c.a;
    g.centre[pa.ordinate] = e.c.o;
    g.centre[pa.applicate] = g.start[pa.applicate];
    g.applicate = pa.applicate;
    g.turns = e.turns;
  } else if (g.motion == Motion::G2 || g.motion == Motion::G3) {
    g.motion = Motion::G1;
  }
  return g;
}

inline void Stage::element(const MotionBlock& like, const geom::Element& e, std::uint8_t tip_at) {
  motion(withGeometry(like, planeGeometry(like, e, tip_at)));
}

}  // namespace ncoffset::core
