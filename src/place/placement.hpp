// Placement stage, the last of the chain: a motion in the workpiece coordinate system (WCS) with
// the frame valid for its block becomes an output Segment in MCS (frames applied; MCS = BCS
// without kinematic transformation) or stays in WCS (`--coords wcs`).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/row_sink.hpp"
#include "core/stage.hpp"
#include "ncoffset/channel.hpp"
#include "ncoffset/path.hpp"

namespace ncoffset::place {

class Placement final : public core::Stage {
 public:
  // `start`: where the tool carrier stands in the MCS before the first segment (the channel's
  // start position, RunOptions::start); without one the first segment keeps the start its block
  // gives (tests of single blocks).
  Placement(PathSink& sink, CoordSystem coords, std::optional<Vec3> start = std::nullopt)
      : sink_(sink), coords_(coords) {
    if (start) path_.at = programmed_.at = *start;
    path_.placed = programmed_.placed = start.has_value();
  }
  // Not copied: target_ may point at own_sink_.
  Placement(const Placement&) = delete;
  Placement& operator=(const Placement&) = delete;
  // At the start of each run (the sink behind a run may change): how to name files in
  // warnings, and whether the sink draws the programmed path.
  void beginRun(std::function<const std::string&(int)> file_name) {
    file_name_ = std::move(file_name);
    wants_programmed_ = sink_.wantsProgrammed();
    // The row hand-over (core/row_sink.hpp): the run's target, if it is a RowSink, in MCS (the
    // rows' only case: toRows implies it, no test of coords_ on their way).
    row_ = coords_ == CoordSystem::MCS ? dynamic_cast<core::RowSink*>(*target_) : nullptr;
    row_target_ = row_ ? *target_ : nullptr;
  }
  // A motion of the (compensated) path.
  core::Feedback motion(const core::MotionBlock& m) override;
  void element(const core::MotionBlock& like, const geom::Element& e, std::uint8_t tip_at) override;
  // The programmed motion of a block, for sinks that draw the contour (PathSink::programmed).
  void programmed(const core::MotionBlock& m) override {
    if (wants_programmed_) programmedSegment(m);
  }
  void warning(const core::MotionBlock& m, int number, const std::string& text) override;
  // The channel's sink switch (interp/channel_impl.hpp) passes a segment on to its target when
  // it holds no event back: while *waiting is false, segments go to *target directly, one
  // virtual call instead of two (docs/performance.md §32); else through the sink as before.
  void bypass(PathSink* const* target, const bool* waiting) {
    target_ = target;
    waiting_ = waiting;
  }
  // Whether the sink draws the programmed path (read at beginRun).
  bool wantsProgrammed() const { return wants_programmed_; }
  // The interpreter's motion number (MotionBlock::seq) of the segment being written.
  long long seq() const { return seq_; }

