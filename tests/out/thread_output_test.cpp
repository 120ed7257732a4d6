// Thread and tapping lines in every output (docs/threads.md): their own motion name in CSV,
// JSON Lines, SVG, HTML and MPF, the lead as the feed, G34/G35's lead change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "out/html_report.hpp"
#include "out/mpf_writer.hpp"
#include "out/svg_writer.hpp"
#include "out/writers.hpp"
#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::File;
using test::lineSeg;
using test::readAll;

Segment thread(int line, Motion m, Vec3 a, Vec3 b, double lead, double change = 0) {
  Segment s = lineSeg(line, m, a, b, lead);
  s.feed_unit = FeedUnit::MmPerRev;
  s.lead_change = change;
  return s;
}

template <class Writer, class... Args>
std::string write(Args&&... args) {
  File f(std::tmpfile());
  {
    Writer w(f.get(), std::forward<Args>(args)...);
    w.segment(thread(3, Motion::G33, {10, 0, 5}, {10, 0, -30}, 1.5));
    w.segment(thread(4, Motion::G34, {10, 0, -30}, {9, 0, -40}, 2, 0.05));
    w.segment(thread(5, Motion::G331, {0, 0, 2}, {0, 0, -20}, 1.25));
    w.segment(thread(6, Motion::G332, {0, 0, -20}, {0, 0, 2}, 1.25));
    w.segment(lineSeg(7, Motion::G63, {0, 0, 2}, {0, 0, -12}, 300));
    w.finish(nullptr);
  }
  return readAll(f.get());
}

TEST(ThreadOutput, CsvNamesEachMotion) {
  EXPECT_EQ(write<CsvWriter>(),
            "line,motion,x,y,z,cx,cy,cz,feed\n3,G33,10,0,-30,,,,1.5\n4,G34,9,0,-40,,,,2\n"
            "5,G331,0,0,-20,,,,1.25\n6,G332,0,0,2,,,,1.25\n7,G63,0,0,-12,,,,300\n");
  EXPECT_EQ(write<RoundedCsvWriter>(3),
            "line,motion,x,y,z,cx,cy,cz,feed\n3,G33,10,0,-30,,,,1.5\n4,G34,9,0,-40,,,,2\n"
            "5,G331,0,0,-20,,,,1.25\n6,G332,0,0,2,,,,1.25\n7,G63,0,0,-12,,,,300\n");
}

TEST(ThreadOutput, JsonLinesCarryTheLeadChange) {
  static const std::string kName = "T.MPF";
  const std::string j = write<JsonLinesWriter>([](int) -> const std::string& { return kName; });
  EXPECT_NE(j.find("\"motion\":\"G33\",\"x\":10,\"y\":0,\"z\":-30,\"feed\":1.5,\"feed_unit\":"
                   "\"mm/rev\"}"),
            std::string::npos);
  EXPECT_NE(j.find("\"motion\":\"G34\""), std::string::npos);
  EXPECT_NE(j.find("\"lead_change\":0.05"), std::string::npos);
  EXPECT_EQ(j.find("\"lead_change\":0}"), std::string::npos);  // only G34/G35 carry it
}

TEST(ThreadOutput, MpfWritesTheLeadAtTheLongestAxis) {
  const std::string m = write<MpfWriter>("wcs", FileNames{});
  EXPECT_NE(m.find("N1 G33 X10 Y0 Z-30 K1.5 ; line 3"), std::string::npos) << m;
  EXPECT_NE(m.find("N2 G34 X9 Y0 Z-40 K2 F0.05 ; line 4"), std::string::npos) << m;
  EXPECT_NE(m.find("N3 G331 X0 Y0 Z-20 K1.25 ; line 5"), std::string::npos) << m;
  EXPECT_NE(m.find("N4 G332 X0 Y0 Z2 K1.25 ; line 6"), std::string::npos) << m;
  EXPECT_NE(m.find("N5 G1 G63 X0 Y0 Z-12 F300 ; line 7"), std::string::npos) << m;
  EXPECT_EQ(m.find("\nG95 ;"), std::string::npos) << m;  // the lead is no F: no G95 block
}

TEST(ThreadOutput, SvgDrawsThreadsInTheirOwnStyle) {
  const std::string s = write<SvgWriter>(View::ZX);
  EXPECT_NE(s.find("class=\"nco-thread\""), std::string::npos);
  EXPECT_NE(s.find("thread or tapping"), std::string::npos);  // the legend row
  File f(std::tmpfile());
  {
    SvgWriter w(f.get(), View::XY);
    w.segment(lineSeg(1, Motion::G1, {0, 0, 0}, {1, 0, 0}, 5));
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()).find("thread or tapping"), std::string::npos);  // none: no row
}

TEST(ThreadOutput, HtmlCountsThreadsPerMotion) {
  const std::string h = write<HtmlReport>(View::XY, std::string("T.MPF"), std::string("wcs"));
  EXPECT_NE(h.find("5 (G0 0, G1 0, G2 0, G3 0, G33 1, G34 1, G331 1, G332 1, G63 1)"),
            std::string::npos);
  // The segment list is drawn by the page's script from the data column K: a thread line is
  // drawn as a line (1) and carries bit 32 and its motion (G331 - G33 = 3) in bits 6-8.
  const size_t k = h.find("\"K\":[");
  ASSERT_NE(k, std::string::npos);
  bool g331 = false;
  for (size_t i = k + 5; i < h.size() && h[i] != ']';) {
    const int v = std::atoi(h.c_str() + i);
    g331 |= (v & 3) == 1 && (v & 32) != 0 && ((v >> 6) & 7) == 3;
    i = h.find_first_of(",]", i);
    if (i != std::string::npos && h[i] == ',') ++i;
  }
  EXPECT_TRUE(g331);
}

}  // namespace
}  // namespace ncoffset::out
