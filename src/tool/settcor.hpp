// SETTCOR, changing tool components in a tool environment (W1 "Working with tool
// environments", "Changing tool components"; 828D FM 09/2011 18.12; PM-JP 12/2019 3.13): its
// parameter checks. The writing itself is ToolSelection::setToolCorrection
// (tool_environment_write.cpp); docs/tool-offsets.md section 14a has the rules and decisions.
#pragma once

#include <array>
#include <string>

namespace ncoffset::tool {

// The component letters of _COMP (C adapter/base, E setup, G geometry, S sum, W wear).
enum class ToolComponent { Base, Geometry, Wear, Sum, Setup };

struct SettcorComponents {
  ToolComponent val1 = ToolComponent::Geometry;
  ToolComponent val2 = ToolComponent::Geometry;
  int count = 0;             // 1 or 2 letters (Val1, Val2)
  bool tool_coords = false;  // ":T": the values are measured in the tool coordinate system
};

// _COMP: one or two letters (any case, blanks and tabs allowed), optionally ":" and W (WCS,
// the default) or T (TCS). Status 0, or -3 (no letter, more than two, one twice, another
// character).
int parseSettcorComponents(const std::string& text, SettcorComponents& out);

// _CORCOMP 0..11 (else status -9) and _CORMODE, a units and a tens digit (negative or above 99:
// status -10) [M: the status numbers -9 and -10]. Whether ncoffset models the mode is
// settcorModelled.
int checkSettcorModes(int corcomp, int cormode);

// The part of SETTCOR ncoffset computes: one component (Val1) with units digit 0 (Val1 takes
// the value) or 1 (the value is added), tens digit 0. The rest is alarm 99010.
bool settcorModelled(const SettcorComponents& c, int cormode);

// What a SETTCOR call asks for.
struct SettcorRequest {
  std::array<double, 3> value{};  // _CORVAL[0..2]
  std::string comp;               // _COMP
  int corcomp = 0;                // _CORCOMP
  int cormode = 0;                // _CORMODE
  int geoax = -1;                 // _GEOAX as geometry axis 0..2 (-1: none)
};

}  // namespace ncoffset::tool
