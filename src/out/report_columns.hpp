// The data of the interactive HTML report (html_report.hpp): a path (the output or the
// programmed path) as JSON arrays, one per column, spooled to temporary files while the run
// goes so memory stays flat in program length (as the SVG writer's layers). The page's script
// decodes them (src/out/report/report_data.js; the layout in docs/output-formats.md):
//   L  source line, as the difference to the segment before (small numbers: the file stays
//      small for long programs)
//   K  kind: motion (0 G0, 1 G1, 2 G2, 3 G3) + 4 with a feed + 8 with a start point in S
//      + 16 (output only) the programmed segment of the block is this one (not in "prog")
//   X, Y, Z  end point
//   R  runs: [index, file, tool slot, feed, feed unit] where one of them changes
//   A  arcs: [index, cx, cy, cz, nx, ny, nz, turns]
//   S  start points that are not the end point before: [index, sx, sy, sz]
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string_view>

#include "ncoffset/path.hpp"

namespace ncoffset::out {

// A JSON array written piece by piece: in memory up to 1 MiB, then in a temporary file.
class Spool {
 public:
  Spool() = default;
  Spool(const Spool&) = delete;
  Spool& operator=(const Spool&) = delete;
  ~Spool();
  // Starts an element (writes the separating comma) and returns the buffer to write it to.
  fmt::memory_buffer& element() {
    if (count_++) buf_.push_back(',');
    if (buf_.size() >= kLimit) [[unlikely]]
      spill();
    return buf_;
  }
  long long count() const { return count_; }
  // Writes `[elements]` to `b`, flushing `b` into `out` on the way.
  void copyTo(fmt::memory_buffer& b, std::FILE* out);

 private:
  static constexpr size_t kLimit = size_t{1} << 20;
  void spill();
  fmt::memory_buffer buf_;
  std::FILE* file_ = nullptr;  // std::tmpfile once the buffer overflowed
  long long count_ = 0;
};

class PathColumns {
 public:
  explicit PathColumns(int decimals) : decimals_(decimals) {}
  // `tool`: the report's tool slot active at the segment (-1: none yet); `same`: the
  // programmed segment is this one (kind + 16).
  void add(const Segment& s, int tool, bool same = false);
  long long size() const { return count_; }
  // Writes `{"L":[..],...}` to `b`/`out`.
  void copyTo(fmt::memory_buffer& b, std::FILE* out);

 private:
  void number(fmt::memory_buffer& b, double v) const;
  int decimals_;
  long long count_ = 0;
  int last_line_ = 0, last_file_ = -1, last_tool_ = -2;
  double last_feed_ = -1;
  FeedUnit last_unit_ = FeedUnit::MmPerMin;
  Vec3 last_end_;
  Spool lines_, kinds_, x_, y_, z_, runs_, arcs_, starts_;
};

// Appends `s` as a JSON string that may stand inside an HTML <script> element: `<` as \u003c
// (no `</script>` can end it), control characters escaped, other bytes as they are (UTF-8).
// `quoted` false: the characters only (a long string written in pieces).
void appendScriptString(fmt::memory_buffer& b, std::string_view s, bool quoted = true);

}  // namespace ncoffset::out
