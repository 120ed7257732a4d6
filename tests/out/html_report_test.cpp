// HTML report (src/out/html_report.hpp): summary, the data the page draws from, the tool table,
// notes linked to their lines, escaping, nothing loaded from anywhere.
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

// A run of two files: P<1>.MPF (index 0) and SUB.SPF (index 1).
ReportContext context() {
  static const std::string names[] = {"dir/P<1>.MPF", "SUB.SPF"};
  static const std::string texts[] = {"G1 X10 ; </script><b>\n", "G0 Z5\nM17\n"};
  ReportContext c;
  c.file_count = [] { return 2; };
  c.file_name = [](int i) -> const std::string& { return names[i]; };
  c.file_text = [](int i) { return std::string_view(texts[i]); };
  c.edge = [](int t, int d) -> std::optional<EdgeData> {
    if (t != 3 || d != 1) return std::nullopt;
    EdgeData e;
    e.dp[1] = 120, e.dp[2] = 0, e.dp[3] = 95.5, e.dp[4] = 0, e.dp[5] = 0, e.dp[6] = 5;
    return e;
  };
  return c;
}

std::string between(const std::string& s, const std::string& a, const std::string& b) {
  size_t i = s.find(a);
  if (i == std::string::npos) return "";
  i += a.size();
  return s.substr(i, s.find(b, i) - i);
}

template <typename Feed>
std::string report(Feed feed, const Alarm* alarm = nullptr, const std::string& coords = "wcs") {
  File f(std::tmpfile());
  EXPECT_TRUE(f);
  {
    HtmlReport r(f.get(), View::XY, "dir/P<1>.MPF", coords, -1, context());
    EXPECT_TRUE(r.wantsProgrammed());
    feed(r);
    r.finish(alarm);
  }
  return readAll(f.get());
}

const Vec3 kZ{0, 0, 1};

TEST(HtmlReport, SummaryAndTheDataOfTheDrawing) {
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
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "") << html.substr(0, 3000);
  EXPECT_NE(html.find("<title>ncoffset: dir/P&lt;1&gt;.MPF</title>"), std::string::npos);
  EXPECT_NE(html.find("<td>WCS (workpiece, tool tip)</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>ran to the end</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>4 (G0 1, G1 1, G2 1, G3 1)</td>"), std::string::npos);
  EXPECT_NE(html.find("path length rapid (G0)</th><td class=\"n\">5.000 mm"), std::string::npos);
  // 10 + twice three quarters of a circle of radius 10: 10 + 30 pi.
  EXPECT_NE(html.find(fmt::format("path length at feed</th><td class=\"n\">{:.3f} mm",
                                  10 + 30 * 3.14159265358979323846)),
            std::string::npos);
  EXPECT_NE(html.find("<th>X range</th><td class=\"n\">-10 &#8230; 10</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>Z range</th><td class=\"n\">0 &#8230; 5</td>"), std::string::npos);
  // Notes link to their line: file index and line.
  EXPECT_NE(html.find("<tr><td class=\"nco-goto\" data-file=\"0\" data-line=\"5\">dir/P&lt;1&gt;"
                      ".MPF:5</td><td>message</td><td>depth &amp; &quot;feed&quot;</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<td class=\"nco-goto\" data-file=\"1\" data-line=\"9\">SUB.SPF:9</td><td>"
                      "warning 10763</td>"),
            std::string::npos);
  // The columns (report_columns.hpp): line differences, kinds (motion + 4 feed + 8 start + 16
  // the programmed segment is this one), end points, runs of file/tool/feed, arcs, the first
  // start.
  const std::string out = between(html, "\"out\":", "},\n\"prog\"");
  EXPECT_NE(out.find("\"L\":[1,1,1,1],\"K\":[24,21,6,7],\"X\":[0,10,0,10],\"Y\":[0,0,10,0],"
                     "\"Z\":[5,5,5,5],\"R\":[[0,0,-1,0,0],[1,0,-1,200,0],[2,0,-1,250,0]],"
                     "\"A\":[[2,0,0,5,0,0,1,0],[3,0,0,5,0,0,1,0]],\"S\":[[0,0,0,0]]"),
            std::string::npos)
      << out;
  const std::string prog = between(html, "\"prog\":", ",\n\"tools\"");
  // Both programmed segments are the output's: none is written twice.
  EXPECT_NE(prog.find("\"L\":[],\"K\":[],\"X\":[]"), std::string::npos) << prog;
  // Both files with their text; `<` escaped so the text cannot end the script.
  EXPECT_NE(html.find("\"files\":[\"dir/P\\u003c1>.MPF\",\"SUB.SPF\"]"), std::string::npos);
  EXPECT_NE(html.find("\"src\":[\"G1 X10 ; \\u003c/script>\\u003cb>\\n\",\"G0 Z5\\nM17\\n\"]"),
            std::string::npos);
  EXPECT_EQ(count(html, "</script>"), 2u);
  EXPECT_NE(html.find("\"notes\":[[0,5,0,\"depth & \\\"feed\\\"\",4],[1,9,10763,"),
            std::string::npos);
  // Self-contained: the style and the script inline, nothing loaded from anywhere.
  EXPECT_EQ(count(html, "<script"), 2u);
  for (const char* external : {"<script src", "<link", " src=", "href=", "@import", "url("})
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  EXPECT_NE(html.find("NCO.start();"), std::string::npos);
}

