// SVG drawing (src/out/svg_writer.hpp): projection on G17/G18/G19 views, SVG arcs with the
// right sense after the y flip, polylines for arcs seen from the side, the viewBox, the alarm.
#include "out/svg_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::arcSeg;
using test::File;
using test::lineSeg;
using test::makeAlarm;
using test::readAll;

std::string draw(View view, const std::vector<Segment>& path, const Alarm* alarm = nullptr,
                 const std::vector<Segment>& programmed = {}) {
  File f(std::tmpfile());
  EXPECT_TRUE(f);
  {
    SvgWriter w(f.get(), view);
    EXPECT_TRUE(w.wantsProgrammed());
    for (const auto& s : programmed) w.programmed(s);
    for (const auto& s : path) w.segment(s);
    w.finish(alarm);
  }
  return readAll(f.get());
}

// The d attributes of the <path> elements of one group (id="path" or id="programmed").
std::vector<std::string> pathData(const std::string& svg, const std::string& group = "path") {
  std::vector<std::string> out;
  size_t g = svg.find("<g id=\"" + group + "\">");
  size_t end = svg.find("</g>", g);
  for (size_t i = svg.find(" d=\"", g); i < end; i = svg.find(" d=\"", i)) {
    i += 4;
    out.push_back(svg.substr(i, svg.find('"', i) - i));
  }
  return out;
}

struct ViewBox {
  double x = 0, y = 0, w = 0, h = 0;
  // Contains the SVG point of (h, v) in view coordinates (y flipped).
  bool covers(double h, double v) const {
    double sy = -v;
    return h >= x && h <= x + w && sy >= y && sy <= y + this->h;
  }
};

ViewBox viewBox(const std::string& svg) {
  ViewBox b;
  size_t i = svg.find("viewBox=\"");
  EXPECT_NE(i, std::string::npos);
  std::istringstream is(svg.substr(i + 9));
  is >> b.x >> b.y >> b.w >> b.h;
  return b;
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

const Vec3 kZ{0, 0, 1}, kY{0, 1, 0}, kX{1, 0, 0};

TEST(SvgWriter, LineIsWellFormedWithHeaderLegendAndNonScalingStrokes) {
  std::string svg = draw(View::XY, {lineSeg(1, Motion::G0, {0, 0, 5}, {10, 5, 5}),
                                    lineSeg(2, Motion::G1, {10, 5, 5}, {20, 5, 0}, 100)});
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u) << svg;
  EXPECT_EQ(test::tagBalance(svg), "") << svg;
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_NE(svg.find("<g id=\"legend\">"), std::string::npos);
  EXPECT_NE(svg.find("view XY (G17): X right, Y up"), std::string::npos);
  // y points down in SVG: Y5 is at -5.
  auto d = pathData(svg);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], "M0 0L10 -5");
  EXPECT_EQ(d[1], "M10 -5L20 -5");
  EXPECT_NE(svg.find("<path class=\"nco-g0\" vector-effect=\"non-scaling-stroke\""),
            std::string::npos);
  EXPECT_NE(svg.find("<path class=\"nco-cut\" vector-effect=\"non-scaling-stroke\""),
            std::string::npos);
  // Every <path> and <circle> has a non-scaling stroke.
  EXPECT_EQ(count(svg, "<path "), count(svg, "<path class=\"nco-"));
  EXPECT_EQ(count(svg, "<path "), count(svg, "vector-effect=\"non-scaling-stroke\""));
}

TEST(SvgWriter, ConsecutiveSegmentsOfOneStyleShareAnElement) {
  std::string svg = draw(View::XY, {lineSeg(1, Motion::G1, {0, 0, 0}, {1, 0, 0}, 5),
                                    lineSeg(2, Motion::G1, {1, 0, 0}, {1, 1, 0}, 5),
                                    lineSeg(3, Motion::G1, {1, 1, 0}, {0, 1, 0}, 5)});
  auto d = pathData(svg);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "M0 0L1 0L1 -1L0 -1");
}

// A circle at rapid traverse (a G0 block's corner circle: no feed) is drawn like G0.
TEST(SvgWriter, RapidArcIsDrawnAsRapid) {
  Segment rapid = arcSeg(2, Motion::G3, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, kZ);
  rapid.has_feed = false;
  std::string svg = draw(View::XY, {lineSeg(1, Motion::G1, {0, 0, 0}, {1, 0, 0}, 5), rapid,
                                    lineSeg(3, Motion::G0, {0, 1, 0}, {0, 5, 0})});
  EXPECT_NE(svg.find("class=\"nco-g0\" vector-effect=\"non-scaling-stroke\" d=\"M1 0A1 1 0 0 0 "
                     "0 -1L0 -5\""),
            std::string::npos)
      << svg;
}

