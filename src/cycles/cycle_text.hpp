// Pieces of NC text the built-in cycles share (docs/cycles.md).
#pragma once

#include <string>
#include <string_view>

namespace ncoffset::cycles {

// After the DEF part of a cycle with `DEF STRING[1] _A1, _A2, _A3`: the two axes of the active
// plane and its applicate, the drilling axis (PM Cycles "Drilling cycles": "the cycles drill
// along the axis perpendicular to the active plane"; G17: X Y / Z, G18: Z X / Y, G19: Y Z / X).
inline constexpr std::string_view kPlaneAxes = R"(G90
_A1="X"
_A2="Y"
_A3="Z"
IF $P_GG[6]==2
_A1="Z"
_A2="X"
_A3="Y"
ENDIF
IF $P_GG[6]==3
_A1="Y"
_A2="Z"
_A3="X"
ENDIF
)";

// _AXN (CYCLE83, CYCLE84, CYCLE840): the tool axis 1, 2, 3 is X, Y, Z; 0 keeps the applicate.
inline constexpr std::string_view kToolAxis = R"(IF _AXN==1
_A3="X"
ENDIF
IF _AXN==2
_A3="Y"
ENDIF
IF _AXN==3
_A3="Z"
ENDIF
)";

// The final drilling depth _Z from DP and DPR (PM Cycles 2.1.2 "CYCLE81", parameters DP and
// DPR: "if a value is entered both for DP and DPR, the final drilling depth is derived from
// DPR"; DPR is relative to the reference plane, without sign).
inline constexpr std::string_view kFinalDepth = R"(_Z=_DP
IF _DPR<>0
_Z=_RFP-ABS(_DPR)
ENDIF
)";

// A dwell of _DTB: seconds (> 0) or, newer versions, spindle revolutions (< 0).
inline constexpr std::string_view kDwellDtb = R"(IF _DTB>0
G4 F=_DTB
ENDIF
IF _DTB<0
G4 S=-_DTB
ENDIF
)";

// The built text of one cycle: its pieces in order (kept for the run, built on first use).
inline std::string joined(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view p : parts) s.append(p);
  return s;
}

}  // namespace ncoffset::cycles
