// W1 2.2-2.4 / spec §2.2-2.4: assignment of L1/L2/L3 to geometry axes.
#include <cstdlib>

#include "ncoffset/tool.hpp"

namespace ncoffset {
namespace {

constexpr int X = 0, Y = 1, Z = 2;
using Row = std::array<int, 3>;

// SD42940 tables (Parameter Manual 08/2013 p321, PM-NC p750): axes of L1, L2, L3.
Row turningRow(int key) {
  switch (key) {
    case 17:
      return {Y, X, Z};
    case -17:
      return {X, Y, Z};
    case -18:
      return {Z, X, Y};
    case 19:
      return {Z, Y, X};
    case -19:
      return {Y, Z, X};
    default:
      return {X, Z, Y};  // 18 and any other non-zero value
  }
}
Row millingRow(int key) {
  switch (key) {
    case 18:
      return {Y, X, Z};
    case 19:
      return {X, Z, Y};
    case -17:
      return {Z, X, Y};
    case -18:
      return {Y, Z, X};
    case -19:
      return {X, Y, Z};
    default:
      return {Z, Y, X};  // 17 and any other non-zero value
  }
}

int planeKey(Plane p) {
  return p == Plane::G17 ? 17 : p == Plane::G18 ? 18 : 19;
}

}  // namespace

LengthAssignment assignLengths(int tool_type, Plane plane, long sd42940, long sd42950) {
  bool turning = sd42950 == 1 ? false : sd42950 == 2 ? true : isTurningOrGrindingType(tool_type);
  LengthAssignment a;
  if (sd42940 == 0) {
    // Default: the SD42940 row of the active plane (W1: milling L1 applicate, L2 ordinate,
    // L3 abscissa; turning L1 ordinate, L2 abscissa, L3 applicate).
    a.axis = turning ? turningRow(planeKey(plane)) : millingRow(planeKey(plane));
    return a;
  }
  // Digits (details §3): |value| = thousands, hundreds, then the table key in the last two.
  long mag = std::labs(sd42940);
  int base = static_cast<int>(mag % 100);
  int hundreds = static_cast<int>((mag / 100) % 10);
  int thousands = static_cast<int>((mag / 1000) % 10);
  int key = sd42940 < 0 ? -base : base;
  a.axis = turning ? turningRow(key) : millingRow(key);
  a.plane_independent = true;
  a.constant_orientation = thousands == 1;
  if (hundreds == 1) a.sign[1] = -1;
  return a;
}

}  // namespace ncoffset
