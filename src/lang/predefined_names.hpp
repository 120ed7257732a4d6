// The predefined names of the control that shop programs use and that have no code of their own
// in the interpreter (docs/names.md is the complete list with the reasons): each is (a) modelled
// (the state ncoffset computes, e.g. CUT2D, the default of its group), (b) accepted with no
// effect on the path (SOFT, COMPCAD, WAITM, ...), or (c) changing the path and not modelled
// (alarm 99010 naming it and why). A name in none of the classes is unknown (alarm 12550), as
// on the control. Looked up only for names that are no address letter and that the interpreter
// does not know otherwise: the plain block never gets here. A DEF may not define one of them
// (reserved_names.cpp).
#pragma once

#include <string_view>

namespace ncoffset::lang {

enum class NameClass : unsigned char { Modelled, NoPathEffect, NotModelled };

struct PredefinedName {
  std::string_view name;
  NameClass cls;
  bool zero_accepted;  // (c) names whose value 0 is the state ncoffset models (DL=0, TCARR=0)
  bool prefix;         // the row stands for every name that starts with it ($TC_SCP13, $AC_...)
  bool cycle;          // a cycle: a program of that name beside the main program is called
  const char* why;
};

// The row of `name` (upper case), or nullptr.
const PredefinedName* findPredefinedName(std::string_view name);

}  // namespace ncoffset::lang

namespace ncoffset::lang {
// The whole table (for the test that compares it with docs/names.md).
const PredefinedName* predefinedNamesBegin();
const PredefinedName* predefinedNamesEnd();
}  // namespace ncoffset::lang
