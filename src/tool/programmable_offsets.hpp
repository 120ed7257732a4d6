// Programmable tool offsets (PM Fundamentals 12/2019 2.5 "Programmable tool offset (TOFFL, TOFF,
// TOFFR)"): length offsets programmed in the part program that add to the active edge's length
// components, and a radius offset. docs/tool-offsets.md section 11.
#pragma once

#include <array>

#include "ncoffset/tool.hpp"

namespace ncoffset::tool {

struct ProgrammedOffsets {
  std::array<double, 4> length{};  // TOFFL (index 0, acts like TOFFL[1]) and TOFFL[1..3]
  std::array<double, 3> axis{};    // TOFF[X], TOFF[Y], TOFF[Z]
  double radius = 0;               // TOFFR
};

// What the programmed offsets add to the components L1, L2, L3 of an edge whose components act
// as `a` assigns them: TOFFL and TOFFL[1] on L1, TOFFL[2] on L2, TOFFL[3] on L3; TOFF[ax] on the
// component assigned to axis ax, with that component's sign so that it acts along +ax.
std::array<double, 3> programmedComponents(const ProgrammedOffsets& p, const LengthAssignment& a);

// The BCS vector of the programmed length offsets of an edge of `type` (the components through
// the assignment of `plane`, SD42940, SD42950; on an axis the frame mirrors negated with SD42910,
// like wear).
Vec3 programmedVector(const ProgrammedOffsets& p, int type, const ToolSettings& s, Plane plane,
                      const std::array<bool, 3>& mirrored);

}  // namespace ncoffset::tool
