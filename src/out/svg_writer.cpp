#include "out/svg_writer.hpp"

#include <algorithm>
#include <cmath>

#include "out/shortest_number.hpp"

namespace ncoffset::out {
namespace {
constexpr double kChordStep = kPi / 180;  // polylines: chords of at most 1 degree
constexpr int kCommandsPerElement = 512;  // a new <path> now and then keeps lines short

// The view plane: abscissa and ordinate axes and the normal the drawing is seen from
// (planeAxes of G17/G18/G19, W1 2.1).
struct Projection {
  int h, v;
  Vec3 normal;
};

Projection projection(View view) {
  switch (view) {
    case View::XY:
      return {0, 1, {0, 0, 1}};
    case View::ZX:
      return {2, 0, {0, 1, 0}};
    case View::YZ:
      return {1, 2, {1, 0, 0}};
  }
  return {0, 1, {0, 0, 1}};
}

const char* viewLegend(View view) {
  switch (view) {
    case View::XY:
      return "view XY (G17): X right, Y up";
    case View::ZX:
      return "view ZX (G18): Z right, X up";
    case View::YZ:
      return "view YZ (G19): Y right, Z up";
  }
  return "";
}

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

// The SVG user coordinates of a point: y grows downwards, so the ordinate is negated.
struct Pt {
  double x, y;
};
Pt toSvg(const Projection& p, Vec3 q) {
  return {q[p.h] + 0.0, -q[p.v] + 0.0};
}
// The same point up to rounding (a segment starts where the previous one ended).
bool near(Pt a, Pt b) {
  auto close = [](double u, double v) {
    return std::fabs(u - v) <= 1e-9 * std::max(1.0, std::max(std::fabs(u), std::fabs(v)));
  };
  return close(a.x, b.x) && close(a.y, b.y);
}

}  // namespace

View viewFromName(std::string_view name) {
  if (name == "zx") return View::ZX;
  if (name == "yz") return View::YZ;
  return View::XY;
}

void appendXmlEscaped(fmt::memory_buffer& b, std::string_view s) {
  size_t i = 0;
  while (i < s.size()) {
    auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      switch (c) {
        case '&':
          append(b, "&amp;");
          break;
        case '<':
          append(b, "&lt;");
          break;
        case '>':
          append(b, "&gt;");
          break;
        case '"':
          append(b, "&quot;");
          break;
        case '\'':
          append(b, "&#39;");
          break;
        default:
          b.push_back(c < 0x20 && c != '\t' && c != '\n' && c != '\r' ? ' ' : s[i]);
      }
      ++i;
      continue;
    }
    // A UTF-8 sequence passes whole; anything else becomes U+FFFD (XML needs valid text).
    size_t len = c >= 0xC2 && c <= 0xDF   ? 2
                 : c >= 0xE0 && c <= 0xEF ? 3
                 : c >= 0xF0 && c <= 0xF4 ? 4
                                          : 0;
    bool ok = len > 0 && i + len <= s.size();
    for (size_t k = 1; ok && k < len; ++k)
      ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
    if (ok) {
      auto c1 = static_cast<unsigned char>(s[i + 1]);
      if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0) || (c == 0xF0 && c1 < 0x90) ||
          (c == 0xF4 && c1 >= 0x90))
        ok = false;  // overlong, surrogate or beyond U+10FFFF
    }
    if (ok) {
      append(b, s.substr(i, len));
      i += len;
    } else {
      append(b, "\xEF\xBF\xBD");
      ++i;
    }
  }
}

// One drawing layer (programmed or compensated path): <path> elements, consecutive segments
// of one style joined into one element. Spills to a temporary file (std::tmpfile) once the
// buffer is large; without one it stays in memory.
class SvgWriter::Layer {
 public:
  Layer(Projection p, int decimals) : proj_(p), decimals_(decimals), tmp_(std::tmpfile()) {}
  ~Layer() {
    if (tmp_) std::fclose(tmp_);
  }
  Layer(const Layer&) = delete;
  Layer& operator=(const Layer&) = delete;

  void draw(const Segment& s, const char* cls) {
    Pt a = toSvg(proj_, s.start);
    if (cls != cls_ || !near(a, pen_) || commands_ >= kCommandsPerElement) {
      close();
      fmt::format_to(fmt::appender(buf_),
                     "<path class=\"{}\" vector-effect=\"non-scaling-stroke\" d=\"M{} {}", cls,
                     num(a.x), num(a.y));
      cls_ = cls;
    }
    if (isArc(s))
      arc(s);
    else
      lineTo(toSvg(proj_, s.end));
    pen_ = toSvg(proj_, s.end);
    if (buf_.size() >= 1 << 16) spill();
  }

  void close() {
    if (!cls_) return;
    append(buf_, "\"/>\n");
    cls_ = nullptr;
    commands_ = 0;
  }

