// Output sinks: CSV (the contract of design.md) and JSON Lines. Both write through a buffer
// that is flushed on every alarm and at the end, never leaving a torn line.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "core/row_sink.hpp"
#include "ncoffset/path.hpp"
#include "out/axis_columns.hpp"

namespace ncoffset::out {

// Resolves a Segment::file index to its name (for JSON Lines).
using FileNames = std::function<const std::string&(int)>;

class BufferedWriter {
 public:
  explicit BufferedWriter(std::FILE* f) : f_(f) {}
  ~BufferedWriter() { flush(); }
  void flush() {
    if (!buf_.size()) return;
    wrote_ = true;
    std::fwrite(buf_.data(), 1, buf_.size(), f_);
    buf_.clear();
    std::fflush(f_);
  }
  // Flushes whole lines only, once the buffer is large.
  void lineDone() {
    if (buf_.size() >= 1 << 16) {
      wrote_ = true;
      std::fwrite(buf_.data(), 1, buf_.size(), f_);
      buf_.clear();
    }
  }
  // The buffer and then `n` characters at `text` to the file (whole lines: a writer's own
  // buffer of rows, CsvWriter), without copying them into the buffer first; `sync`: flushed
  // (as flush()).
  void write(const char* text, size_t n, bool sync) {
    wrote_ = true;
    if (buf_.size()) std::fwrite(buf_.data(), 1, buf_.size(), f_);
    buf_.clear();
    std::fwrite(text, 1, n, f_);
    if (sync) std::fflush(f_);
  }
  fmt::memory_buffer& buf() { return buf_; }
  // Whether anything reached the file (a header can no longer change).
  bool wrote() const { return wrote_; }

 private:
  std::FILE* f_;
  bool wrote_ = false;
  fmt::memory_buffer buf_;
};

// Numbers as the shortest text that reads back as the same double. (The writers are not final:
// the CLI extends them with printing MSG texts, tools/ncoffset/message_sinks.hpp.)
class CsvWriter : public core::RowSink, public PathSink {
 public:
  explicit CsvWriter(std::FILE* f);
  ~CsvWriter() override { flushRows(true); }
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  // (final: row() writes what segment() writes, core/row_sink.hpp.)
  void segment(const Segment& s) final;
  void row(int line, Motion motion, bool has_feed, double x, double y, double z, double cx,
           double cy, double cz, double feed) final;
  void finish(const Alarm* alarm) override;
  // The additional axes: columns after feed (docs/output-formats.md).
  void axisNames(const std::vector<std::string>& names) override;
  void axes(const AxesEvent& e) override { axes_.set(e); }

 private:
  // The text last written for a column whose value seldom changes from row to row (z and the
  // centre's z, the feed): copied while the value is the same (docs/performance.md §32).
  struct Memo {
    double value = std::numeric_limits<double>::quiet_NaN();  // equal to no value
    size_t len = 0;
    char text[16] = {};  // (numbers of up to 16 characters; longer ones are not kept)
  };
  static char* writeMemo(char* p, double v, Memo& m);
  static char* writeSmallMemo(char* p, double v, Memo& m);
  // The end of the usual row of a line after y (",z,,,,feed\n"), for the next row of a line
  // with the same z and feed (docs/performance.md §51).
  struct TailMemo {
    double z = std::numeric_limits<double>::quiet_NaN();  // equal to no z
    double feed = 0;
    bool has_feed = false;
    size_t len = 0;
    char text[32] = {};
  };
  char* writeLineTail(char* p, double z, bool has_feed, double feed);
  // The line number's text: the row before's while the line repeats, incremented in place
  // while the rows come from consecutive lines (docs/performance.md §37).
  struct LineMemo {
    // A negative line, or none yet: no line is kNone or kNone + 1.
    static constexpr long long kNone = std::numeric_limits<long long>::min() / 2;
    long long value = kNone;  // the line whose text `text` holds (>= 0)
    size_t len = 0;
    char text[16] = {};
  };
  char* writeLine(char* p, int line);
  static char* writeMotion(char* p, Motion motion);
  // row()'s twin for every row (out of line: the usual row stays without a call).
  [[gnu::noinline]] void generalRow(int line, Motion motion, bool has_feed, double x, double y,
                                    double z, double cx, double cy, double cz, double feed);
  static void increment(LineMemo& m);
  char* writeAxes(char* p) const;
  // The rows are written at rows_end_ in a buffer of their own (a pointer to move instead of the
  // memory buffer's size and capacity to test twice a row, docs/performance.md §40) and go to
  // w_ once past kRowsFlush or at the end; the header stays in w_ before them.
  static constexpr size_t kRowsFlush = size_t{1} << 16;
  void allocateRows();
  // The rows (and what w_ holds before them) to the file; `sync`: flushed, as w_.flush().
  [[gnu::noinline]] void flushRows(bool sync = false);
  BufferedWriter w_;
  std::unique_ptr<char[]> rows_;
  char* rows_end_ = nullptr;
  char* rows_flush_ = nullptr;  // rows_.get() + kRowsFlush
  AxisColumns axes_;
  size_t axis_room_ = 0;  // characters the axis fields of a row may take
  Memo z_, feed_;         // generalRow's
  Memo zf_, feedf_;       // the usual row's: the fields with their comma (",49")
  TailMemo tail_;
  LineMemo line_;
};

// Puts the additional axes' names into a CSV header still in `w`'s buffer (false: the header
// was written already, or rows follow it).
bool extendCsvHeader(BufferedWriter& w, AxisColumns& axes, const std::vector<std::string>& names);

// The same columns with numbers of at most `decimals` (0..17) decimals (--decimals,
// shortest_number.hpp writeRounded). A class of its own: CsvWriter's row stays as it is.
class RoundedCsvWriter : public PathSink {
 public:
  RoundedCsvWriter(std::FILE* f, int decimals);
  void segment(const Segment& s) override;
  void finish(const Alarm* alarm) override;
  void axisNames(const std::vector<std::string>& names) override {
    extendCsvHeader(w_, axes_, names);
  }
  void axes(const AxesEvent& e) override { axes_.set(e); }

 private:
  BufferedWriter w_;
  AxisColumns axes_;
  int decimals_;
};

class JsonLinesWriter : public PathSink {
 public:
  JsonLinesWriter(std::FILE* f, FileNames names, int decimals = -1)
      : w_(f), names_(std::move(names)), decimals_(decimals) {}
  void segment(const Segment& s) override;
  void message(const SourceLoc& where, const std::string& text) override;
  void warning(const SourceLoc& where, int number, const std::string& text) override;
  // Events as records with a "type" field (docs/architecture.md "Events").
  bool wantsEvents() const override { return true; }
  void tool(const ToolEvent& e) override;
  void mFunction(const MFunctionEvent& e) override;
  void dwell(const DwellEvent& e) override;
  void spindle(const SpindleEvent& e) override;
  void feed(const FeedEvent& e) override;
  void frame(const FrameEvent& e) override;
  void finish(const Alarm* alarm) override;
  void axisNames(const std::vector<std::string>& names) override { axes_.announce(names); }
  void axes(const AxesEvent& e) override { axes_.set(e); }

 private:
  AxisColumns axes_;
  // `{"type":"<type>","line":L,"file":"F"` of an event record.
  void eventHead(const char* type, int line, int file);
  BufferedWriter w_;
  FileNames names_;
  int decimals_;
};

// Appends `s` as a JSON string literal.
void appendJsonString(fmt::memory_buffer& b, std::string_view s);

}  // namespace ncoffset::out
