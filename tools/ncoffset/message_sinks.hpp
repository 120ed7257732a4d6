// The CLI's sinks around the output writer: MSG texts and warnings printed on stderr, and the
// progress line (progress_line.hpp).
//
// The writer itself prints the messages (Printing<W>, a writer class with message() and
// warning() extended), so that a segment goes from the channel to the writer's own segment()
// in one call: a wrapper forwarding every segment cost 15 instructions a segment (about 0.6 %
// of the TRC contour with CSV, docs/performance.md §28). Only where the progress line is shown
// (stderr a terminal, no -q) does a ProgressForwarder count the segments in between — the
// general path, which passes everything on to the same writer.
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "ncoffset/path.hpp"
#include "progress_line.hpp"
#include "terminal_text.hpp"

namespace ncoffset::cli {

// Writer W that also prints MSG texts and warnings on stderr (before W sees them).
template <typename W>
class Printing final : public W {
 public:
  using W::W;
  void message(const SourceLoc& where, const std::string& text) override {
    printError(fmt::format("{}:{}: message: {}", where.file, where.line, text));
    W::message(where, text);
  }
  void warning(const SourceLoc& where, int number, const std::string& text) override {
    printError(fmt::format("{}:{}: warning {}: {}", where.file, where.line, number, text));
    W::warning(where, number, text);
  }
};

// Counts the segments for the progress line and passes everything on to `next`.
class ProgressForwarder final : public PathSink {
 public:
  ProgressForwarder(PathSink& next, ProgressSource source)
      : next_(next), progress_(true, std::move(source)) {}
  void segment(const Segment& s) override {
    progress_.segment(s);
    next_.segment(s);
  }
  void message(const SourceLoc& where, const std::string& text) override {
    next_.message(where, text);
  }
  void warning(const SourceLoc& where, int number, const std::string& text) override {
    next_.warning(where, number, text);
  }
  void programmed(const Segment& s) override { next_.programmed(s); }
  bool wantsProgrammed() const override { return next_.wantsProgrammed(); }
  bool wantsEvents() const override { return next_.wantsEvents(); }
  void tool(const ToolEvent& e) override { next_.tool(e); }
  void mFunction(const MFunctionEvent& e) override { next_.mFunction(e); }
  void dwell(const DwellEvent& e) override { next_.dwell(e); }
  void spindle(const SpindleEvent& e) override { next_.spindle(e); }
  void feed(const FeedEvent& e) override { next_.feed(e); }
  void frame(const FrameEvent& e) override { next_.frame(e); }
  void axisNames(const std::vector<std::string>& n) override { next_.axisNames(n); }
  void axes(const AxesEvent& e) override { next_.axes(e); }
  void finish(const Alarm* alarm) override { next_.finish(alarm); }

 private:
  PathSink& next_;
  ProgressLine progress_;
};

}  // namespace ncoffset::cli
