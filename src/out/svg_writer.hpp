// SVG drawing of the path projected on a working plane (G17 XY, G18 ZX, G19 YZ): the
// programmed path thin grey dashed, the compensated path by motion, arcs as SVG arcs where
// they lie in the view plane. Memory stays flat in program length: the drawing goes to
// temporary files while the bounding box is tracked; finish() writes the header with the
// viewBox and copies the drawing behind it.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "ncoffset/path.hpp"
#include "out/arc_geometry.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

// The plane the path is projected on, named after its abscissa and ordinate: XY (G17, seen
// from +Z), ZX (G18: Z to the right, X up, seen from +Y), YZ (G19: Y right, Z up, from +X).
enum class View { XY, ZX, YZ };
// "xy", "zx", "yz" (lower case); anything else is XY.
View viewFromName(std::string_view name);

// Appends `s` escaped for XML and HTML text and attribute values: & < > " ' as references,
// control characters as spaces, bytes that are no valid UTF-8 as U+FFFD.
void appendXmlEscaped(fmt::memory_buffer& b, std::string_view s);

class SvgWriter : public PathSink {
 public:
  // standalone: a whole SVG file (XML declaration); otherwise the bare <svg> element, for
  // inlining into HTML. decimals: of the path's coordinates (--decimals; -1: the shortest
  // round-trip text); the layout (viewBox, legend) is not rounded.
  SvgWriter(std::FILE* f, View view, bool standalone = true, int decimals = -1);
  ~SvgWriter() override;
  void segment(const Segment& s) override;
  void programmed(const Segment& s) override;
  bool wantsProgrammed() const override { return true; }
  // The run's start position is assumed (RunOptions::start not given): the move from it to the
  // first segment's end is not drawn, and only that end is in the viewBox (docs/output-formats.md
  // "Start position").
  void leaveOutFirstMove() { skip_path_ = skip_programmed_ = true; }
  // Writes the drawing; an alarm is marked at the last end point. Later calls do nothing.
  void finish(const Alarm* alarm) override;

 private:
  class Layer;
  struct Layout {
    double size, vx, vw;  // drawing size; left edge and width of the viewBox
  };
  Layout writeHeader(const Alarm* alarm);
  void writeAlarmMark(const Alarm& alarm, const Layout& l);

  BufferedWriter w_;
  View view_;
  bool standalone_;
  int decimals_;
  bool finished_ = false;
  bool threads_ = false;  // a thread or tapping line was drawn (its legend row)
  bool skip_path_ = false, skip_programmed_ = false;  // leaveOutFirstMove(), until the first
  std::unique_ptr<Layer> programmed_, path_;
  Box box_;
  Vec3 last_end_;  // where the path stands (machine zero before the first segment)
};

}  // namespace ncoffset::out
