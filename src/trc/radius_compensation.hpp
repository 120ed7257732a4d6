// Tool radius compensation 2D (W1 2.4, spec §5, details Q1-Q9): a streaming stage between the
// interpreter and the placement.
//
// It keeps a window of compensated elements whose end points may still change: the last
// MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS traversing blocks. Each new element is joined to the
// previous one (inside corner: intersection; outside corner: G450 circle / G451 intersection,
// MD20210/MD20230); when two consecutive equidistants do not meet, or with CDON always, the
// new element is intersected with earlier elements of the window (bottleneck detection, §5.5):
// the elements in between are omitted with warning 10763 and their other actions run at the
// intersection. An element leaves the window (is written) once no later block can reach it;
// a junction still open then is alarm 10751. G461/G462 extend the approach and retraction
// blocks by a circle / straight line for that search (§5.3).
//
// One class, implemented by concern: radius_compensation.cpp (the stage driver: selection,
// dispatch, release, flush, STOPRE), pieces.cpp (elements and equidistants), corners.cpp,
// bottleneck.cpp and approach_retraction.cpp; compensation_internal.hpp holds what they share.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/stage.hpp"
#include "geom/contour.hpp"
#include "geom/plane_metric.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/piece_window.hpp"

namespace ncoffset::trc {

// v's coordinates in the plane of axes `pa`: G17's read straight, the others through Vec3's
// index, whose two tests a read keeps when GCC does not know the index (the same values;
// docs/performance.md §48).
[[gnu::always_inline]] inline geom::Vec2 planePoint(const Vec3& v, PlaneAxes pa) {
  if (pa.abscissa == 0 && pa.ordinate == 1) return {v.x, v.y};
  return {v[pa.abscissa], v[pa.ordinate]};
}

class RadiusCompensation final : public core::Stage {
 public:
  explicit RadiusCompensation(core::Stage& out) : out_(out) {}
  // Every motion block, in program order.
  core::Feedback motion(const core::MotionBlock& m) override;
  void programmed(const core::MotionBlock& m) override { out_.programmed(m); }
  // Whether the stages behind draw the programmed path (PathSink::wantsProgrammed): without such
  // a sink no block passes the virtual programmed() call (docs/performance.md §26).
  void passProgrammed(bool on) { pass_programmed_ = on; }
  void warning(const core::MotionBlock& at, int number, const std::string& text) override {
    out_.warning(at, number, text);
  }
  // A block without any motion while compensation is active (counts against MD20250).
  void blockWithoutMotion() override;
  // End of program: the last element ends on its normal at the end point.
  void flush() override;
  // A preprocessor stop (STOPRE) while active (W1 2.4.11): the last element ends on its normal
  // at its end point, the next block approaches the normal point at its start; with SD42480
  // STOP_CUTCOM_STOPRE = 1 alarm 10778 instead.
  std::optional<Vec3> preprocessorStop(bool alarm) override;
  bool active() const { return state_ != State::Off; }
  // Tests only (tests/trc/compensation_fast_path_test.cpp): true makes every block take the
  // general paths, the twins of the fast ones, so that a test compares the two outputs.
  static void useGeneralPaths(bool on) {
    general_paths_ = on;
    wide_copy_ = !on && wideCopyAvailable();
  }

 private:
  enum class State { Off, Selecting, On };

