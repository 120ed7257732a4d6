// SETTCOR's parameter checks (W1 "Changing tool components"; docs/tool-offsets.md section 14a).
#include "tool/settcor.hpp"

#include <cctype>

namespace ncoffset::tool {

namespace {

bool componentOf(char ch, ToolComponent& out) {
  struct Letter {
    char ch;
    ToolComponent component;
  };
  static constexpr Letter kLetters[] = {{'C', ToolComponent::Base},
                                        {'E', ToolComponent::Setup},
                                        {'G', ToolComponent::Geometry},
                                        {'S', ToolComponent::Sum},
                                        {'W', ToolComponent::Wear}};
  for (const Letter& l : kLetters)
    if (l.ch == ch) {
      out = l.component;
      return true;
    }
  return false;
}

}  // namespace

int parseSettcorComponents(const std::string& text, SettcorComponents& out) {
  out = SettcorComponents{};
  bool colon = false, coord_seen = false;
  for (char raw : text) {
    const char ch = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
    if (ch == ' ' || ch == '\t') continue;
    if (colon) {
      // PM-JP 12/2019: the second substring is empty, W (WCS) or T (TCS).
      if (coord_seen || (ch != 'W' && ch != 'T')) return -3;
      out.tool_coords = ch == 'T';
      coord_seen = true;
      continue;
    }
    if (ch == ':') {
      colon = true;
      continue;
    }
    ToolComponent c;
    if (!componentOf(ch, c) || out.count == 2) return -3;
    if (out.count == 1) {
      if (c == out.val1) return -3;  // a letter twice
      out.val2 = c;
    } else {
      out.val1 = c;
    }
    ++out.count;
  }
  return out.count == 0 ? -3 : 0;
}

int checkSettcorModes(int corcomp, int cormode) {
  if (corcomp < 0 || corcomp > 11) return -9;
  if (cormode < 0 || cormode > 99) return -10;
  return 0;
}

bool settcorModelled(const SettcorComponents& c, int cormode) {
  return c.count == 1 && (cormode == 0 || cormode == 1);
}

}  // namespace ncoffset::tool
