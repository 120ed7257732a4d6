// The additional axes' columns of a writer (docs/output-formats.md "Additional axes"): their
// names from PathSink::axisNames and their positions from the last PathSink::axes event.
#pragma once

#include <cctype>
#include <string>
#include <vector>

#include "ncoffset/path.hpp"

namespace ncoffset::out {

struct AxisColumns {
  std::vector<std::string> names;  // as the channel names them (A, B, X1, ...)
  std::vector<double> positions;

  bool empty() const { return names.empty(); }
  void announce(const std::vector<std::string>& n) {
    names = n;
    positions.assign(n.size(), 0.0);
  }
  void set(const AxesEvent& e) {
    if (e.positions.size() == positions.size()) positions = e.positions;
  }
  // The CSV header fields: ",a,b" (lower case like x, y, z).
  std::string header() const {
    std::string h;
    for (const auto& n : names) {
      h += ',';
      for (char c : n) h += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return h;
  }
};

}  // namespace ncoffset::out
