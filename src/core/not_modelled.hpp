// Alarm 99010: a construct the control accepts and ncoffset does not model (docs/alarms.md).
#pragma once

#include <fmt/format.h>

#include <string_view>

#include "ncoffset/alarm.hpp"

namespace ncoffset::core {

// `what` is not modelled, `why` says what it would change.
[[noreturn]] inline void notModelled(std::string_view what, std::string_view why) {
  raise(AlarmNumber::NotModelled, fmt::format("{} is not modelled by ncoffset: {}", what, why));
}

}  // namespace ncoffset::core
