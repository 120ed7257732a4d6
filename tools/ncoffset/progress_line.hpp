// A progress line on long runs (issue 14): where stderr is a terminal, a run that lasts more than
// a second shows which file and line it is at and how many segments it has written, updated in
// place at most four times a second, and erased before anything else is written to stderr and
// at the end. Nothing is written when stderr is not a terminal (pipes, files, CI logs).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "ncoffset/path.hpp"

namespace ncoffset::cli {

class ProgressLine {
 public:
  // `enabled`: whether stderr is a terminal (isatty), decided by the caller.
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  // Called for every segment: costs an increment and a compare, a clock read every 4,096.
  void segment(const Segment& s, const std::string& file) {
    if (!enabled_ || (++count_ & 4095) != 0) return;
    update(s.line, file);
  }

 private:
  void update(int line, const std::string& file);
  bool enabled_;
  std::uint64_t count_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

// Erases the progress line if one is shown (called before every other line on stderr).
void clearProgressLine();

}  // namespace ncoffset::cli
