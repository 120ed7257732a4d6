// Tool radius compensation settings (W1 2.4): the G groups and data the compensation stage
// reads for each block.
#pragma once

namespace ncoffset {

// G group 17: approach and retraction behaviour.
enum class Approach { Norm, Kont, KontC, KontT };
// G group 18: outside corners. TransitionCircle = G450, Intersection = G451.
enum class CornerMode { TransitionCircle, Intersection };
// G group 23: collision (bottleneck) detection. CDOF, CDON, CDOF2.
enum class CollisionCheck { Cdof, Cdon, Cdof2 };

struct TrcSettings {
  int mode = 40;      // G40, G41 (tool left of the contour), G42 (right)
  double radius = 0;  // compensation value: edge radius + wear + OFFN (may be negative)
  Approach approach = Approach::Norm;
  CornerMode corner = CornerMode::TransitionCircle;
  CollisionCheck collision = CollisionCheck::Cdof;
  double disc = 0;                 // DISC= (already limited by MD20220)
  int strategy = 460;              // G460 / G461 / G462
  double corner_limit = 100;       // MD20210 CUTCOM_CORNER_LIMIT (degrees)
  double curve_insert_limit = 10;  // MD20230 CUTCOM_CURVE_INSERT_LIMIT (degrees)
  int max_dummy_blocks = 1;        // MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS
  int check_blocks = 3;            // MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS (look-ahead)
};

// A smooth approach or retraction block (W1 2.4.4, spec §6): what the SAR stage needs to expand
// it into its sub-blocks. `type` 0 = an ordinary block.
struct SarRequest {
  int type = 0;     // 147/148 line, 247/248 quadrant, 347/348 semicircle
  int side = 140;   // G140..G143
  int space = 340;  // G340 (in space) / G341 (in the plane)
  bool has_disr = false, has_discl = false, has_disrp = false, has_fad = false;
  bool discl_ac = false, disrp_ac = false;
  double disr = 0, discl = 0, disrp = 0, fad = 0;
  bool plane_axis = false;  // an axis of the plane is programmed in the block
  bool any_axis = false;    // any geometry axis is programmed
  bool f_programmed = false;
  double feed_value = 0;   // the block's feed: F programmed in it, else the modal one
  double feed_before = 0;  // the modal feed before the block
  int motion_before = 1;   // 0: G0, 1: interpolation (G1/G2/G3) before the block
  bool approach() const { return type == 147 || type == 247 || type == 347; }
  bool retraction() const { return type == 148 || type == 248 || type == 348; }
};

}  // namespace ncoffset
