// The compensated path as a SINUMERIK part program (PM-NC: G0/G1 linear, G2/G3 with the
// absolute centre I=AC(..) J=AC(..) K=AC(..), TURN= for helices; G17/G18/G19 working plane):
// run through ncoffset again, it gives the same path without frames, tools or compensation.
// A header comment says what the positions assume, then a block of reset words; in MCS every
// motion block has SUPA (docs/output-formats.md).
#pragma once

#include <cstdio>
#include <string>

#include "ncoffset/path.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

class MpfWriter : public PathSink {
 public:
  // coords: "mcs" or "wcs", named in the header comment. names: file names for a comment
  // where the source file of the blocks changes (may be empty: line numbers only). decimals:
  // of the numbers, 0..17, kShortest (shortest_number.hpp) for the default, 6.
  // diameter: the transverse axis arrives as diameter values (--diameter): the reset block
  // says DIAMON.
  MpfWriter(std::FILE* f, const std::string& coords, FileNames names = {}, int decimals = -1,
            bool diameter = false);
  void segment(const Segment& s) override;
  void message(const SourceLoc& where, const std::string& text) override;
  void warning(const SourceLoc& where, int number, const std::string& text) override;
  // `; ALARM N at FILE:LINE: TEXT`, M0 and M30, or M30. Later calls do nothing.
  void finish(const Alarm* alarm) override;
  // The additional axes: `A=90` words in every motion block (docs/output-formats.md).
  void axisNames(const std::vector<std::string>& names) override { axes_.announce(names); }
  void axes(const AxesEvent& e) override { axes_.set(e); }

 private:
  AxisColumns axes_;
  void block(const Segment& s, Motion motion, Vec3 end);
  void feedWord(const Segment& s);  // the F word, when it changed
  void threadLead(const Segment& s);
  void feedUnit(FeedUnit u);
  void source(const Segment& s);

  BufferedWriter w_;
  FileNames names_;
  bool mcs_;         // SUPA in every motion block
  int decimals_;     // of the numbers written
  long long n_ = 0;  // block number of the last block
  int file_ = -1;    // source file of the last block
  int plane_ = -1;   // applicate axis of the last plane written (2: G17, 1: G18, 0: G19)
  bool has_feed_ = false;
  double feed_ = 0;                     // the last F written
  FeedUnit unit_ = FeedUnit::MmPerMin;  // of the last F written (the header writes G94)
  bool finished_ = false;
};

// `v` with at most `decimals` decimals and no trailing zeros ("-0" as "0"), never with an
// exponent.
void appendNcNumber(fmt::memory_buffer& b, double v, int decimals = 6);

// The header of the program for coords "mcs" or "wcs": comment lines and the reset block.
std::string mpfHeader(const std::string& coords, bool diameter = false);

}  // namespace ncoffset::out
