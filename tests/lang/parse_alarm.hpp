// The alarm number parseBlock raises for one block of text, 0 if it parses (the lang tests'
// one helper for syntax alarms).
#pragma once

#include <string_view>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {

inline int parseAlarm(std::string_view text, const ParseLimits& limits = {}) {
  Block b;
  try {
    parseBlock(text, 1, b, limits);
  } catch (const AlarmError& e) {
    return e.number();
  }
  return 0;
}

}  // namespace ncoffset::lang
