// The `--vars` file (design.md): the R parameters that were written, the active tool as its
// system variables show it, the last smooth approach's points, and every user variable of the
// main program (and the global ones) by name, as one JSON object.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/stage.hpp"
#include "interp/variables.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::out {

// $P_TOOLNO, $P_TOOL, $P_TOOLL, $P_TOOLR, $P_TOOLO and $TOOL_LENGTH_BCS.
struct ToolReadout {
  int tool = 0;
  int edge = 0;
  Vec3 lengths;  // L1, L2, L3 with wear
  double radius = 0;
  Vec3 orientation;                        // unit vector along the tool
  Vec3 length_bcs;                         // the length vector in the BCS
  std::array<double, 26> active_offset{};  // $P_AD[1..26]: $TC_DP1..25 and the CE number
  int environments = 0;                    // $P_TOOLENVN
};

// The active sum/setup offset DL with its values (L1, L2, L3, radius: $TC_SCPx3..x6 and
// $TC_ECPx3..x6) and the programmed offsets TOFFL[0..3], TOFF[X,Y,Z], TOFFR
// (docs/tool-offsets.md sections 10, 11).
struct OffsetReadout {
  int dl = 0;
  std::array<double, 4> sum{}, setup{};
  std::array<double, 4> toffl{};
  Vec3 toff;
  double toffr = 0;
};

struct VariablesReport {
  std::vector<std::pair<std::size_t, double>> r;  // R number and value, ascending
  ToolReadout tool;
  OffsetReadout offsets;
  core::ApproachPoints approach;                                 // $P_APR, $P_AEP, $P_APDV
  std::map<std::string, const interp::UserVariable*> variables;  // sorted by name
};

void writeVariablesJson(std::ostream& out, const VariablesReport& report);

}  // namespace ncoffset::out
