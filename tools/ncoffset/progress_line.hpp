// A progress line on long runs (issues 14 and 21): where stderr is a terminal, a run that lasts
// more than a second shows which file and line it is at, the blocks executed and how many a
// second, the segments written and, in a file larger than kLargeFile, how far through the file
// the line is; updated in place at most four times a second, and erased before anything else
// is written to stderr and at the end. Nothing is written when stderr is not a terminal
// (pipes, files, CI logs) or with -q.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ncoffset/path.hpp"

namespace ncoffset::cli {

// What the line reads from the run besides the segment.
struct ProgressSource {
  std::function<const std::string&(int)> file_name;
  std::function<std::string_view(int)> file_text;
  std::function<long long()> blocks;
};

class ProgressLine {
 public:
  static constexpr size_t kLargeFile = size_t{4} << 20;  // 4 MiB: the percentage is shown
  // `enabled`: stderr is a terminal (isatty) and -q not given, decided by the caller.
  ProgressLine(bool enabled, ProgressSource source);
  ~ProgressLine();
  // Called for every segment: costs an increment and a compare, a clock read every 4,096.
  void segment(const Segment& s) {
    if (!enabled_ || (++count_ & 4095) != 0) return;
    update(s.line, s.file);
  }

 private:
  void update(int line, int file);
  // The percentage of `file` at `line` ("" for a small file); lines counted once per file.
  std::string percent(int line, int file);
  bool enabled_;
  ProgressSource source_;
  std::uint64_t count_ = 0;
  long long last_blocks_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
  std::vector<long long> lines_;  // per file index: its line count (-1 small, 0 not counted)
};

// Erases the progress line if one is shown (called before every other line on stderr).
void clearProgressLine();

}  // namespace ncoffset::cli
