// Tool radius compensation 2D (W1 2.4, spec §5, details Q1-Q9): a streaming stage between the
// interpreter and the placement. It keeps one compensated element back until the next one is
// known, resolves the corner between them and passes the result on.
//
// Modelled: G41/G42 in G17/G18/G19 for lines, arcs and helices (the applicate passes through);
// NORM approach and retraction, and KONT where it equals NORM (start/end point not behind the
// contour); outside corners with G450 (transition circle about the corner point, belonging to
// the next block) and G451 (intersection; circle at or beyond MD20210), flat corners below
// MD20230 by intersection; inside corners by the intersection with the neighbouring block;
// blocks without plane motion between two elements (up to MD20250, else alarm 10762).
// Everything else raises an alarm naming it (99010 where the control has a behaviour that
// ncoffset does not reproduce yet), never a silently different path.
#pragma once

#include <optional>
#include <vector>

#include "geom/contour.hpp"
#include "place/placement.hpp"

namespace ncoffset::trc {

class RadiusCompensation {
 public:
  explicit RadiusCompensation(place::Placement& out) : out_(out) {}
  // Every motion block, in program order.
  void motion(const place::MotionBlock& m);
  // A block without any motion while compensation is active (counts against MD20250).
  void blockWithoutMotion();
  // End of program: the last element ends on its normal at the end point.
  void finish();
  bool active() const { return state_ != State::Off; }

 private:
  enum class State { Off, Selecting, On };

  // One contour element with the block it came from (for line, feed, frame, applicate).
  struct Piece {
    place::MotionBlock block;
    geom::Element programmed;
    geom::Element compensated;
    double r0 = 0, r1 = 0;  // compensation value at the start and the end (a D change in a
                            // line spreads the change over the block, details Q8)
  };

  geom::Element toElement(const place::MotionBlock& m) const;
  place::MotionBlock toBlock(const place::MotionBlock& like, const geom::Element& e) const;
  void emit(const place::MotionBlock& m) { out_.motion(m); }
  void emitPiece(const Piece& p);
  void emitWaiting(geom::Vec2 at);
  Piece compensate(const place::MotionBlock& m, double r0, double r1) const;
  Piece compensate(const place::MotionBlock& m) const {
    double r = std::fabs(settings_.radius);
    return compensate(m, r, r);
  }
  // The equidistant at the constant value the corner calculation uses (details Q8: the end
  // value of the first element, the start value of the second).
  geom::Element cornerEquidistant(const Piece& p, bool at_end) const;
  // A new compensation value in a line spreads over that block (details Q8).
  Piece compensateWithChange(const place::MotionBlock& m);
  void corner(Piece& next);
  // Ends `cur` and starts `next` at x, passes `cur` and the waiting blocks on; `next` waits.
  void joinAt(Piece& cur, Piece& next, geom::Vec2 x);
  void kontApproach(Piece& first);
  void kontRetraction(const place::MotionBlock& m);
  void checkSameSettings(const place::MotionBlock& m) const;
  bool planeMotion(const place::MotionBlock& m) const;
  double side() const;  // +1: compensated to the left of travel, -1: right

  place::Placement& out_;
  State state_ = State::Off;
  place::MotionBlock selection_;      // the G41/G42 block waiting for the first element
  std::optional<Piece> pending_;      // the last compensated element, end not final yet
  std::vector<place::MotionBlock> waiting_;  // blocks without plane motion after pending_
  int dummy_blocks_ = 0;
  TrcSettings settings_;              // of the selection
};

}  // namespace ncoffset::trc