  void copyTo(BufferedWriter& out) {
    close();
    if (tmp_) {
      spill();
      std::rewind(tmp_);
      char chunk[1 << 14];
      size_t n;
      while ((n = std::fread(chunk, 1, sizeof chunk, tmp_)) > 0) {
        out.buf().append(chunk, chunk + n);
        out.lineDone();
      }
    }
    out.buf().append(buf_.data(), buf_.data() + buf_.size());
    buf_.clear();
  }

 private:
  void lineTo(Pt p) {
    fmt::format_to(fmt::appender(buf_), "L{} {}", num(p.x), num(p.y));
    ++commands_;
  }

  // In the view plane: SVG elliptical-arc commands (a circle: rx = ry). A full circle and
  // TURN= turns need several, each less than a full circle. Otherwise (an arc about another
  // axis, seen from the side, or its helix): chords of at most one degree.
  void arc(const Segment& s) {
    ArcGeometry g = arcGeometry(s);
    double facing = dot(g.n, proj_.normal);
    double total = std::fabs(g.sweep);
    if (std::fabs(facing) > 1 - 1e-9) {
      // Counter-clockwise seen from the viewer (x right, y up) is the negative angle sense of
      // SVG once y points down: sweep-flag 0.
      bool ccw = (g.sweep > 0) == (facing > 0);
      int pieces = total <= 1.9 * kPi ? 1 : static_cast<int>(std::ceil(total / (0.9 * kPi)));
      bool large = pieces == 1 && total > kPi;
      for (int i = 1; i <= pieces; ++i) {
        Pt p = toSvg(proj_, i == pieces ? s.end : g.at(static_cast<double>(i) / pieces));
        fmt::format_to(fmt::appender(buf_), "A{} {} 0 {} {} {} {}", num(g.radius), num(g.radius),
                       large ? 1 : 0, ccw ? 0 : 1, num(p.x), num(p.y));
        ++commands_;
      }
      return;
    }
    int chords = std::max(1, static_cast<int>(std::ceil(total / kChordStep - 1e-9)));
    for (int i = 1; i < chords; ++i) lineTo(toSvg(proj_, g.at(static_cast<double>(i) / chords)));
    lineTo(toSvg(proj_, s.end));
  }

  void spill() {
    if (!tmp_ || !buf_.size()) return;
    std::fwrite(buf_.data(), 1, buf_.size(), tmp_);
    buf_.clear();
  }

  Number num(double v) const { return {v, decimals_}; }

  Projection proj_;
  int decimals_;
  std::FILE* tmp_;
  fmt::memory_buffer buf_;
  const char* cls_ = nullptr;  // the style of the open <path>, nullptr: none open
  Pt pen_{0, 0};
  int commands_ = 0;
};

SvgWriter::SvgWriter(std::FILE* f, View view, bool standalone, int decimals)
    : w_(f),
      view_(view),
      standalone_(standalone),
      decimals_(decimals),
      programmed_(std::make_unique<Layer>(projection(view), decimals)),
      path_(std::make_unique<Layer>(projection(view), decimals)) {}

SvgWriter::~SvgWriter() = default;

void SvgWriter::segment(const Segment& s) {
  if (finished_) return;
  last_end_ = s.end;
  if (skip_path_) [[unlikely]] {  // from an assumed start position: only where it ends
    skip_path_ = false;
    box_.add(s.end);
    return;
  }
  box_.add(s);
  // Rapid traverse: G0, and the corner circle of a G0 block under radius compensation.
  // Thread and tapping lines (G33..G63) in a style of their own (docs/threads.md).
  const bool thread = isThreadMotion(s.motion);
  threads_ |= thread;
  path_->draw(s, thread ? "nco-thread" : s.has_feed ? "nco-cut" : "nco-g0");
}

void SvgWriter::programmed(const Segment& s) {
  if (finished_) return;
  if (skip_programmed_) [[unlikely]] {
    skip_programmed_ = false;
    box_.add(s.end);
    return;
  }
  box_.add(s);
  programmed_->draw(s, "nco-prog");
}

void SvgWriter::finish(const Alarm* alarm) {
  if (finished_) return;
  finished_ = true;
  if (alarm || box_.empty()) box_.add(last_end_);
  Layout layout = writeHeader(alarm);
  auto& b = w_.buf();
  append(b, "<g id=\"programmed\">\n");
  programmed_->copyTo(w_);
  append(b, "</g>\n<g id=\"path\">\n");
  path_->copyTo(w_);
  append(b, "</g>\n");
  if (alarm) writeAlarmMark(*alarm, layout);
  append(b, "</svg>\n");
  w_.flush();
}

