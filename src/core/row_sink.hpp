// The placement's short way to a sink that reads only a few fields of a segment (the CSV
// writer): those fields handed over in registers, no 144-byte Segment built in memory and read
// back (docs/architecture.md "The row hand-over", docs/performance.md §49).
#pragma once

#include "ncoffset/path.hpp"

namespace ncoffset::core {

// A PathSink that is also a RowSink reads of a segment only the line, the motion, the end
// point, the centre (arcs only), the feed and whether it has one, and promises: row(line, motion,
// has_feed, end, centre, feed) writes exactly what segment(s) writes for every Segment s with those
// fields (whatever its other fields, and whatever `centre` is for a line). Its segment() must not
// be overridden by a derived class (make it final). Placement (src/place) finds the interface once
// a run (dynamic_cast at beginRun) and uses it only while the segment would go straight to that
// sink (the sink switch's bypass, nothing waiting) and the segment needs no rejoin; every other
// segment goes to segment() as before (the twin: tests/place/placement_rows_test.cpp).
class RowSink {
 public:
  // (Scalars, not a struct by reference: all ten arguments in registers.)
  virtual void row(int line, Motion motion, bool has_feed, double x, double y, double z, double cx,
                   double cy, double cz, double feed) = 0;

 protected:
  ~RowSink() = default;
};

}  // namespace ncoffset::core
