// The compensated path: what ncoffset emits where the control's interpolator would start.
#pragma once

#include <string>
#include <vector>

#include "ncoffset/alarm.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset {

// G0..G3, and the thread and tapping motions (PM-NC "Thread cutting"; docs/threads.md): lines
// whose feed is the thread lead in mm/rev (G33, G34, G35, G331, G332) or F (G63, tapping with
// a compensating chuck).
enum class Motion { G0, G1, G2, G3, G33, G34, G35, G331, G332, G63 };
const char* motionName(Motion m);
// The G number of the motion (0, 1, 2, 3, 33, 34, 35, 331, 332, 63).
int motionGNumber(Motion m);
// A thread or tapping motion (G33, G34, G35, G331, G332, G63): a straight line.
inline bool isThreadMotion(Motion m) {
  return m > Motion::G3;
}

// What a feed value means (G group 15, PM-NC "Feedrate"): mm/min (G94, G961, G971), mm per
// spindle revolution (G95, G96, G97) or the inverse of the block's time in minutes (G93).
enum class FeedUnit : unsigned char { MmPerMin, MmPerRev, InverseTime };
// "mm/min", "mm/rev", "1/min".
const char* feedUnitName(FeedUnit u);

// One output segment. Points are in the coordinate system chosen by the run (MCS or WCS).
struct Segment {
  int line = 0;  // 1-based source line of the block that produced it
  int file = 0;  // index into the run's file table (0 = main program)
  Motion motion = Motion::G1;
  Vec3 start;            // where the segment starts
  Vec3 end;              // where it ends
  Vec3 centre;           // arcs: absolute centre, lying in the plane of the start point
  Vec3 normal{0, 0, 1};  // arcs: unit normal; motion G2/G3 is the sense viewed from +normal
  int turns = 0;         // arcs: additional full turns (TURN=)
  double feed = 0;       // in feed_unit as programmed (G70/G700: converted to mm); 0 for G0
  FeedUnit feed_unit = FeedUnit::MmPerMin;
  // false: rapid traverse. G0 rows, and the G2/G3 corner circle (or the DISC chords) radius
  // compensation inserts before a G0 block: it moves with that block's data (PM-F 840Di 11/2006
  // p364), at rapid traverse.
  bool has_feed = false;
  // G34/G35: the lead change F in mm/rev per revolution (feed holds the start lead); else 0.
  double lead_change = 0;
};

// Events besides motion, for machine simulations (docs/architecture.md "Events"). Each carries
// the block's source line and file index (as Segment). A sink receives an event after the
// segments of the blocks before it and before the segments of its own block: the words of a
// block act before its motion, as the auxiliary functions do with output before the motion
// (MD22200 AUXFU_M_SYNC_TYPE = 0), except M0/M1, which stop after it.
struct ToolEvent {
  enum class Word { T, D, M6 } word = Word::T;  // what the block programmed
  int line = 0, file = 0;
  int tool = 0;          // the T number selected (T) or active (D, M6)
  int edge = 0;          // the active D number (0: no offset)
  double radius = 0;     // the active edge's radius (mm)
  Vec3 length;           // the active length vector in the BCS (tool tip -> carrier reference)
  bool changed = false;  // T: the tool became active at once (MD22550 = 0, no M6 needed)
};
struct MFunctionEvent {
  int line = 0, file = 0;
  int number = 0;   // M3, M8, ... (M2, M17, M30 end the program: PathSink::finish instead)
  int spindle = 0;  // address extension M2=3 -> 2; 0 without one
};
struct DwellEvent {
  int line = 0, file = 0;
  double seconds = 0;      // G4 F..
  double revolutions = 0;  // G4 S.. (of the master spindle)
};
struct SpindleEvent {
  int line = 0, file = 0;
  double speed = 0;  // S value as programmed (rev/min)
  int spindle = 0;   // address extension S2=...; 0 without one (the master spindle)
};
// The positions of the channel's additional axes (A, B, C, U, V, W, ... beyond X/Y/Z;
// docs/language.md "Axes") after a block that moves one, in the order of
// PathSink::axisNames and in the run's coordinates (MCS: machine positions, WCS: programmed
// positions; a modulo rotary axis in 0 <= value < 360). They hold from the next segment on.
struct AxesEvent {
  int line = 0, file = 0;
  std::vector<double> positions;
};
struct FeedEvent {
  int line = 0, file = 0;
  double feed = 0;  // the modal feed after the block, mm/min (G94) or mm/rev (G95)
};
// The channel's frame changed (G54..G599, G500, TRANS/ROT/SCALE/MIRROR and their A forms, G58,
// G59, frame variables): the WCS -> BCS map from this block on (FM K2). A WCS segment after it
// is in this frame, so its start is the previous end expressed anew (docs/output-formats.md
// "Start position"). G53/G153/SUPA suppress the frames of their own block only: no event.
struct FrameEvent {
  int line = 0, file = 0;
  Affine map;  // BCS point = map.linear * WCS point + map.offset (MCS = BCS + tool length)
};

// Receives the path as it is produced, block by block (streaming).
class PathSink {
 public:
  virtual ~PathSink() = default;
  virtual void segment(const Segment& s) = 0;
  // A message from MSG("...").
  virtual void message(const SourceLoc&, const std::string&) {}
  // A warning that does not stop the run (e.g. 10763: a block omitted by bottleneck detection).
  virtual void warning(const SourceLoc&, int /*number*/, const std::string& /*text*/) {}
  // The programmed (uncompensated) tool path of a motion, in the same coordinates as the
  // segments: what the tool centre would follow without radius compensation. For drawings;
  // emitted before the compensated segments of the same block where compensation is active.
  virtual void programmed(const Segment&) {}
  // Whether programmed() is wanted at all (asked once per run; computing it costs time).
  virtual bool wantsProgrammed() const { return false; }
  // Whether the events below are wanted (asked once per run; blocks without these words cost
  // nothing either way).
  virtual bool wantsEvents() const { return false; }
  virtual void tool(const ToolEvent&) {}
  virtual void mFunction(const MFunctionEvent&) {}
  virtual void dwell(const DwellEvent&) {}
  virtual void spindle(const SpindleEvent&) {}
  virtual void feed(const FeedEvent&) {}
  virtual void frame(const FrameEvent&) {}
  // The additional axes the run writes (their output columns), once, before the program's
  // first segment; never called for a run that uses none. Their positions: axes(), sent
  // whatever wantsEvents() says, before the segments of the block that moves them.
  virtual void axisNames(const std::vector<std::string>& /*names*/) {}
  virtual void axes(const AxesEvent&) {}
  // The run ended: normally (alarm == nullptr) or by an alarm.
  virtual void finish(const Alarm* alarm) = 0;
};

}  // namespace ncoffset
