// What the parts of radius compensation share (radius_compensation.cpp, pieces.cpp,
// corners.cpp, bottleneck.cpp, approach_retraction.cpp and the inline parts of
// radius_compensation.hpp): the tolerances and the alarms raised in more than one of them.
//
// The tolerances are those of the compensation geometry, geom/tolerance.hpp (one policy for
// geom/ and trc/, docs/radius-compensation.md "Tolerances").
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <limits>
#include <string>

#include "core/motion_block.hpp"
#include "geom/tolerance.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::trc::detail {

namespace tol = geom::tol;

// Block `b` with the tip vector P - S kept only at `keep` (core::TipAt): the approach line
// starts where P stood, the retraction line ends where P is to stand (docs/cutting-edge-
// positions.md).
// In place: a 432-byte block is not copied again (docs/performance.md §31).
inline void keepTipAt(core::MotionBlock& b, std::uint8_t keep) {
  b.tip_at = static_cast<std::uint8_t>(b.tip_at & keep);
}

// A distance whose square `d2` is below 0.99 kPoint^2 is below kPoint, without the root: the
// root is correctly rounded and monotone, so sqrt(d2) <= sqrt(0.99) kPoint (within an ulp) there.
// The tangent junction's test (joinTangent) asks the root only above that (docs/performance.md
// §48; tests/trc/join_tangent_test.cpp).
inline bool surelyBelowPoint(double d2) {
  return d2 < 0.99 * tol::kPoint * tol::kPoint;
}

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
