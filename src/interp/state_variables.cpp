// Position and state reads (PM-JP "Flexible NC programming", "System variables"; the lists of
// system variables): $AA_IW[ax] and $AA_IM[ax], the actual positions in the WCS and the MCS,
// are main-run variables: reading one stops the preprocessing (an implicit STOPRE, with what
// that does to radius compensation and smooth approach, docs/radius-compensation.md). $P_GG[n]
// (the active G function of group n) and $P_F (the programmed feed) are preprocessing
// variables: no stop.
#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Value;

namespace {

int stateAxisIndex(const Value& v, std::string_view name, const ChannelAxes& axes) {
  if (v.isText()) return axes.geometryAxisOf(v.str, name);
  raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
}

}  // namespace

// An implicit preprocessor stop (PM-JP: main-run variables stop the preprocessing, as STOPRE).
// Returns where the tool tip stands (WCS of the last block's frame): the programmed end point,
// or with radius compensation active the point on the normal where the stop ended the contour.
Vec3 Interpreter::mainRunStop() {
  const std::optional<Vec3> moved =
      motion_.preprocessorStop(data_.get("$SC_STOP_CUTCOM_STOPRE") != 0);
  return moved ? *moved : motion_.wcs();
}

// The internal number of the active G function of group `group` (PM-NC "List of G functions":
// the functions of a group are numbered from 1 in the order of the list); 0 for a group
// ncoffset keeps no state of.
int Interpreter::gGroupIndex(int group) const {
  switch (group) {
    case 1:
      return static_cast<int>(modal_.motion) + 1;  // G0 1, G1 2, G2 3, G3 4
    case 6:
      return static_cast<int>(modal_.plane) + 1;  // G17 1, G18 2, G19 3
    case 7:
      return static_cast<int>(modal_.trc) + 1;  // G40 1, G41 2, G42 3
    case 8: {
      const int f = modal_.frame_select;  // G500 1, G54..G57 2..5, G505..G599 6..100
      return f == 500 ? 1 : f < 100 ? f - 52 : f - 499;
    }
    case 13:  // G70 1, G71 2, G700 3, G710 4
      switch (modal_.units) {
        case Units::G70:
          return 1;
        case Units::G71:
          return 2;
        case Units::G700:
          return 3;
        case Units::G710:
          return 4;
      }
      return 0;
    case 14:
      return modal_.incremental ? 2 : 1;  // G90 1, G91 2
    case 15:
      return static_cast<int>(modal_.feed_type) + 1;  // G93 1, G94 2, G95 3, G96 4, G97 5
    case 17:
      return static_cast<int>(modal_.approach) + 1;  // NORM 1, KONT 2, KONTT 3, KONTC 4
    case 18:
      return static_cast<int>(modal_.corner) + 1;  // G450 1, G451 2
    case 23:
      return static_cast<int>(modal_.collision) + 1;  // CDOF 1, CDON 2, CDOF2 3
    case 43:
      return static_cast<int>(modal_.sar_side) + 1;  // G140 1 .. G143 4
    case 44:
      return static_cast<int>(modal_.sar_infeed) + 1;  // G340 1, G341 2
    case 48:
      return static_cast<int>(modal_.trc_strategy) + 1;  // G460 1, G461 2, G462 3
    default:
      return 0;
  }
}

// The workpiece counters (PM-JP system variables; FM K1 "Workpiece counter"): channel variables a
// program reads and writes (the count of parts made), no effect on the path. They start at 0.
double* Interpreter::partCounter(std::string_view name) {
  static constexpr std::string_view kNames[] = {"$AC_TOTAL_PARTS", "$AC_REQUIRED_PARTS",
                                                "$AC_ACTUAL_PARTS", "$AC_SPECIAL_PARTS"};
  for (size_t i = 0; i < std::size(kNames); ++i)
    if (name == kNames[i]) return &part_counters_[i];
  return nullptr;
}

bool Interpreter::readState(std::string_view name, std::span<const Value> idx, bool indexed,
                            Value& out) {
  if (const double* counter = partCounter(name)) {
    if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
    out = Value::integer(*counter);
    return true;
  }
  if (name == "$P_AXN1" || name == "$P_AXN2" || name == "$P_AXN3") {
    // The abscissa, ordinate and applicate of the working plane (G17 X Y Z, G18 Z X Y,
    // G19 Y Z X) as AXIS values.
    static constexpr const char* kAxes[3][3] = {{"X", "Y", "Z"}, {"Z", "X", "Y"}, {"Y", "Z", "X"}};
    if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
    out = {lang::Type::Axis, 0, kAxes[static_cast<int>(modal_.plane)][name[6] - '1'], {}};
    return true;
  }
  if (name == "$P_SEARCH") {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "$P_SEARCH takes no index");
    out = Value::integer(0);  // no block search: ncoffset runs the program from its start
    return true;
  }
  if (name == "$AA_IW" || name == "$AA_IM") {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
    const int axis = stateAxisIndex(idx[0], name, axes_);
    // The tool tip where the last block left it: through the frame of that block into the BCS
    // and the MCS (with the tool length the axes have taken up), and seen through the frame
    // active now for $AA_IW (a frame programmed since then changes $AA_IW, as on the control).
    const Vec3 delta = mainRunStop() - motion_.wcs();  // off the programmed point (compensation)
    const Vec3 shift = motion_.frameLinear() * delta;
    const Vec3 p = name == "$AA_IW" ? frames_.toWcs(motion_.bcs() + shift) : motion_.mcs() + shift;
    // $AA_IW reads a diameter on the transverse axis under DIAMON/DIAM90 (docs/turning.md).
    out = Value::real(name == "$AA_IW" ? readPosition(p[axis], axis) : p[axis]);
    return true;
  }
  if (name == "$P_GG") {
    if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_GG needs [group]");
    const double g = lang::toNumber(idx[0], "G group");
    if (!(g >= 1 && g <= 70) || g != std::floor(g))
      raise(AlarmNumber::ArrayIndex1, fmt::format("illegal array index 1: $P_GG[{}]", g));
    const int index = gGroupIndex(static_cast<int>(g));
    if (index == 0)
      raise(AlarmNumber::NotModelled,
            fmt::format("$P_GG[{}] is not modelled by ncoffset: it keeps no state of G group {}", g,
                        g));
    out = Value::integer(index);
    return true;
  }
  if (name == "$P_F") {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "$P_F takes no index");
    out = Value::real(modal_.units == Units::G700 ? modal_.feed / 25.4 : modal_.feed);
    return true;
  }
  return false;
}

}  // namespace ncoffset::interp
