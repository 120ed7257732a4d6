// The standard drilling cycles and hole patterns built into ncoffset (docs/cycles.md): each is
// an NC program (PROC with the cycle's parameter list) written for ncoffset from the motion
// sequence the Cycles manual describes, never the control's cycle source. The subprogram search
// (interp/program_flow.cpp) finds one only after the user's programs: a CYCLE81.SPF beside the
// main program or on --path replaces the built-in one, as a user cycle does on the control.
#pragma once

#include <string_view>

namespace ncoffset::cycles {

// The program text of the built-in cycle `name` (upper case), or an empty view.
std::string_view builtinCycleText(std::string_view name);

// The parts (drilling_cycles.cpp, tapping_cycles.cpp, boring_cycles.cpp, hole_patterns.cpp).
std::string_view drillingCycleText(std::string_view name);
std::string_view tappingCycleText(std::string_view name);
std::string_view boringCycleText(std::string_view name);
std::string_view holePatternText(std::string_view name);

}  // namespace ncoffset::cycles