// G3 is counter-clockwise seen from +Z; with y down in SVG that is sweep-flag 0.
TEST(SvgWriter, ArcFlagsG17AfterTheYFlip) {
  std::string g3 = draw(View::XY, {arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, kZ)});
  EXPECT_EQ(pathData(g3), std::vector<std::string>{"M10 0A10 10 0 0 0 0 -10"});
  // G2 the same way round is the long way: large-arc 1, sweep 1.
  std::string g2 = draw(View::XY, {arcSeg(1, Motion::G2, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, kZ)});
  EXPECT_EQ(pathData(g2), std::vector<std::string>{"M10 0A10 10 0 1 1 0 -10"});
  // The viewBox covers the arc, not only its end points: G2 passes (0,-10) and (-10,0).
  ViewBox b = viewBox(g2);
  EXPECT_TRUE(b.covers(0, -10) && b.covers(-10, 0) && b.covers(10, 0) && b.covers(0, 10));
  // A normal along -Z reverses the sense: G2 seen from -Z is G3 seen from +Z.
  std::string neg =
      draw(View::XY, {arcSeg(1, Motion::G2, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, {0, 0, -1})});
  EXPECT_EQ(pathData(neg), std::vector<std::string>{"M10 0A10 10 0 0 0 0 -10"});
}

// G18: Z to the right, X up, seen from +Y; G19: Y right, Z up, seen from +X.
TEST(SvgWriter, ArcFlagsG18AndG19) {
  std::string g18 = draw(View::ZX, {arcSeg(1, Motion::G3, {0, 0, 10}, {10, 0, 0}, {0, 0, 0}, kY)});
  EXPECT_EQ(pathData(g18), std::vector<std::string>{"M10 0A10 10 0 0 0 0 -10"});
  std::string g18cw =
      draw(View::ZX, {arcSeg(1, Motion::G2, {10, 0, 0}, {0, 0, 10}, {0, 0, 0}, kY)});
  EXPECT_EQ(pathData(g18cw), std::vector<std::string>{"M0 -10A10 10 0 0 1 10 0"});
  EXPECT_NE(g18.find("view ZX (G18): Z right, X up"), std::string::npos);
  std::string g19 = draw(View::YZ, {arcSeg(1, Motion::G3, {0, 10, 0}, {0, 0, 10}, {0, 0, 0}, kX)});
  EXPECT_EQ(pathData(g19), std::vector<std::string>{"M10 0A10 10 0 0 0 0 -10"});
  std::string g19cw =
      draw(View::YZ, {arcSeg(1, Motion::G2, {0, 0, 10}, {0, 10, 0}, {0, 0, 0}, kX)});
  EXPECT_EQ(pathData(g19cw), std::vector<std::string>{"M0 -10A10 10 0 0 1 10 0"});
}

// Seen from the side an arc is chords of at most one degree (no SVG arc).
TEST(SvgWriter, ArcOutOfTheViewPlaneIsAPolyline) {
  std::string svg = draw(View::ZX, {arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, kZ)});
  auto d = pathData(svg);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].find('A'), std::string::npos);
  EXPECT_EQ(count(d[0], "L"), 90u);  // 90 degrees
  // Z is horizontal, X vertical: the arc goes from X10 (up) to X0 along Z = 0.
  EXPECT_EQ(d[0].rfind("M0 -10L0 ", 0), 0u) << d[0];
  EXPECT_EQ(d[0].substr(d[0].size() - 4), "L0 0");
}

TEST(SvgWriter, FullCircleAndHelixWithTurns) {
  // A full circle: several SVG arcs (one cannot start and end on the same point).
  std::string full = draw(View::XY, {arcSeg(1, Motion::G2, {10, 0, 0}, {10, 0, 0}, {0, 0, 0}, kZ)});
  auto d = pathData(full);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(count(d[0], "A"), 3u) << d[0];
  EXPECT_EQ(count(d[0], " 0 0 1 "), 3u) << d[0];  // G2: clockwise on screen, sweep-flag 1
  EXPECT_EQ(d[0].substr(d[0].size() - 5), " 10 0");
  // Helix: a quarter plus TURN=1 rising 10 in Z; seen from +Z it is circle arcs...
  Segment helix = arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 10}, {0, 0, 0}, kZ, 100, 1);
  std::string top = draw(View::XY, {helix});
  d = pathData(top);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(count(d[0], "A"), 3u) << d[0];  // 450 degrees in pieces of at most 162
  EXPECT_EQ(d[0].substr(d[0].size() - 6), " 0 -10");
  // ...from the side a screw line of 450 one-degree chords from Z0 to Z10.
  std::string side = draw(View::ZX, {helix});
  d = pathData(side);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(count(d[0], "L"), 450u);
  EXPECT_EQ(d[0].rfind("M0 -10L", 0), 0u);
  EXPECT_EQ(d[0].substr(d[0].size() - 5), "L10 0");  // Z10 right, X0
}

