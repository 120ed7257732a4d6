// TOFFL, TOFF, TOFFR (PM Fundamentals 12/2019 2.5; docs/tool-offsets.md section 11).
#include "tool/programmable_offsets.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

std::array<double, 3> programmedComponents(const ProgrammedOffsets& p, const LengthAssignment& a) {
  std::array<double, 3> c{p.length[0] + p.length[1], p.length[2], p.length[3]};
  for (size_t k = 0; k < 3; ++k) c[k] += a.sign[k] * p.axis[static_cast<size_t>(a.axis[k])];
  return c;
}

Vec3 programmedVector(const ProgrammedOffsets& p, int type, const ToolSettings& s, Plane plane,
                      const std::array<bool, 3>& mirrored) {
  const LengthAssignment a = assignLengths(type, plane, s.length_const, s.length_type);
  const std::array<double, 3> c = programmedComponents(p, a);
  Vec3 v;
  for (size_t k = 0; k < 3; ++k) {
    const int axis = a.axis[k];
    const double mirror = mirrored[static_cast<size_t>(axis)] && s.mirror_wear ? -1 : 1;
    v[axis] += a.sign[k] * mirror * c[k];
  }
  return v;
}

void ToolSelection::setProgrammed(const ProgrammedOffsets& p) {
  programmed_ = p;
  // The radius and the length vector of the active edge change at once (the next block that
  // moves an axis takes the length up, as after a D selection).
  if (edge_.valid) refreshRadius();
}

}  // namespace ncoffset::tool
