// The channel's state of the orientable toolholder (W1 2.5; toolholder_words.cpp): the selected
// holder (TCARR), G group 42 (TCOABS, TCOFR..), and what the block programmed of them, PAROT
// (group 52) and TOROT/TOFRAME (group 53).
#pragma once

#include "tool/toolholder.hpp"

namespace ncoffset::interp {

// Group 53: TOROTOF, TOROT = TOROTZ, TOROTY, TOROTX, TOFRAME = TOFRAMEZ, TOFRAMEY, TOFRAMEX.
enum class ToolFrame : unsigned char { Off, Z, Y, X };

struct CarrierState {
  int number = 0;  // TCARR=m in effect
  tool::CarrierAngles mode = tool::CarrierAngles::Absolute;
  tool::CarrierPose pose;
  // What the current block programmed (pending until the block is executed).
  bool pending = false;
  int programmed_number = -1;  // TCARR=m of the block, -1 none
  bool mode_changed = false;
  bool axis_moved = false;  // an additional axis moved: TCOABS takes the holder's axes anew
  int parot = -1;           // 1 PAROT, 0 PAROTOF, -1 neither
  int toframe = -1;         // ToolFrame of the block, -1 none
  bool tool_frame_on = false;
};

}  // namespace ncoffset::interp