TEST(SvgWriter, ViewBoxCoversEveryPointOfBothPaths) {
  std::vector<Segment> prog = {lineSeg(1, Motion::G1, {0, 0, 0}, {-50, 3, 0}, 10)};
  std::vector<Segment> path = {lineSeg(1, Motion::G1, {0, -2, 0}, {-50, 1, 0}, 10),
                               arcSeg(2, Motion::G2, {-50, 1, 0}, {-30, 1, 0}, {-40, 1, 0}, kZ)};
  std::string svg = draw(View::XY, path, nullptr, prog);
  ViewBox b = viewBox(svg);
  for (auto [h, v] : std::vector<std::pair<double, double>>{
           {0, 0}, {-50, 3}, {0, -2}, {-50, 1}, {-40, 11}, {-30, 1}})
    EXPECT_TRUE(b.covers(h, v)) << h << "," << v;
  auto pd = pathData(svg, "programmed");
  EXPECT_EQ(pd, std::vector<std::string>{"M0 0L-50 -3"});
  EXPECT_NE(svg.find("<path class=\"nco-prog\""), std::string::npos);
}

TEST(SvgWriter, AlarmMarkAtTheLastEndPointWithEscapedTitle) {
  Alarm a = makeAlarm(14040, "A&B.MPF", 7, "end point <wrong> \"here\"");
  std::string svg = draw(View::XY, {lineSeg(1, Motion::G1, {0, 0, 0}, {4, 3, 0}, 10)}, &a);
  EXPECT_EQ(test::tagBalance(svg), "") << svg;
  EXPECT_NE(svg.find("<circle class=\"nco-alarm\" vector-effect=\"non-scaling-stroke\" cx=\"4\" "
                     "cy=\"-3\""),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<title>alarm 14040 at A&amp;B.MPF:7: end point &lt;wrong&gt; "
                     "&quot;here&quot;</title>"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find(">alarm 14040</text>"), std::string::npos);
  // No alarm, no mark.
  std::string ok = draw(View::XY, {lineSeg(1, Motion::G1, {0, 0, 0}, {4, 3, 0}, 10)});
  EXPECT_EQ(ok.find("nco-alarm\" vector-effect=\"non-scaling-stroke\" cx"), std::string::npos);
}

TEST(SvgWriter, EmptyPathAndAnAlarmBeforeTheFirstMotion) {
  std::string empty = draw(View::XY, {});
  EXPECT_EQ(test::tagBalance(empty), "");
  ViewBox b = viewBox(empty);
  EXPECT_GT(b.w, 0);
  EXPECT_GT(b.h, 0);
  Alarm a = makeAlarm(12080, "P.MPF", 1, "syntax error");
  std::string at0 = draw(View::XY, {}, &a);
  EXPECT_NE(at0.find("cx=\"0\" cy=\"0\""), std::string::npos);
  EXPECT_TRUE(viewBox(at0).covers(0, 0));
}

// Far more than the in-memory buffer: the drawing goes through the temporary file whole.
TEST(SvgWriter, LongPathsAreCopiedWhole) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  const int n = 100000;
  {
    SvgWriter w(f.get(), View::XY);
    for (int i = 0; i < n; ++i)
      w.segment(lineSeg(i + 1, Motion::G1, {double(i), 0, 0}, {double(i + 1), 0, 0}, 1));
    w.finish(nullptr);
  }
  std::string svg = readAll(f.get());
  EXPECT_EQ(test::tagBalance(svg), "");
  EXPECT_EQ(count(svg, "L"), static_cast<size_t>(n));
  EXPECT_NE(svg.find("L100000 0\"/>"), std::string::npos);
  ViewBox b = viewBox(svg);
  EXPECT_TRUE(b.covers(0, 0) && b.covers(n, 0));
}

TEST(SvgWriter, ViewNames) {
  EXPECT_EQ(viewFromName("xy"), View::XY);
  EXPECT_EQ(viewFromName("zx"), View::ZX);
  EXPECT_EQ(viewFromName("yz"), View::YZ);
}

TEST(XmlEscape, MarkupControlsAndInvalidUtf8) {
  auto esc = [](std::string_view s) {
    fmt::memory_buffer b;
    appendXmlEscaped(b, s);
    return fmt::to_string(b);
  };
  EXPECT_EQ(esc("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(esc("x\x01y\tz"), "x y\tz");
  EXPECT_EQ(esc("\xC3\x98l"), "\xC3\x98l");  // valid UTF-8 passes
  EXPECT_EQ(esc("\xFF"
                "a\xC3"),
            "\xEF\xBF\xBD"
            "a\xEF\xBF\xBD");  // invalid bytes, cut sequence
  EXPECT_EQ(esc("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate
}

}  // namespace
}  // namespace ncoffset::out
