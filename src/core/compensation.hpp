// What radius compensation and smooth approach read from each block (W1 2.4, 2.4.4): the G
// groups 7, 17, 18, 23, 43, 44, 48 and their data, as named values. Every stage includes this.
#pragma once

#include <cstdint>

#include "ncoffset/trc.hpp"

namespace ncoffset::core {

// G group 7: tool radius compensation (W1 2.4.1).
enum class TrcMode : std::uint8_t {
  Off,    // G40: no compensation
  Left,   // G41: the tool runs left of the contour (seen in the direction of travel)
  Right,  // G42: the tool runs right of the contour
};

// G group 48: approach and retraction with collision detection (W1 2.4.7, spec §5.3).
enum class TrcStrategy : std::uint8_t {
  G460,  // no extension of the approach/retraction block
  G461,  // extended by a circle of radius R about the contour's end point
  G462,  // extended by a straight line along the contour's end tangent
};

// G group 43: the side of a smooth approach or retraction (W1 2.4.4).
enum class SarSide : std::uint8_t {
  G140,  // the side follows G41/G42
  G141,  // from the left of the contour
  G142,  // from the right of the contour
  G143,  // automatic: the side where the approach point lies
};

// G group 44: the infeed of a smooth approach (W1 2.4.4).
enum class SarInfeed : std::uint8_t {
  G340,  // in space: the infeed runs with the approach curve
  G341,  // in the plane: infeed perpendicular to the plane first
};

// The SAR G codes (group 2 in the SAR sense): how the contour is approached or left.
enum class SarKind : std::uint8_t {
  None,
  Line147,        // G147: approach along a straight line
  Quadrant247,    // G247: approach along a quadrant
  Semicircle347,  // G347: approach along a semicircle
  Line148,        // G148: retraction along a straight line
  Quadrant248,    // G248: retraction along a quadrant
  Semicircle348,  // G348: retraction along a semicircle
};

inline bool isApproach(SarKind k) {
  return k == SarKind::Line147 || k == SarKind::Quadrant247 || k == SarKind::Semicircle347;
}
inline bool isRetraction(SarKind k) {
  return k == SarKind::Line148 || k == SarKind::Quadrant248 || k == SarKind::Semicircle348;
}
// The shape of the approach curve: 1 straight line, 2 quadrant, 3 semicircle.
inline int sarShape(SarKind k) {
  switch (k) {
    case SarKind::Line147:
    case SarKind::Line148:
      return 1;
    case SarKind::Quadrant247:
    case SarKind::Quadrant248:
      return 2;
    case SarKind::Semicircle347:
    case SarKind::Semicircle348:
      return 3;
    case SarKind::None:
      break;
  }
  return 0;
}

// Radius compensation data of one block.
struct TrcSettings {
  TrcMode mode = TrcMode::Off;
  double radius = 0;  // compensation value: edge radius + wear + OFFN (may be negative)
  Approach approach = Approach::Norm;
  CornerMode corner = CornerMode::TransitionCircle;
  CollisionCheck collision = CollisionCheck::Cdof;
  double disc = 0;  // DISC= (already limited by MD20220)
  TrcStrategy strategy = TrcStrategy::G460;
  // Group 22: false CUT2D/CUT2DD (the plane of G17..G19 in the machine), true CUT2DF/CUT2DFD
  // (the plane of the active frame). docs/radius-compensation.md "CUT2D, CUT2DF". (Here: in the
  // padding after `strategy`, the block copied per block does not grow.)
  bool frame_plane = false;
  // G group 40: true CUTCONON, false CUTCONOF: "keep tool radius compensation constant" (W1
  // "Keep tool radius compensation constant"; docs/radius-compensation.md "CUTCONON"). (In the
  // same padding.)
  bool constant = false;
  double corner_limit = 100;       // MD20210 CUTCOM_CORNER_LIMIT (degrees)
  double curve_insert_limit = 10;  // MD20230 CUTCOM_CURVE_INSERT_LIMIT (degrees)
  int max_dummy_blocks = 1;        // MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS
  int check_blocks = 3;            // MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS (look-ahead)
};

// A smooth approach or retraction block (W1 2.4.4, spec §6): what the SAR stage needs to expand
// it into its sub-blocks. `kind` None: an ordinary block.
struct SarRequest {
  SarKind kind = SarKind::None;
  SarSide side = SarSide::G140;
  SarInfeed infeed = SarInfeed::G340;
  bool has_disr = false, has_discl = false, has_disrp = false, has_fad = false;
  bool discl_ac = false, disrp_ac = false;
  bool plane_axis = false;    // an axis of the plane is programmed in the block
  bool any_axis = false;      // any geometry axis is programmed
  bool f_programmed = false;  // F is programmed in the block
  bool rapid_before = false;  // G0 (not G1/G2/G3) was modal before the block
  int max_dummy_blocks = 5;   // MD20202 WAB_MAXNUM_DUMMY_BLOCKS
  double disr = 0, discl = 0, disrp = 0, fad = 0;
  double feed_value = 0;   // the block's feed: F programmed in it, else the modal one
  double feed_before = 0;  // the modal feed before the block
  bool approach() const { return isApproach(kind); }
  bool retraction() const { return isRetraction(kind); }
};

}  // namespace ncoffset::core