  // One element of the window: a traversing block, or the approach line of the selection
  // block (index 0).
  struct Piece {
    core::MotionBlock block;
    geom::Element programmed;
    geom::Element compensated;  // start and end as far as they are known
    // The ends of the whole equidistant (before corners trimmed it; the G462 retraction's
    // extension starts at raw_end). Only the ends: the whole element was copied once a block.
    geom::Vec2 raw_start, raw_end;
    // Around the whole equidistant (so around every trimmed part of it), widened by a change of
    // value: computed at the first call (bottleneck detection: CDON, or an open junction), not
    // for every element (docs/performance.md §36).
    const geom::Box& box() {
      if (!box_known) setBox();
      return box_;
    }
    void setBox() {
      geom::Element raw = compensated;
      raw.p0 = raw_start;
      raw.p1 = raw_end;
      box_ = geom::Box(raw);
      if (r0 != r1) {  // a varying value (spiral, inclined line): widen by the change
        const double d = std::fabs(r1 - r0);
        box_.lo_a -= d, box_.lo_o -= d, box_.hi_a += d, box_.hi_o += d;
      }
      box_known = true;
    }
    double r0 = 0, r1 = 0;     // compensation value at the start and the end (D change, Q8)
    double side = 1;           // +1: tool left of the travel, -1: right
    long index = 0;            // traversing blocks since the selection (approach = 0)
    bool valid = true;         // has an equidistant (an inside arc smaller than R has none)
    bool open_before = false;  // no intersection with the previous element (yet)
    bool approach = false;     // the selection block's approach line
    bool restart = false;      // starts anew: side change (G41 <-> G42, sign of R), STOPRE
    bool emitted = false;      // already written (kept only to join the next element to)
    core::TrcStrategy strategy = core::TrcStrategy::G460;  // approach line
    geom::Vec2 first_tangent;  // approach line: the first element's start tangent (G462)
    std::vector<core::MotionBlock> transition;  // inserted before it (G450 circle, KONT)
    std::vector<core::MotionBlock> waiting;     // blocks without plane motion after it
    geom::Box box_;                             // box(), when box_known
    bool box_known = false;
  };
  // Copies block `from` into `to` (a slot's block, the retraction line): with AVX in 14 loads
  // and 14 stores of up to 32 bytes, not GCC's `rep movsq` of 54 quadwords, which counts 54
  // instructions and starts in microcode (docs/performance.md §42); `to = from` without AVX and
  // with the general paths (the twin).
  static void copyBlock(core::MotionBlock& to, const core::MotionBlock& from) {
    if (wide_copy_)
      copyBlockWide(to, from);
    else
      to = from;
  }
  static void copyBlockWide(core::MotionBlock& to, const core::MotionBlock& from);
  static bool wideCopyAvailable();

  // `p.compensated` as it is now is the whole equidistant: its ends are kept (raw_start,
  // raw_end) and its box computed when asked (with the general paths at once, the twin).
  static void keepRaw(Piece& p) {
    p.raw_start = p.compensated.p0;
    p.raw_end = p.compensated.p1;
    p.box_known = false;
    if (general_paths_) p.setBox();
  }

  // Forward declaration; defined in corners.cpp (the geometry of one junction).
  struct Corner;

  // --- The stage driver (radius_compensation.cpp): selection, dispatch, release, flush.
  // A G41/G42 block with plane motion: waits for the first element (W1 2-41).
  void startSelection(const core::MotionBlock& m);
  // The plane's lengths under the block's frame.
  // (The identity inline, once a selection; the rest out of line, §48.)
  static geom::PlaneMetric planeMetric(const core::MotionBlock& m, bool& projected) {
    projected = false;
    if (m.frame.isIdentity()) return {};
    return framedMetric(m, projected);
  }
  [[gnu::noinline]] static geom::PlaneMetric framedMetric(const core::MotionBlock& m,
                                                          bool& projected);
  void checkProjectable(const core::MotionBlock& m) const;
  void motionSelecting(const core::MotionBlock& m);
  // A block with compensation active and on (G40: retract).
  void motionOn(const core::MotionBlock& m);
  // The block keeps the selection's plane, frame and G group 22; true when CUTCONON handled it.
  bool checkSameSettings(const core::MotionBlock& m);
  // A change of G group 22 or 40, a projected plane, or a suppression running.
  bool rareSettings(const core::MotionBlock& m);
  // The bytes of G groups 22 and 40 (TrcSettings::frame_plane, ::constant) as one value: one
  // comparison per block finds a change of either.
  static std::uint16_t groupBytes(const core::TrcSettings& t) {
    static_assert(offsetof(core::TrcSettings, constant) ==
                  offsetof(core::TrcSettings, frame_plane) + 1);
    std::uint16_t v;
    std::memcpy(
        &v, reinterpret_cast<const unsigned char*>(&t) + offsetof(core::TrcSettings, frame_plane),
        sizeof v);
    return v;
  }
  // Writes the elements no later block can change.
  void release();
  void flushAll();
  // The block moves in the plane. (Inline: asked for every block.)
  static bool planeMotion(const core::MotionBlock& m) {
    if (m.motion == Motion::G2 || m.motion == Motion::G3) return true;
    return lineLength(m, planeAxes(m.plane)) > geom::tol::kPoint;  // a shorter motion is none
  }
  // The plane length of a line block: toElement(m).p1 - p0, without building the element.
  // (motionOn keeps it for the line's unit vector, compensateConstant: one root, §48.)
  // (The plane's axes from the caller: motionOn asks planeAxes once, which GCC does not inline
  // into it a second time.)
  static double lineLength(const core::MotionBlock& m, PlaneAxes pa) {
    return geom::length(planePoint(m.end, pa) - planePoint(m.start, pa));
  }