 private:
  // Where a layer of the path stands: the last segment's end (output coordinates) and the frame
  // and tool offset it was placed with.
  struct Joint {
    bool placed = false;  // a segment was written (or the start position is known)
    Vec3 at;
    Vec3 offset;
    core::BlockFrame frame;
  };
  // A segment placed with another frame or tool offset than the one before starts where that one
  // ended: the carrier does not jump at a tool or frame change (docs/tool-offsets.md section 5).
  void join(Segment& s, const core::MotionBlock& m, Joint& j) const {
    if (!joined(m, j)) [[unlikely]]
      rejoin(s, m, j);
    j.at = s.end;
  }
  // Whether `m` has the frame and tool offset the segment before was placed with (no rejoin).
  static bool joined(const core::MotionBlock& m, const Joint& j) {
    return m.frame.state() == j.frame.state() && m.tool_offset.x == j.offset.x &&
           m.tool_offset.y == j.offset.y && m.tool_offset.z == j.offset.z;
  }
  void rejoin(Segment& s, const core::MotionBlock& m, Joint& j) const;
  void programmedSegment(const core::MotionBlock& m);
  // The segment of geometry `g` (a core::Geometry, or the block `m` itself) in block `m`.
  template <typename G>
  Segment toSegment(const core::MotionBlock& m, const G& g) const;
  // element()'s usual case (G17, MCS, no frame, no turning tool's P - S): the segment straight
  // from the element, without its geometry as a block (docs/performance.md §37).
  Segment planeSegment(const core::MotionBlock& like, const geom::Element& e) const;
  // The same as a row (toRows).
  void rowElement(const core::MotionBlock& like, const geom::Element& e);
  // element()'s usual case: G17 in MCS, no frame, no turning tool's P - S.
  bool usualElement(const core::MotionBlock& like, std::uint8_t tip_at) const {
    return like.plane == Plane::G17 && coords_ == CoordSystem::MCS && like.frame.isIdentity() &&
           tip_at == core::kTipNone;
  }
  // element() for a segment (not a row: toRows), out of line (element's row stays short).
  [[gnu::noinline]] void segmentElement(const core::MotionBlock& like, const geom::Element& e,
                                        std::uint8_t tip_at);
  // segmentElement's other cases (out of line: the usual one stays short).
  [[gnu::noinline]] void generalElement(const core::MotionBlock& like, const geom::Element& e,
                                        std::uint8_t tip_at);
  // motion()'s usual case (MCS, no frame, no P - S): the segment straight from the block.
  Segment blockSegment(const core::MotionBlock& m) const;
  // motion()'s usual case: MCS, no frame, no P - S.
  bool usualMotion(const core::MotionBlock& m) const {
    return coords_ == CoordSystem::MCS && m.frame.isIdentity() && m.tip_at == core::kTipNone;
  }
  // motion()'s other cases (out of line).
  [[gnu::noinline]] void generalMotion(const core::MotionBlock& m, bool check);
  // The segment's way out: joined to the path, range checked (`check`), to the sink.
  void place(Segment& s, const core::MotionBlock& m, bool check);
  // toSegment's points, normal and sense under a frame (MCS coordinates; out of line: rare).
  void framedPoints(const core::MotionBlock& m, const core::Geometry& g, Vec3& start, Vec3& end,
                    Vec3& centre, Vec3& normal, Motion& motion) const;
  // P - S at the points of `s` (of a motion `motion`) on the path of S (core::TipAt `tip_at`).
  void addTip(Segment& s, const core::MotionBlock& m, std::uint8_t tip_at, Motion motion) const;

  // Whether the segment of `m` goes to row_ (core/row_sink.hpp): the run's target is a RowSink,
  // the segment goes to it directly (nothing waits in the sink switch) and needs no rejoin
  // (which would change its start, which a row does not have).
  // (Only in MCS: beginRun.)
  bool toRows(const core::MotionBlock& m) const {
    return *target_ == row_target_ && !*waiting_ && joined(m, path_);
  }
  // place() for toRows' segments: the end and centre (arcs; else any value) of a segment of
  // motion `motion` in block `m`, joined, range checked (`check`), as a row to row_.
  void placeRow(const core::MotionBlock& m, Motion motion, const Vec3& end, const Vec3& centre,
                bool check);

  void emit(const Segment& s) {
    if (!*waiting_) [[likely]]
      (*target_)->segment(s);
    else
      sink_.segment(s);
  }

  PathSink& sink_;
  PathSink* own_sink_ = &sink_;  // without a bypass: the sink itself, never waiting
  static constexpr bool kNeverWaiting = false;
  PathSink* const* target_ = &own_sink_;
  const bool* waiting_ = &kNeverWaiting;
  // The row hand-over: the target found at beginRun (nullptr: none) and its RowSink.
  const PathSink* row_target_ = nullptr;
  core::RowSink* row_ = nullptr;
  CoordSystem coords_;
  bool wants_programmed_ = false;
  long long seq_ = 0;
  Joint path_, programmed_;  // the compensated path and the programmed one (drawings)
  std::function<const std::string&(int)> file_name_;
};

}  // namespace ncoffset::place
