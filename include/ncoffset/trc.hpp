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
  int mode = 40;            // G40, G41 (tool left of the contour), G42 (right)
  double radius = 0;        // compensation value: edge radius + wear + OFFN (may be negative)
  Approach approach = Approach::Norm;
  CornerMode corner = CornerMode::TransitionCircle;
  CollisionCheck collision = CollisionCheck::Cdof;
  double disc = 0;          // DISC= (already limited by MD20220)
  int strategy = 460;       // G460 / G461 / G462
  double corner_limit = 100;       // MD20210 CUTCOM_CORNER_LIMIT (degrees)
  double curve_insert_limit = 10;  // MD20230 CUTCOM_CURVE_INSERT_LIMIT (degrees)
  int max_dummy_blocks = 1;        // MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS
  int check_blocks = 3;            // MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS (look-ahead)
};

}  // namespace ncoffset
