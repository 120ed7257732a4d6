#include "cycles/builtin_cycles.hpp"

namespace ncoffset::cycles {

std::string_view builtinCycleText(std::string_view name) {
  // Every built-in name starts with CYCLE or HOLES: other calls return at once.
  if (name.rfind("CYCLE", 0) != 0 && name.rfind("HOLES", 0) != 0) return {};
  for (auto part : {drillingCycleText, tappingCycleText, boringCycleText, holePatternText}) {
    const std::string_view text = part(name);
    if (!text.empty()) return text;
  }
  return {};
}

}  // namespace ncoffset::cycles
