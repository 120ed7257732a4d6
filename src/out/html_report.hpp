// One self-contained HTML page about a run: summary (segments per motion, G0 and cutting path
// length, bounding box, the alarm, warnings and MSG texts), the SVG drawing inline (the
// SvgWriter's) and a table of the first segments. No scripts, no external resources.
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "out/arc_geometry.hpp"
#include "out/svg_writer.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

class HtmlReport final : public PathSink {
 public:
  static constexpr int kMaxRows = 1000;   // segments listed in the table
  static constexpr int kMaxNotes = 1000;  // warnings and messages listed (memory stays flat)

  // program and coords ("mcs"/"wcs") name the run in the page title and summary.
  // decimals: of the table's and the ranges' numbers and the drawing's path (--decimals).
  HtmlReport(std::FILE* f, View view, std::string program, std::string coords, int decimals = -1);
  void segment(const Segment& s) override;
  void message(const SourceLoc& where, const std::string& text) override;
  void warning(const SourceLoc& where, int number, const std::string& text) override;
  void programmed(const Segment& s) override { svg_.programmed(s); }
  bool wantsProgrammed() const override { return true; }
  // The start position is assumed: the first move is neither drawn nor in the lengths and
  // ranges (SvgWriter::leaveOutFirstMove); it is counted and listed as a segment.
  void leaveOutFirstMove() {
    svg_.leaveOutFirstMove();
    skip_first_ = true;
  }
  // Writes the page. Later calls do nothing.
  void finish(const Alarm* alarm) override;

 private:
  struct Note {
    SourceLoc where;
    int number;  // warning number; 0: an MSG text
    std::string text;
  };
  void note(const SourceLoc& where, int number, const std::string& text);
  void writeSummary(const Alarm* alarm);

  BufferedWriter w_;
  SvgWriter svg_;
  std::string program_, coords_;
  int decimals_;
  bool finished_ = false;
  bool skip_first_ = false;
  std::array<long long, 4> counts_{};  // per Motion
  double rapid_length_ = 0, cut_length_ = 0;
  Box box_;
  fmt::memory_buffer rows_;  // table rows of the first kMaxRows segments
  std::vector<Note> notes_;
  long long notes_dropped_ = 0;
};

}  // namespace ncoffset::out
