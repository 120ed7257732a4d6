#include "out/shortest_number.hpp"

#include <fmt/compile.h>

namespace ncoffset::out {

char* writeShortestSlow(char* out, double v) {
  return fmt::format_to(out, FMT_COMPILE("{}"), v + 0.0);  // -0 prints as 0
}

}  // namespace ncoffset::out
