#include "out/mpf_writer.hpp"

#include <cmath>

#include "out/arc_geometry.hpp"
#include "out/shortest_number.hpp"

namespace ncoffset::out {
namespace {

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

// A comment runs to the end of the line: no line breaks in it.
void appendCommentText(fmt::memory_buffer& b, std::string_view s) {
  for (char c : s) b.push_back(c == '\n' || c == '\r' ? ' ' : c);
}

const char* const kPlaneCode[3] = {"G19", "G18", "G17"};  // by applicate axis X, Y, Z

}  // namespace

void appendNcNumber(fmt::memory_buffer& b, double v, int decimals) {
  char text[512];  // |v| < 1e308: 309 digits, sign, point, 17 decimals
  const double a = std::fabs(v);
  const char* end = a < 1e15 ? writeRounded(text, v, decimals)
                             : writeFixedDecimals(text, sizeof text, v, decimals);
  b.append(text, end);
}

std::string mpfHeader(const std::string& coords, bool diameter) {
  const bool mcs = coords == "mcs";
  std::string h = "; ncoffset compensated path (coords " + coords + ")\n";
  if (mcs) {
    h += "; Positions: machine coordinates (MCS) of the tool carrier reference point. Every\n"
         ";   motion block has SUPA: no frame, zero offset, DRF or PRESET offset shifts it.\n"
         "; Already in the positions: the frames (G54.., TRANS, ROT, SCALE, MIRROR), the tool\n"
         ";   length and the radius compensation (G41/G42) of the source program: D0, G40.\n";
  } else {
    h += "; Positions: workpiece coordinates (WCS) of the tool tip.\n"
         "; Already in the positions: the radius compensation (G41/G42) of the source program.\n"
         "; Not in the positions: frames and tool length. Select the zero offset, frames and\n"
         ";   tool (T, D) of the source program before running this; frame or tool changes\n"
         ";   inside the source program are not repeated here.\n";
  }
  h += "; G90 absolute, G71 mm, G94 mm/min: F as programmed; G95 (mm/rev) or G93 (inverse\n"
       ";   time) is written before a feed the source programmed so (G95/G96/G97, G93). Arcs:\n"
       ";   the plane (G17/G18/G19) is written before them, centres absolute (I=AC J=AC K=AC).\n"
       ";   Each block names its source line.\n";
  if (diameter)
    h += "; DIAMON: the transverse axis (MD20100 $MC_DIAMETER_AX_DEF, to be set as in the source)\n"
         ";   is written as diameter values, its absolute centre too (docs/turning.md).\n";
  h += mcs ? "G90 G71 G94 G40 G17 D0 ; reset: absolute, mm, mm/min, no radius compensation, "
             "XY plane, no tool offset\n"
           : "G90 G71 G94 G40 G17 ; reset: absolute, mm, mm/min, no radius compensation, XY "
             "plane\n";
  if (diameter) h += "DIAMON ; the transverse axis in diameter\n";
  return h;
}

MpfWriter::MpfWriter(std::FILE* f, const std::string& coords, FileNames names, int decimals,
                     bool diameter)
    : w_(f),
      names_(std::move(names)),
      mcs_(coords == "mcs"),
      decimals_(decimals < 0 ? 6 : decimals) {
  const std::string h = mpfHeader(coords, diameter);
  w_.buf().append(h.data(), h.data() + h.size());
}

void MpfWriter::segment(const Segment& s) {
  if (finished_) return;
  if (!isArc(s)) {
    block(s, s.motion, s.end);
    return;
  }
  // The plane from the normal's dominant axis; the sense as seen from its positive end.
  int ax = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(s.normal[i]) > std::fabs(s.normal[ax])) ax = i;
  double len = norm(s.normal);
  const bool tilted = !(len > 0) || std::fabs(s.normal[ax]) / len < 1 - 1e-9;
  if (tilted || !s.has_feed) {
    // About a tilted axis (a frame rotating the plane, output in MCS), or at rapid traverse (the
    // corner circle of a G0 block under radius compensation): no G2/G3 can say it; G1 / G0
    // chords of at most one degree.
    ArcGeometry g = arcGeometry(s);
    int chords = std::max(1, static_cast<int>(std::ceil(std::fabs(g.sweep) / (kPi / 180) - 1e-9)));
    fmt::format_to(fmt::appender(w_.buf()), "; {} {}: {} chords\n", motionName(s.motion),
                   tilted ? "about a tilted axis" : "at rapid traverse", chords);
    for (int i = 1; i <= chords; ++i)
      block(s, s.has_feed ? Motion::G1 : Motion::G0,
            i == chords ? s.end : g.at(static_cast<double>(i) / chords));
    return;
  }
  Motion m = s.motion;
  if (s.normal[ax] < 0) m = m == Motion::G2 ? Motion::G3 : Motion::G2;
  if (ax != plane_) {
    fmt::format_to(fmt::appender(w_.buf()), "{}\n", kPlaneCode[ax]);
    plane_ = ax;
  }
  block(s, m, s.end);
}

