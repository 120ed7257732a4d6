// The alarm number a call raises (0 when it raises none): the unit tests' one helper for it.
#pragma once

#include "ncoffset/alarm.hpp"

namespace ncoffset::test {

int alarmOf(auto&& f) {
  try {
    f();
  } catch (const AlarmError& e) {
    return e.number();
  }
  return 0;
}

}  // namespace ncoffset::test
