// The interactive HTML report (issue 21; docs/output-formats.md "HTML"): one self-contained
// page with the program text of every file of the run beside a drawing of the path (pan, zoom,
// views XY/ZX/YZ/isometric, the programmed path beside the compensated one), linked both ways,
// a summary with a time estimate, the tool table and the warnings and alarm with their source
// lines. The path travels as JSON columns (report_columns.hpp) that the page's script
// (src/out/report/*.js, embedded at build time) draws; nothing is loaded from anywhere.
#pragma once

#include <array>
#include <cstdio>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncoffset/tool.hpp"
#include "out/arc_geometry.hpp"
#include "out/report_columns.hpp"
#include "out/svg_writer.hpp"
#include "out/time_estimate.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

// What the report asks the channel besides the path (any may be empty: then it goes without).
struct ReportContext {
  std::function<int()> file_count;
  std::function<const std::string&(int)> file_name;
  std::function<std::string_view(int)> file_text;
  std::function<std::optional<EdgeData>(int tool, int edge)> edge;  // the offset memory now
  std::function<AxisDynamics()> dynamics;                           // asked at the first segment
};

class HtmlReport : public PathSink {
 public:
  static constexpr int kMaxNotes = 1000;         // warnings and messages listed
  static constexpr int kMaxToolSlots = 1000;     // tool / edge / offset combinations listed
  static constexpr int kMaxToolChanges = 10000;  // tool change marks in the drawing
  static constexpr int kMaxUses = 20;            // blocks named per tool

  // program and coords ("mcs"/"wcs") name the run in the page title and summary.
  // decimals: of the numbers written (--decimals). view: the view the page opens with.
  HtmlReport(std::FILE* f, View view, std::string program, std::string coords, int decimals = -1,
             ReportContext context = {});
  void segment(const Segment& s) override;
  void message(const SourceLoc& where, const std::string& text) override;
  void warning(const SourceLoc& where, int number, const std::string& text) override;
  // Held until the output segment of the same block comes: where both are the same (no radius
  // compensation), the output segment carries a flag instead (kind + 16) and the programmed
  // one is not written twice.
  void programmed(const Segment& s) override;
  bool wantsProgrammed() const override { return true; }
  bool wantsEvents() const override { return true; }
  void tool(const ToolEvent& e) override;
  void frame(const FrameEvent& e) override;  // where the WCS origin is (drawn in MCS)
  void dwell(const DwellEvent& e) override { time_.dwell(e); }
  void spindle(const SpindleEvent& e) override { time_.spindle(e); }
  // The start position is assumed (no --start): the first move is neither drawn nor in the
  // lengths, ranges and time (docs/output-formats.md "Start position"); it is listed.
  void leaveOutFirstMove() { skip_first_ = true; }
  // Writes the page. Later calls do nothing.
  void finish(const Alarm* alarm) override;

 private:
  struct Note {
    SourceLoc where;
    int number;  // warning number; 0: an MSG text
    std::string text;
    long long segment;  // the segments written before it
  };
  struct ToolSlot {
    int tool = 0, edge = 0;
    double radius = 0;
    Vec3 length;
    std::optional<EdgeData> data;
    long long segments = 0;
    std::vector<SourceLoc> uses;  // the T/D/M6 blocks that selected it (the first kMaxUses)
    long long more_uses = 0;
  };
  struct ToolChange {
    long long segment;
    int slot;
  };
  void note(const SourceLoc& where, int number, const std::string& text);
  // html_report_page.cpp: the parts of the page.
  void writeHead();
  void writeSummary(const Alarm* alarm);
  void writeTools();
  void writeNotes(const Alarm* alarm);
  void writeData(const Alarm* alarm);
  void writeFiles();
  int fileIndex(const std::string& name) const;

  BufferedWriter w_;
  std::FILE* f_;
  View view_;
  std::string program_, coords_;
  int decimals_;
  ReportContext context_;
  bool finished_ = false;
  std::array<long long, 10> counts_{};  // per Motion
  long long total_ = 0;
  bool skip_first_ = false, first_seen_ = false;  // leaveOutFirstMove()
  double rapid_length_ = 0, cut_length_ = 0;
  Box box_;
  PathColumns output_, programmed_;
  TimeEstimate time_;
  bool dynamics_known_ = false;
  std::vector<Note> notes_;
  long long notes_dropped_ = 0;
  std::vector<ToolSlot> tools_;
  int tool_slot_ = -1;
  std::vector<ToolChange> changes_;
  // The WCS origin (BCS point of WCS zero) from the segment on, per frame change (the first
  // kMaxFrames; docs/output-formats.md "HTML").
  struct FrameMark {
    long long segment;
    Vec3 origin;
  };
  static constexpr size_t kMaxFrames = 10000;
  std::vector<FrameMark> frames_;
  std::deque<Segment> held_;  // programmed segments not yet written (at most kHeld)
  static constexpr size_t kHeld = 64;
};

}  // namespace ncoffset::out