// The viewBox is the drawing's bounding box with a margin and a band below it for the
// legend; legend, mark and text are sized from the drawing (they scale with it, the strokes
// do not), so small and huge parts look alike.
SvgWriter::Layout SvgWriter::writeHeader(const Alarm* alarm) {
  const Projection p = projection(view_);
  double x0 = box_.lo[p.h], x1 = box_.hi[p.h];
  double y0 = -box_.hi[p.v], y1 = -box_.lo[p.v];  // SVG y of the top and bottom edge
  double size = std::max(x1 - x0, y1 - y0);
  if (!(size > 0)) size = 1;
  const double margin = 0.05 * size, font = 0.03 * size, row = 1.4 * font;
  const int rows = (alarm ? 5 : 4) + (threads_ ? 1 : 0);
  double vx = x0 - margin, vy = y0 - margin;
  double vw = x1 - x0 + 2 * margin, vh = y1 - y0 + 2 * margin + (rows + 0.5) * row;
  if (vw < 0.8 * size) {  // room for the legend beside a narrow drawing
    vx -= (0.8 * size - vw) / 2;
    vw = 0.8 * size;
  }
  double px = 800 / std::max(vw, vh);
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  if (standalone_) append(b, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  fmt::format_to(it,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{}\" "
                 "height=\"{}\" viewBox=\"{} {} {} {}\">\n",
                 std::round(vw * px), std::round(vh * px), vx, vy, vw, vh);
  fmt::format_to(it, "<title>ncoffset path, {}</title>\n", viewLegend(view_));
  append(b,
         "<style>\n"
         ".nco-prog{fill:none;stroke:#999;stroke-width:1;stroke-dasharray:4 3}\n"
         ".nco-g0{fill:none;stroke:#d9534f;stroke-width:1;stroke-dasharray:6 4}\n"
         ".nco-cut{fill:none;stroke:#1f5fbf;stroke-width:1.5;stroke-linejoin:round}\n"
         ".nco-thread{fill:none;stroke:#2e8b3e;stroke-width:2;stroke-dasharray:2 2}\n"
         ".nco-alarm{fill:none;stroke:#e00000;stroke-width:2}\n"
         ".nco-legend{font-family:sans-serif;fill:#333}\n"
         "</style>\n");
  // Legend: sample strokes and their meaning, the view, the alarm mark.
  double lx = vx + margin, ly = y1 + margin;
  struct Entry {
    const char* cls;
    const char* text;
  };
  const Entry entries[] = {{"nco-prog", "programmed path (no radius compensation)"},
                           {"nco-g0", "G0 rapid traverse"},
                           {"nco-cut", "G1/G2/G3 compensated path"},
                           {"nco-thread", "G33/G34/G35/G331/G332/G63 thread or tapping"}};
  append(b, "<g id=\"legend\">\n");
  int r = 0;
  for (const Entry& e : entries) {
    if (!threads_ && e.cls == entries[3].cls) continue;  // the thread row where there are any
    double y = ly + (++r) * row;
    fmt::format_to(it,
                   "<path class=\"{}\" vector-effect=\"non-scaling-stroke\" d=\"M{} {}h{}\"/>"
                   "<text class=\"nco-legend\" x=\"{}\" y=\"{}\" font-size=\"{}\">{}</text>\n",
                   e.cls, lx, y - 0.35 * font, 2 * font, lx + 2.6 * font, y, font, e.text);
  }
  fmt::format_to(it, "<text class=\"nco-legend\" x=\"{}\" y=\"{}\" font-size=\"{}\">{}</text>\n",
                 lx, ly + (++r) * row, font, viewLegend(view_));
  if (alarm) {
    double y = ly + (++r) * row;
    fmt::format_to(it,
                   "<circle class=\"nco-alarm\" vector-effect=\"non-scaling-stroke\" cx=\"{}\" "
                   "cy=\"{}\" r=\"{}\"/><text class=\"nco-legend\" x=\"{}\" y=\"{}\" "
                   "font-size=\"{}\">where alarm {} stopped the run</text>\n",
                   lx + font, y - 0.35 * font, 0.4 * font, lx + 2.6 * font, y, font, alarm->number);
  }
  append(b, "</g>\n");
  w_.lineDone();
  return {size, vx, vw};
}

// A circle where the path stands, with the alarm as its title (tooltip) and its number beside.
void SvgWriter::writeAlarmMark(const Alarm& alarm, const Layout& l) {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  Pt at = toSvg(projection(view_), last_end_);
  bool right = at.x > l.vx + l.vw / 2;
  fmt::format_to(it,
                 "<g id=\"alarm\"><circle class=\"nco-alarm\" vector-effect=\"non-scaling-stroke\" "
                 "cx=\"{}\" cy=\"{}\" r=\"{}\"><title>alarm {} at ",
                 Number{at.x, decimals_}, Number{at.y, decimals_}, 0.02 * l.size, alarm.number);
  appendXmlEscaped(b, alarm.where.file);
  fmt::format_to(it, ":{}: ", alarm.where.line);
  appendXmlEscaped(b, alarm.text);
  fmt::format_to(it,
                 "</title></circle><text class=\"nco-legend\" x=\"{}\" y=\"{}\" font-size=\"{}\" "
                 "text-anchor=\"{}\">alarm {}</text></g>\n",
                 right ? at.x - 0.03 * l.size : at.x + 0.03 * l.size, at.y - 0.03 * l.size,
                 0.03 * l.size, right ? "end" : "start", alarm.number);
}

}  // namespace ncoffset::out
