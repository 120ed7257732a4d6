// Toolholders with orientation capability (W1 2.5 "Toolholder with orientation capability",
// PM-JP "TCARR, TCOABS, TCOFR"; docs/toolholders.md): the data blocks $TC_CARR1..65[m] (MD18088
// $MN_MM_NUM_TOOL_CARRIER of them) and what a selected holder does to the path: the rotation and
// the offset it gives the tool length vector (kinematic types T and M), and the offset and
// rotation of the table (types P and M).
#pragma once

#include <array>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "lang/value.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::tool {

// One data block $TC_CARRn[m] (W1 2.5.2 table "System variables"): numeric parameters by number
// (1..65; 47..54 and 61..63 do not exist), the axis names $TC_CARR21/22, the kinematic type
// $TC_CARR23 and the user's texts $TC_CARR34..36.
struct CarrierData {
  std::array<double, 66> num{};  // [n] = $TC_CARRn (REAL and INT parameters)
  std::string axis1, axis2;      // $TC_CARR21, $TC_CARR22 (AXIS)
  char kind = 'T';               // $TC_CARR23 (CHAR: T, P, M; any other letter: alarm 14153)
  std::string name, user_axis1, user_axis2;  // $TC_CARR34..36
};

// Group 42: the holder's angles from $TC_CARR13/14 (TCOABS) or from the active frame with the
// tool along its Z, Y or X axis (TCOFR = TCOFRZ, TCOFRY, TCOFRX).
enum class CarrierAngles : unsigned char { Absolute, FrameZ, FrameY, FrameX };

// What the active holder does (identity without one):
//   tool length vector  L' = tool_rotation * L + tool_offset      (types T, M; T alone: no part)
//   table               BCS = part_offset + ...                     ($P_PARTFR, types P, M)
//   PAROT rotation      part_rotation                                (types P, M)
struct CarrierPose {
  int number = 0;  // TCARR=m (0: none)
  char kind = 'T';
  double angle1 = 0, angle2 = 0;  // the rotary axis positions used (degrees)
  Mat3 tool_rotation;
  Vec3 tool_offset;
  Mat3 part_rotation;
  Vec3 part_offset;
  // $P_TCANG[1..4], $P_TCSOL: the angle pairs TCOFR found (first the one taken).
  std::array<double, 4> solutions{};
  int solution_count = 0;
};

// Rotation by `degrees` about the axis `v` (right hand; |v| need not be 1). A zero vector gives
// the identity: such an axis does not rotate (W1: the holder then only adds its offsets).
Mat3 rotationAboutVector(Vec3 v, double degrees);

class ToolCarriers {
 public:
  explicit ToolCarriers(int count) : count_(count) {}
  void setCount(int count) { count_ = count; }
  int count() const { return count_; }

  // $TC_CARRn[m] reads and writes (false for names that are none); alarms 17020 (m outside
  // 0..MD18088; m = 0 only for `$TC_CARR1[0]=0`, which clears every block), 12550 (n not a
  // parameter), 12150 (a value of the wrong type).
  bool read(std::string_view name, std::span<const lang::Value> idx, bool indexed,
            lang::Value& out) const;
  bool write(std::string_view name, std::span<const lang::Value> idx, bool indexed,
             const lang::Value& v);

  // The pose of holder m (TCARR=m; m = 0: the identity). `frame_linear` is the active frame's
  // linear part (TCOFR), `fine` SD42974 $SC_TOCARR_FINE_CORRECTION. Alarms 14150 (m beyond
  // MD18088), 14153 (unknown kinematic type), 14152 (TCOFR: no angles give the orientation).
  // `axis_angles`: the positions of the rotary axes $TC_CARR21/22 names where the channel has
  // them (NaN where not: then $TC_CARR13/14, W1 "the angles of a manual holder").
  CarrierPose pose(int m, CarrierAngles mode, const Mat3& frame_linear, bool fine,
                   std::array<double, 2> axis_angles = {kNoAxis, kNoAxis}) const;
  static constexpr double kNoAxis = std::numeric_limits<double>::quiet_NaN();
  // The names $TC_CARR21/22 of holder m ("" where none).
  std::array<std::string, 2> axisNames(int m) const;

 private:
  const CarrierData& data(int m) const;
  int count_;
  std::map<int, CarrierData> blocks_;  // written blocks; the others are all zero (type T)
};

// The angles (a1, a2) with R(v1, a1 - off1) R(v2, a2 - off2)... solved for TCOFR
// (toolholder_angles.cpp): rotations Ra(b1) Rb(b2) s = t; up to two solutions, false if none.
struct AngleSolutions {
  int count = 0;
  std::array<std::array<double, 2>, 2> b{};
};
AngleSolutions solveTwoAxes(Vec3 a, Vec3 b, Vec3 s, Vec3 t, std::array<double, 2> preset);

}  // namespace ncoffset::tool
