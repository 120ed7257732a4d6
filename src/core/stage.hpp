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
  // A compensated element: the geometry `g` with everything else (line, feed, frame, tool) from
  // `like`. By default a copy of `like` with `g` goes to motion().
  virtual void element(const MotionBlock& like, const Geometry& g);
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

inline void Stage::element(const MotionBlock& like, const Geometry& g) {
  motion(withGeometry(like, g));
}

}  // namespace ncoffset::core
