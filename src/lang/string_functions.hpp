// The string functions of the NC language (PM-JP "Flexible NC programming", "String
// operations"): TOUPPER, TOLOWER, INDEX, RINDEX, MINDEX, MATCH, SUBSTR, NUMBER, ISNUMBER, AXNAME,
// AXSTRING. STRLEN is with the arithmetic functions (evaluator.cpp), `<<` an operator, ISVAR
// needs the channel's names (interp/system_variables.cpp).
#pragma once

#include <span>
#include <string_view>

#include "lang/value.hpp"

namespace ncoffset::lang {

// Evaluates the string function `name`; false when `name` is none of them.
bool stringFunction(std::string_view name, std::span<const Value> args, Value& out);

// The value of `text` as the NC language writes a number (blanks around it, a sign, digits with
// an optional decimal point, an optional `EX` exponent); false when it is no number.
bool parseNumberText(std::string_view text, double& out);

}  // namespace ncoffset::lang