void MpfWriter::block(const Segment& s, Motion motion, Vec3 end) {
  auto& b = w_.buf();
  if (s.file != file_ && names_) {  // the source file of the following blocks' line numbers
    append(b, "; file ");
    appendCommentText(b, names_(s.file));
    b.push_back('\n');
  }
  file_ = s.file;
  const bool thread = isThreadMotion(motion) && motion != Motion::G63;
  if (motion != Motion::G0 && !thread && s.has_feed && s.feed_unit != unit_) feedUnit(s.feed_unit);
  // G63 is no motion of its own (group 2): the block is a G1 line with G63.
  fmt::format_to(fmt::appender(b), "N{} {}", ++n_,
                 motion == Motion::G63 ? "G1 G63" : motionName(motion));
  if (mcs_) append(b, " SUPA");
  const char* axis[3] = {" X", " Y", " Z"};
  for (int i = 0; i < 3; ++i) {
    append(b, axis[i]);
    appendNcNumber(b, end[i], decimals_);
  }
  for (size_t k = 0; k < axes_.names.size(); ++k) {  // the additional axes
    fmt::format_to(fmt::appender(b), " {}=", axes_.names[k]);
    appendNcNumber(b, axes_.positions[k], decimals_);
  }
  if (motion == Motion::G2 || motion == Motion::G3) {
    // The centre in the plane's two axes, absolute; the applicate travel is in the end point.
    const char* centre[3] = {" I=AC(", " J=AC(", " K=AC("};
    for (int i = 0; i < 3; ++i) {
      if (i == plane_) continue;
      append(b, centre[i]);
      appendNcNumber(b, s.centre[i], decimals_);
      b.push_back(')');
    }
    if (s.turns > 0) fmt::format_to(fmt::appender(b), " TURN={}", s.turns);
  }
  if (thread)
    threadLead(s);
  else if (motion != Motion::G0)
    feedWord(s);
  source(s);
  w_.lineDone();
}

// A thread line: the lead (the segment's feed, mm/rev) at the address of the axis with the
// longest path (PM-NC "G33": I, J, K for X, Y, Z; a taper thread's lead is that of its longer
// axis); G34/G35 write the lead change as F, which is the modal F from then on.
void MpfWriter::threadLead(const Segment& s) {
  int ax = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(s.end[i] - s.start[i]) > std::fabs(s.end[ax] - s.start[ax])) ax = i;
  const char* lead[3] = {" I", " J", " K"};
  append(w_.buf(), lead[ax]);
  appendNcNumber(w_.buf(), s.feed, decimals_);
  if (s.motion == Motion::G34 || s.motion == Motion::G35) {
    append(w_.buf(), " F");
    appendNcNumber(w_.buf(), s.lead_change, decimals_);
    has_feed_ = true;
    feed_ = s.lead_change;
  }
}

void MpfWriter::feedWord(const Segment& s) {
  if (!s.has_feed || (has_feed_ && s.feed == feed_)) return;
  append(w_.buf(), " F");
  appendNcNumber(w_.buf(), s.feed, decimals_);
  has_feed_ = true;
  feed_ = s.feed;
}

// G93 / G94 / G95 in a block of its own before the first feed of another unit; the F that
// follows is written again (its meaning changed).
void MpfWriter::feedUnit(FeedUnit u) {
  const char* code = u == FeedUnit::MmPerRev ? "G95" : u == FeedUnit::InverseTime ? "G93" : "G94";
  fmt::format_to(fmt::appender(w_.buf()), "{} ; feed in {}\n", code, feedUnitName(u));
  unit_ = u;
  has_feed_ = false;
}

void MpfWriter::source(const Segment& s) {
  fmt::format_to(fmt::appender(w_.buf()), " ; line {}\n", s.line);
}

void MpfWriter::message(const SourceLoc& where, const std::string& text) {
  if (finished_) return;
  auto& b = w_.buf();
  append(b, "; MSG: ");
  appendCommentText(b, text);
  append(b, " (");
  appendCommentText(b, where.file);
  fmt::format_to(fmt::appender(b), ":{})\n", where.line);
  w_.lineDone();
}

void MpfWriter::warning(const SourceLoc& where, int number, const std::string& text) {
  if (finished_) return;
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "; warning {}: ", number);
  appendCommentText(b, text);
  append(b, " (");
  appendCommentText(b, where.file);
  fmt::format_to(fmt::appender(b), ":{})\n", where.line);
  w_.lineDone();
}

void MpfWriter::finish(const Alarm* alarm) {
  if (finished_) return;
  finished_ = true;
  auto& b = w_.buf();
  if (alarm) {
    fmt::format_to(fmt::appender(b), "; ALARM {} at ", alarm->number);
    appendCommentText(b, alarm->where.file);
    fmt::format_to(fmt::appender(b), ":{}: ", alarm->where.line);
    appendCommentText(b, alarm->text);
    append(b, "\nM0 ; incomplete: the source program stopped at the alarm above\nM30\n");
  } else {
    append(b, "M30\n");
  }
  w_.flush();
}

}  // namespace ncoffset::out
