// The index checks of the offset memory's variables (tool_variables.cpp), shared by the edge
// data `$TC_DP..[t,d]` and the sum/setup offsets `$TC_SCP..[t,d]` (sum_offsets.cpp).
#pragma once

#include <span>
#include <string_view>

#include "lang/value.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::tool {

// A whole index lo..hi, else `alarm` naming `what`.
int wholeIndex(const lang::Value& v, int lo, int hi, AlarmNumber alarm, const char* what);
// The [T,D] of an edge variable: T 1..32000 (17020), D 1..9 (17030).
void edgeIndex(std::string_view name, std::span<const lang::Value> idx, bool indexed, int& t,
               int& d);

}  // namespace ncoffset::tool
