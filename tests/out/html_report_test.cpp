// HTML report (src/out/html_report.hpp): summary, inline drawing, segment table, escaping.
#include "out/html_report.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::arcSeg;
using test::File;
using test::lineSeg;
using test::makeAlarm;
using test::readAll;

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

template <typename Feed>
std::string report(Feed feed, const Alarm* alarm = nullptr, const std::string& coords = "wcs") {
  File f(std::tmpfile());
  EXPECT_TRUE(f);
  {
    HtmlReport r(f.get(), View::XY, "dir/P<1>.MPF", coords);
    EXPECT_TRUE(r.wantsProgrammed());
    feed(r);
    r.finish(alarm);
  }
  return readAll(f.get());
}

const Vec3 kZ{0, 0, 1};

TEST(HtmlReport, SummaryDrawingAndTable) {
  std::string html = report([](HtmlReport& r) {
    r.programmed(lineSeg(1, Motion::G0, {0, 0, 0}, {0, 0, 5}));
    r.segment(lineSeg(1, Motion::G0, {0, 0, 0}, {0, 0, 5}));
    r.programmed(lineSeg(2, Motion::G1, {0, 0, 5}, {10, 0, 5}, 200));
    r.segment(lineSeg(2, Motion::G1, {0, 0, 5}, {10, 0, 5}, 200));
    r.segment(arcSeg(3, Motion::G2, {10, 0, 5}, {0, 10, 5}, {0, 0, 5}, kZ, 250));
    r.segment(arcSeg(4, Motion::G3, {0, 10, 5}, {10, 0, 5}, {0, 0, 5}, kZ, 250));
    r.message({"dir/P<1>.MPF", 5}, "depth & \"feed\"");
    r.warning({"SUB.SPF", 9}, 10763, "path component of the block is zero");
  });
  EXPECT_EQ(html.rfind("<!DOCTYPE html>\n<html lang=\"en\">", 0), 0u);
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "") << html;
  EXPECT_NE(html.find("<title>ncoffset: dir/P&lt;1&gt;.MPF</title>"), std::string::npos);
  EXPECT_NE(html.find("<td>WCS (workpiece, tool tip)</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>ran to the end</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>4 (G0 1, G1 1, G2 1, G3 1)</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("path length rapid (G0)</th><td class=\"n\">5.000 mm"), std::string::npos);
  // 10 + twice three quarters of a circle of radius 10: 10 + 30 pi.
  EXPECT_NE(html.find(fmt::format("path length at feed</th><td class=\"n\">{:.3f} mm",
                                  10 + 30 * 3.14159265358979323846)),
            std::string::npos);
  // The arcs pass X-10 and Y-10: the box has the arcs, not only their end points.
  EXPECT_NE(html.find("<th>X range</th><td class=\"n\">-10 &#8230; 10</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>Y range</th><td class=\"n\">-10 &#8230; 10</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>Z range</th><td class=\"n\">0 &#8230; 5</td>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>dir/P&lt;1&gt;.MPF:5</td><td>message</td><td>depth &amp; "
                      "&quot;feed&quot;</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td>SUB.SPF:9</td><td>warning 10763</td><td>path component"),
            std::string::npos);
  // The drawing inline: one <svg> element, no XML declaration, both paths in it.
  EXPECT_EQ(count(html, "<svg "), 1u);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_NE(html.find("<path class=\"nco-prog\""), std::string::npos);
  EXPECT_NE(html.find("<path class=\"nco-cut\""), std::string::npos);
  EXPECT_LT(html.find("<h2>Summary</h2>"), html.find("<svg "));
  EXPECT_LT(html.find("</svg>"), html.find("<h2>Segments</h2>"));
  // The table: one row per segment.
  EXPECT_NE(html.find("<tr><td class=\"n\">2</td><td>G1</td><td class=\"n\">10</td><td "
                      "class=\"n\">0</td><td class=\"n\">5</td><td class=\"n\">200</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td class=\"n\">1</td><td>G0</td><td class=\"n\">0</td><td "
                      "class=\"n\">0</td><td class=\"n\">5</td><td class=\"n\"></td></tr>"),
            std::string::npos);
  EXPECT_EQ(count(html, "<tr><td class=\"n\">"), 4u);
  // Self-contained: nothing loaded from anywhere.
  for (const char* external : {"<script", "<link", "src=", "href=", "@import", "url("})
    EXPECT_EQ(html.find(external), std::string::npos) << external;
}

TEST(HtmlReport, AlarmIsNamedAndMarked) {
  Alarm a = makeAlarm(14040, "P.MPF", 12, "error in end point of circle <R>");
  std::string html = report(
      [](HtmlReport& r) {
        r.segment(lineSeg(1, Motion::G1, {0, 0, 0}, {3, 4, 0}, 100));
      },
      &a, "mcs");
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "") << html;
  EXPECT_NE(html.find("<td class=\"alarm\">alarm 14040 at P.MPF:12: error in end point of circle "
                      "&lt;R&gt;</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td>MCS (machine axes)</td>"), std::string::npos);
  EXPECT_NE(html.find("<circle class=\"nco-alarm\" vector-effect=\"non-scaling-stroke\" cx=\"3\" "
                      "cy=\"-4\""),
            std::string::npos);
}

TEST(HtmlReport, TableStopsAfterTheFirstThousandSegments) {
  const int n = HtmlReport::kMaxRows + 234;
  std::string html = report([&](HtmlReport& r) {
    for (int i = 0; i < n; ++i)
      r.segment(lineSeg(i + 1, Motion::G1, {double(i), 0, 0}, {double(i + 1), 0, 0}, 10));
  });
  EXPECT_EQ(count(html, "<tr><td class=\"n\">"), static_cast<size_t>(HtmlReport::kMaxRows));
  EXPECT_NE(html.find("<p>The first 1000 segments are listed; 234 more are not.</p>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>1234 (G0 0, G1 1234, G2 0, G3 0)</td>"), std::string::npos);
}

TEST(HtmlReport, EmptyRun) {
  std::string html = report([](HtmlReport&) {});
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "") << html;
  EXPECT_NE(html.find("<p>No segment.</p>"), std::string::npos);
  EXPECT_NE(html.find("<th>X range</th><td class=\"n\">&#8211;</td>"), std::string::npos);
}

}  // namespace
}  // namespace ncoffset::out
