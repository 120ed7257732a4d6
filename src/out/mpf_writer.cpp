#include "out/mpf_writer.hpp"

#include <cmath>

#include "out/arc_geometry.hpp"

namespace ncoffset::out {
namespace {

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

// A comment runs to the end of the line: no line breaks in it.
void appendCommentText(fmt::memory_buffer& b, std::string_view s) {
  for (char c : s) b.push_back(c == '\n' || c == '\r' ? ' ' : c);
}

constexpr double kPi = 3.14159265358979323846;
const char* const kPlaneCode[3] = {"G19", "G18", "G17"};  // by applicate axis X, Y, Z

}  // namespace

void appendNcNumber(fmt::memory_buffer& b, double v) {
  char text[512];
  auto r = fmt::format_to_n(text, sizeof text, "{:.6f}", v);
  std::string_view s(text, std::min(r.size, sizeof text));
  if (s.find('.') != std::string_view::npos) {
    while (s.back() == '0') s.remove_suffix(1);
    if (s.back() == '.') s.remove_suffix(1);
  }
  if (s == "-0") s = "0";
  append(b, s);
}

MpfWriter::MpfWriter(std::FILE* f, const std::string& coords, FileNames names)
    : w_(f), names_(std::move(names)) {
  fmt::format_to(fmt::appender(w_.buf()),
                 "; ncoffset compensated path (coords {})\n"
                 "G90 G71 ; absolute, mm\n",
                 coords);
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
  fmt::format_to(fmt::appender(b), "N{} {}", ++n_, motionName(motion));
  const char* axis[3] = {" X", " Y", " Z"};
  for (int i = 0; i < 3; ++i) {
    append(b, axis[i]);
    appendNcNumber(b, end[i]);
  }
  if (motion == Motion::G2 || motion == Motion::G3) {
    // The centre in the plane's two axes, absolute; the applicate travel is in the end point.
    const char* centre[3] = {" I=AC(", " J=AC(", " K=AC("};
    for (int i = 0; i < 3; ++i) {
      if (i == plane_) continue;
      append(b, centre[i]);
      appendNcNumber(b, s.centre[i]);
      b.push_back(')');
    }
    if (s.turns > 0) fmt::format_to(fmt::appender(b), " TURN={}", s.turns);
  }
  if (motion != Motion::G0) feed(s);
  source(s);
  w_.lineDone();
}

void MpfWriter::feed(const Segment& s) {
  if (!s.has_feed || (has_feed_ && s.feed == feed_)) return;
  append(w_.buf(), " F");
  appendNcNumber(w_.buf(), s.feed);
  has_feed_ = true;
  feed_ = s.feed;
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
    append(b, "\nM0\n");
  } else {
    append(b, "M30\n");
  }
  w_.flush();
}

}  // namespace ncoffset::out