TEST(HtmlReport, ProgrammedPathBesideTheCompensatedOne) {
  // G41 with R5 on a line along X: the output 5 below, the programmed path as programmed.
  std::string html = report([](HtmlReport& r) {
    r.programmed(lineSeg(2, Motion::G1, {0, 0, 0}, {10, 0, 0}, 100));
    r.programmed(lineSeg(3, Motion::G1, {10, 0, 0}, {20, 0, 0}, 100));
    r.segment(lineSeg(2, Motion::G1, {0, -5, 0}, {10, -5, 0}, 100));
    r.segment(lineSeg(3, Motion::G1, {10, -5, 0}, {20, -5, 0}, 100));
  });
  const std::string out = between(html, "\"out\":", "},\n\"prog\"");
  EXPECT_NE(out.find("\"L\":[2,1],\"K\":[13,5],\"X\":[10,20],\"Y\":[-5,-5]"), std::string::npos)
      << out;
  const std::string prog = between(html, "\"prog\":", ",\n\"tools\"");
  EXPECT_NE(prog.find("\"L\":[2,1],\"K\":[13,5],\"X\":[10,20],\"Y\":[0,0]"), std::string::npos)
      << prog;
}

TEST(HtmlReport, AlarmIsNamedAndLinked) {
  Alarm a = makeAlarm(14040, "SUB.SPF", 12, "error in end point of circle <R>");
  std::string html = report(
      [](HtmlReport& r) {
        r.segment(lineSeg(1, Motion::G1, {0, 0, 0}, {3, 4, 0}, 100));
      },
      &a, "mcs");
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "");
  EXPECT_NE(html.find("<td class=\"alarm\">alarm 14040 at SUB.SPF:12: error in end point of circle "
                      "&lt;R&gt;</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>MCS (machine axes)</td>"), std::string::npos);
  EXPECT_NE(html.find("<tr class=\"alarm\"><td class=\"nco-goto\" data-file=\"1\" "
                      "data-line=\"12\">SUB.SPF:12</td><td>alarm 14040</td>"),
            std::string::npos);
  // After the one segment written: the drawing marks it at that segment's end.
  EXPECT_NE(html.find("\"alarm\":[1,12,14040,\"error in end point of circle \\u003cR>\",1]"),
            std::string::npos);
}

TEST(HtmlReport, ToolTableAndChanges) {
  std::string html = report([](HtmlReport& r) {
    ToolEvent t;
    t.word = ToolEvent::Word::D, t.line = 2, t.file = 0, t.tool = 3, t.edge = 1, t.radius = 5;
    t.length = {0, 0, 95.5};
    r.tool(t);
    r.segment(lineSeg(3, Motion::G1, {0, 0, 0}, {10, 0, 0}, 100));
    r.segment(lineSeg(4, Motion::G1, {10, 0, 0}, {20, 0, 0}, 100));
  });
  // T, D, type, L1..L3, R, cutting edge position, segments, where selected.
  EXPECT_NE(html.find("<tr data-slot=\"0\"><td>3</td><td>1</td><td>120</td><td class=\"n\">95.5"
                      "</td><td class=\"n\">0</td><td class=\"n\">0</td><td class=\"n\">5</td>"
                      "<td>0</td><td class=\"n\">2</td><td><span class=\"nco-goto\" "
                      "data-file=\"0\" data-line=\"2\">dir/P&lt;1&gt;.MPF:2</span></td></tr>"),
            std::string::npos)
      << html.substr(0, 4000);
  EXPECT_NE(html.find("\"tools\":[{\"t\":3,\"d\":1,\"r\":5,\"l\":[0,0,95.5],\"type\":120,"
                      "\"sl\":0}],\"changes\":[[0,0]]"),
            std::string::npos);
  // The segments carry the tool slot in their run.
  EXPECT_NE(html.find("\"R\":[[0,0,0,100,0]]"), std::string::npos);
}

TEST(HtmlReport, ManySegmentsStayInTheData) {
  const int n = 5000;  // every segment is in the data (the page shows them all)
  std::string html = report([&](HtmlReport& r) {
    for (int i = 0; i < n; ++i)
      r.segment(lineSeg(i + 1, Motion::G1, {double(i), 0, 0}, {double(i + 1), 0, 0}, 10));
  });
  EXPECT_NE(html.find("<td>5000 (G0 0, G1 5000, G2 0, G3 0)</td>"), std::string::npos);
  const std::string x = between(html, "\"X\":[", "]");
  EXPECT_EQ(count(x, ","), static_cast<size_t>(n - 1));
  EXPECT_EQ(x.rfind(",5000"), x.size() - 5);
}

TEST(HtmlReport, EmptyRun) {
  std::string html = report([](HtmlReport&) {});
  EXPECT_EQ(test::tagBalance(html, {"meta"}), "");
  EXPECT_NE(html.find("<td>0 (G0 0, G1 0, G2 0, G3 0)</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>X range</th><td class=\"n\">&#8211;</td>"), std::string::npos);
  EXPECT_NE(html.find("\"out\":{\"L\":[],\"K\":[]"), std::string::npos);
}

}  // namespace
}  // namespace ncoffset::out