  // --- The window's elements (pieces.cpp): blocks as plane elements and their equidistants.
  // (Defined in usual_element.hpp, which every caller includes.)
  geom::Element toElement(const core::MotionBlock& m) const;
  // Program coordinates to the machine's lengths (a scaling frame; not inlined: rare).
  [[gnu::noinline]] void toMetric(geom::Element& e) const;
  core::MotionBlock toBlock(const core::MotionBlock& like, const geom::Element& e) const;
  // toBlock(m, e) for a line `e` from anywhere to the plane end point of block m itself (the
  // retraction line); the fast twin of toBlock.
  // Into `b` (the stage's line_, no block constructed).
  void lineToEnd(core::MotionBlock& b, const core::MotionBlock& m, const geom::Element& e) const;
  // Element `e` in the machine's lengths back in program coordinates (a scaling frame: rare).
  [[gnu::noinline]] geom::Element fromMetric(const geom::Element& e) const;
  // A block of `like` that keeps its applicate motion but stands at plane point `at`.
  core::MotionBlock atPoint(const core::MotionBlock& like, geom::Vec2 at) const;
  void emit(const core::MotionBlock& m) { out_.motion(m); }
  void emitPiece(const Piece& p);
  // emitPiece with blocks before or after the element, or a scaling frame (out of line).
  [[gnu::noinline]] void emitWithBlocks(const Piece& p, std::uint8_t tip_at);
  Piece compensate(const core::MotionBlock& m, double r0, double r1) const;
  // (`index` and `restart`: the slot's fields, set with the others.)
  void compensateInto(Piece& p, const core::MotionBlock& m, double r0, double r1, long index = 0,
                      bool restart = false) const;
  // compensateInto's steps: the slot's fields but the geometry; the geometry of the usual element
  // (one value, no scaling frame), the fast twin of compensateInto's general path.
  void startPiece(Piece& p, double r0, double r1, long index, bool restart) const;
  // (`length`: a line's lineLength when measured, else kUnmeasured; `pa`: planeAxes(m.plane).)
  void compensateConstant(Piece& p, const core::MotionBlock& m, double r, double length,
                          PlaneAxes pa) const;
  static constexpr double kUnmeasured = 0;
  // The usual element whole (usual_element.hpp): compensateInto's fast path, inline.
  void compensateUsual(Piece& p, const core::MotionBlock& m, double r, long index, bool restart,
                       double length, PlaneAxes pa) const;
  // The equidistant at the constant value the corner calculation uses (details Q8: the end
  // value of the first element, the start value of the second).
  geom::Element cornerEquidistant(const Piece& p, bool at_end) const;
  // The next element with its compensation value (a change spreads over the block, Q8) and
  // side (a change of side starts anew at the block's start, like a selection).
  // (`restart`: the element starts anew in any case, after STOPRE.)
  // (`length`, `pa`: as compensateUsual's.)
  void compensateNext(Piece& p, const core::MotionBlock& m, long index, bool restart, double length,
                      PlaneAxes pa);
  // motionOn for a block without plane motion (out of line: its block on the stack).
  [[gnu::noinline]] void waitOn(const core::MotionBlock& m);

