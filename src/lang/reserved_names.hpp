// The names a DEF may not give a user variable (PM-NC "Fundamentals of NC programming", "Names":
// reserved keywords must not be used as identifiers; PM-JP "Flexible NC programming",
// "Definition of user variables"): address letters, addresses with a number (X1, R5, MD20270),
// extended addresses (CR, AR, DISC, ...), keywords, operators, data types and the predefined
// functions and commands ncoffset gives a meaning to. A variable of such a name would change
// what later words of the program mean (after `DEF REAL X`, `X=5` would be an assignment).
#pragma once

#include <string_view>

namespace ncoffset::lang {

// `name` (upper case) is predefined: an address, keyword or predefined name.
bool isPredefinedName(std::string_view name);

// Why `name` is no valid user variable name, or nullptr when it is one: at most 31 characters,
// the first two letters or underscores (the rest letters, digits, underscores).
const char* variableNameProblem(std::string_view name);

}  // namespace ncoffset::lang
