#include "start_option.hpp"

#include <cmath>
#include <cstdlib>

namespace ncoffset::cli {

std::optional<Vec3> parseStart(const std::string& text, std::string& why) {
  why = "'" + text + "' is not X,Y,Z: three numbers in mm separated by commas";
  Vec3 p;
  size_t at = 0;
  for (int i = 0; i < 3; ++i) {
    size_t end = i < 2 ? text.find(',', at) : text.size();
    if (end == std::string::npos) return std::nullopt;
    const std::string part = text.substr(at, end - at);
    if (part.empty() || part.find_first_not_of("0123456789+-.eE") != std::string::npos)
      return std::nullopt;
    char* stop = nullptr;
    const double v = std::strtod(part.c_str(), &stop);
    if (stop != part.c_str() + part.size() || !std::isfinite(v)) return std::nullopt;
    if (std::fabs(v) > 1e9) {
      why = "'" + text + "': a start coordinate beyond the machine's number range (1e9 mm)";
      return std::nullopt;
    }
    p[i] = v;
    at = end + 1;
  }
  why.clear();
  return p;
}

}  // namespace ncoffset::cli