  // --- Corners (corners.cpp, W1 2.4.3, 2.4.5, details Q3/Q4).
  // Joins `next` to the last element of the window (corner).
  void connect(Piece& cur, Piece& next);
  // connect's first outcome, inline for motionOn (the common case of CAM contours, §31): both
  // elements valid, no change of side, and the equidistants meet, so `next` starts where `cur`
  // ends and nothing is inserted. False: connect decides.
  // (The distance's root only when its square is not surely below kPoint^2, and with the
  // general paths, the twin: §48.)
  static bool joinTangent(const Piece& cur, Piece& next) {
    if (!cur.valid || !next.valid || next.restart) return false;
    const geom::Vec2 d = cur.compensated.p1 - next.compensated.p0;
    const double d2 = d.a * d.a + d.o * d.o;  // (geom::length's sum)
    if ((general_paths_ || !detail::surelyBelowPoint(d2)) && std::sqrt(d2) >= geom::tol::kPoint)
      return false;
    next.compensated.p0 = cur.compensated.p1;
    return true;
  }
  // A change of side: the straight line from the old normal point to the new one.
  void restartLine(Piece& next, geom::Vec2 from) const;
  void insideCorner(Piece& cur, Piece& next, const Corner& k) const;
  void outsideCorner(Piece& cur, Piece& next, const Corner& k) const;
  // The transition about corner point p from a (tangent ta) to b (tangent tb): the circle of
  // radius R, or with DISC > 0 the DISC curve as chords; the applicate runs from app0 to app1.
  void transition(std::vector<core::MotionBlock>& out, const core::MotionBlock& like, geom::Vec2 a,
                  geom::Vec2 ta, geom::Vec2 b, geom::Vec2 tb, geom::Vec2 p, double s, double disc,
                  double app0, double app1) const;

  // --- Bottleneck detection (bottleneck.cpp, W1 2.4.8, spec §5.5, details Q5).
  // A junction of the window without intersection, or an element without equidistant. (Here,
  // not in bottleneck.cpp: the driver asks it for every block.)
  bool anyOpen() const {
    return window_.any([](const Piece& p) { return p.open_before || !p.valid; });
  }
  // anyOpen() once `next` (the last element) is joined: with none open before it (maybe_open_
  // false: the usual contour) only `next` can be, and the walk over the window is saved (§36).
  bool openWith(const Piece& next) const {
    if (!maybe_open_) return next.open_before || !next.valid;
    return anyOpen();
  }
  // Intersects `next` with earlier elements of the window; `needed`: anyOpen() (CDOF searches
  // only then, CDON always).
  void bridge(Piece& next, bool needed);
  // The crossing of `later` with `target` (element `c` itself, or with `extension` its G461/G462
  // extension) where a bridge may start: nearest the start of `later`, turning to `side`.
  static std::optional<geom::Crossing> bridgeCrossing(const Piece& c, const geom::Element& target,
                                                      bool extension, const geom::Element& later,
                                                      double side);
  // The G461 circle / G462 line an approach line `c` is extended by for the search (Q7).
  static geom::Element approachExtension(const Piece& c, double r);
  // Omits the window's elements after position `keep` (but the last one if `keep_last`); `at`
  // is where their other actions run.
  void omitAfter(size_t keep, geom::Vec2 at, bool keep_last);
  // Raises 10751 for a junction that no later block can close any more.
  void checkOpen(long next_index) const;

