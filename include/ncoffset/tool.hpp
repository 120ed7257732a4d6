// Tool offsets (W1): tool data per cutting edge, effective lengths and radius, assignment of the
// length components L1/L2/L3 to the geometry axes, basic tool orientation and LENTOAX.
// The functions here are pure: the channel snapshots the data and setting data at the
// cutting-edge selection and calls them (W1 2.5: setting data act at the next selection).
#pragma once

#include <array>
#include <string>

#include "ncoffset/geometry.hpp"

namespace ncoffset {

// $TC_DP1..$TC_DP25 and the orientation data of one cutting edge (spec §1.2, §4).
struct EdgeData {
  std::array<double, 26> dp{};          // dp[n] = $TC_DPn (dp[0] unused)
  int dpv = 0;                          // $TC_DPV: coded orientation 1..6 (0: from DPV3..5)
  double dpv3 = 0, dpv4 = 0, dpv5 = 0;  // $TC_DPV3..5: orientation along L1, L2, L3
  int type() const { return static_cast<int>(dp[1]); }
  int cuttingEdgePosition() const { return static_cast<int>(dp[2]); }  // $TC_DP2, SL 1..9
};

// Setting data that shape the offsets, as they were at the cutting-edge selection.
struct ToolSettings {
  long length_const = 0;          // SD42940 $SC_TOOL_LENGTH_CONST
  long length_type = 0;           // SD42950 $SC_TOOL_LENGTH_TYPE
  bool mirror_length = false;     // SD42900 $SC_MIRROR_TOOL_LENGTH
  bool mirror_wear = false;       // SD42910 $SC_MIRROR_TOOL_WEAR
  bool wear_sign_cutpos = false;  // SD42920 $SC_WEAR_SIGN_CUTPOS
  bool wear_sign = false;         // SD42930 $SC_WEAR_SIGN
};

// W1 2.2 / spec §1.3: tool types 400..599 are turning and grinding tools.
constexpr bool isTurningOrGrindingType(int type) {
  return type >= 400 && type <= 599;
}

// Where each length component acts: axis[k] (0=X, 1=Y, 2=Z) and sign[k] (+1/-1) for L(k+1).
struct LengthAssignment {
  std::array<int, 3> axis{2, 1, 0};
  std::array<int, 3> sign{1, 1, 1};
  bool plane_independent = false;     // SD42940 != 0
  bool constant_orientation = false;  // SD42940 thousands digit = 1
};

// Spec §2.2-2.4: default tables by plane, SD42940 tables (incl. "any other value", negative
// values, hundreds digit = sign of L2, thousands digit = orientation from the table) and
// SD42950 (0 by type, 1 milling, 2 turning, others as 0).
LengthAssignment assignLengths(int tool_type, Plane plane, long sd42940, long sd42950);

// The edge's lengths after the wear rules, before assignment: geometry+base and wear per
// component, the total L1..L3 ($P_TOOLL) and the radius ($P_TOOLR).
struct EffectiveLengths {
  std::array<double, 3> geometry{};  // DP3..5 + DP21..23
  std::array<double, 3> wear{};      // DP12..14 after SD42930 and SD42920
  std::array<double, 3> total{};     // geometry + wear
  double radius = 0;                 // DP6 + DP15 (wear sign by SD42930)
};
EffectiveLengths effectiveLengths(const EdgeData& e, const ToolSettings& s);

// The vector from the tool tip to the carrier reference point in the basic coordinate system
// (spec §2.5 evaluation order). `mirrored[axis]`: that geometry axis is mirrored by the frame
// active at the selection (SD42900/SD42910).
Vec3 lengthVector(const EdgeData& e, const ToolSettings& s, Plane plane,
                  const std::array<bool, 3>& mirrored);

// Spec §4: the unit tool orientation in the basic coordinate system (plane default, $TC_DPV
// codes per the manual's table, $TC_DPV3..5 vectors), with SD42940/42950/42900 acting as on
// lengths.
Vec3 toolOrientation(const EdgeData& e, const ToolSettings& s, Plane plane,
                     const std::array<bool, 3>& mirrored);

// Spec §7: the theoretical tool tip P relative to the cutting edge centre S for cutting edge
// position SL 1..9 ($TC_DP2) of a turning tool with nose radius r, as components along the
// axes of L1 and L2 (X and Z in G18 with the standard assignment). SL 9 and 0: P = S.
std::array<double, 2> tipFromEdgeCentre(int sl, double r);

// The vector P - S of the active edge in the basic coordinate system
// (docs/cutting-edge-positions.md): tipFromEdgeCentre(SL, r) on the axes L1 and L2 are assigned to
// in `plane` (with the signs of SD42940/SD42950, like the lengths). Zero for tool types outside
// 400..599 and for SL 0 and 9. Radius compensation adds it where S runs on the equidistant, so that
// the lengths refer to P.
Vec3 tipVector(const EdgeData& e, const ToolSettings& s, Plane plane, double r);

// LENTOAX (W1 2.11, details §1): _AXIND and _MATRIX for the active edge in the coordinate
// system `coord` (M/B/W/K/T). `frame_linear` is the linear part of WCS -> BCS, `carrier` the
// rotation of an active toolholder with orientation capability (W1 2.5; not in the TCS).
struct LentoaxResult {
  int status = 0;              // 0 parallel, 1 use _MATRIX, -1 bad _COORD, -2 no tool
  std::array<int, 3> axind{};  // abscissa, ordinate, applicate
  std::array<std::array<double, 3>, 3> matrix{};  // [axis][component]
};
LentoaxResult lentoax(const EdgeData& e, const ToolSettings& s, Plane plane,
                      const std::array<bool, 3>& mirrored, const Mat3& frame_linear,
                      const std::string& coord, const Mat3& carrier = Mat3{});

}  // namespace ncoffset
