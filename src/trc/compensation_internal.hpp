// What the parts of radius compensation share (radius_compensation.cpp, pieces.cpp,
// corners.cpp, bottleneck.cpp, approach_retraction.cpp and the inline parts of
// radius_compensation.hpp): the tolerances and the alarms raised in more than one of them.
//
// The tolerances are gathered here with the values they had as literals; one name per role, so
// that changing one (another issue will) does not change the others by accident.
#pragma once

#include <fmt/format.h>

#include <limits>
#include <string>

#include "ncoffset/alarm.hpp"

namespace ncoffset::trc::detail {

// Lengths (mm) and element parameters (fractions of an element): "on the element", "the same
// point", "behind the contour".
inline constexpr double kEps = 1e-9;
// The turn condition of bottleneck detection: the cross product of the two unit tangents at a
// crossing (W1 2.4.8, details Q5).
inline constexpr double kTurnEps = 1e-9;
// "No value / no motion": a compensation value, a plane or applicate motion, a change of the
// value, the cross product of two antiparallel tangents (a reversal).
inline constexpr double kZero = 1e-12;
// How far the straight chords of a DISC transition curve may deviate from the curve (mm).
inline constexpr double kDiscTolerance = 1e-3;
// The index of a block that never comes (for checkOpen when the window is flushed).
inline constexpr long kNoLaterBlock = std::numeric_limits<long>::max() / 2;

[[noreturn]] inline void notModelled(const std::string& what) {
  raise(AlarmNumber::NotModelled,
        fmt::format("{} is not modelled by ncoffset yet (tool radius compensation)", what));
}

// Alarm 10751 (W1 2.4.8, spec §5.6): a junction that no block within MD20240 closes.
[[noreturn]] inline void collision(int line, int check_blocks) {
  throw AlarmError(AlarmNumber::TrcCollision,
                   fmt::format("danger of collision due to tool radius compensation: no point of "
                               "intersection found within the reviewed {} traversing blocks "
                               "(MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS)",
                               check_blocks),
                   line);
}

}  // namespace ncoffset::trc::detail