  // --- Keep tool radius compensation constant (constant_compensation.cpp, W1 "Keep tool
  // radius compensation constant", docs/radius-compensation.md "CUTCONON").
  // A block with CUTCONON or the first after it; true when it was handled here.
  bool keepConstant(const core::MotionBlock& m);
  // The first block of a suppression: the window ends on the normal at its end (the offset).
  void beginConstant();
  // A block traversed uncompensated, shifted by `constant_offset_`.
  void emitShifted(const core::MotionBlock& m);
  [[noreturn]] static void constantAtSelection(const core::MotionBlock& m);

  // --- Approach and retraction (approach_retraction.cpp, W1 2.4.10, details Q1/Q2/Q7).
  // The selection block's approach line to the first element (NORM or KONT) into `approach`;
  // may move the start of `first`.
  void approachLine(Piece& approach, Piece& first);
  void kontApproach(Piece& approach, Piece& first);
  void retract(const core::MotionBlock& m);
  // G461/G462: the last element, meeting no earlier one, extended to find one (Q7).
  void retractionExtension(const core::MotionBlock& m);
  void kontRetraction(const core::MotionBlock& m);

  // +1: compensated to the left of travel. G41: left of the direction of travel; a negative
  // compensation value changes the side (PM-NC p256).
  // (Two flags compared, no branch: asked three times a block.)
  static double sideOf(const core::TrcSettings& t) {
    return (t.mode == core::TrcMode::Left) != (t.radius < 0) ? 1.0 : -1.0;
  }
  double side() const { return side_; }
  // settings_ and the side they give (side_: asked for every element, computed once a block).
  void setSettings(const core::TrcSettings& t) {
    settings_ = t;
    side_ = sideOf(t);
  }

  core::Stage& out_;
  bool pass_programmed_ = true;  // set per run by the channel
  State state_ = State::Off;
  // The G41/G42 block waiting for the first element: while selecting, the block of the window's
  // first slot, which becomes the approach line's (so it is copied once, docs/performance.md
  // §36). What the active compensation keeps comparing with after that: its plane, frame and
  // G groups 22 and 40.
  const core::MotionBlock& selection() const { return window_[0].block; }
  Plane sel_plane_ = Plane::G17;
  core::BlockFrame sel_frame_;
  std::uint16_t sel_groups_ = 0;            // groupBytes
  bool sel_frame_plane_ = false;            // G group 22: CUT2DF
  std::vector<core::MotionBlock> waiting_;  // blocks without plane motion after the selection
  core::MotionBlock line_;                  // the retraction line (lineToEnd): not constructed anew
  PieceWindow<Piece> window_;
  long count_ = 0;              // traversing blocks since the selection
  bool restart_next_ = false;   // after STOPRE: the next element starts anew
  bool constant_ = false;       // CUTCONON: blocks are shifted by constant_offset_
  geom::Vec2 constant_offset_;  // the offset vector at the end of the last compensated block
  int dummy_blocks_ = 0;
  core::TrcSettings settings_;  // of the last block (set by setSettings)
  double side_ = -1;            // sideOf(settings_)
  // The plane's lengths under the selection block's frame (SCALE): the window's elements are in
  // these coordinates, so that R is kept in the machine (toElement / geometry convert).
  geom::PlaneMetric metric_;
  bool projected_ = false;  // CUT2D in a plane the frame tilts: compensated in its projection
  // What checkSameSettings compares groupBytes with: sel_groups_, or with projected_ or
  // constant_ (rareSettings for every block) kRareGroups, which no block has (two bools): one
  // comparison for both tests (§48).
  std::uint16_t same_groups_ = 0;
  static constexpr std::uint16_t kRareGroups = 0xFFFF;
  void setRare(bool rare) { same_groups_ = rare ? kRareGroups : sel_groups_; }
  // An element of the window may be open or without equidistant (false: none is, so openWith
  // looks at the new one only). Set by every change of the window but motionOn's and the
  // selection's (bottleneck detection and release close and remove, never open).
  bool maybe_open_ = true;
  static inline bool general_paths_ = false;            // useGeneralPaths
  static inline bool wide_copy_ = wideCopyAvailable();  // copyBlock: AVX, not the general paths
};

}  // namespace ncoffset::trc
