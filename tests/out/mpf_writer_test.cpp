// Compensated part program (src/out/mpf_writer.hpp): blocks, planes, sense, helix, feed,
// comments and the end of the program.
#include "out/mpf_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::arcSeg;
using test::File;
using test::lineSeg;
using test::makeAlarm;
using test::readAll;

std::vector<std::string> program(const std::vector<Segment>& path, const Alarm* alarm = nullptr,
                                 FileNames names = {}) {
  File f(std::tmpfile());
  EXPECT_TRUE(f);
  {
    MpfWriter w(f.get(), "wcs", std::move(names));
    EXPECT_FALSE(w.wantsProgrammed());
    for (const auto& s : path) w.segment(s);
    w.finish(alarm);
  }
  // The lines after the header (MpfWriter.Header).
  std::string text = readAll(f.get());
  const std::string header = mpfHeader("wcs");
  EXPECT_EQ(text.substr(0, header.size()), header);
  std::vector<std::string> out;
  std::istringstream is(text.substr(std::min(header.size(), text.size())));
  for (std::string l; std::getline(is, l);) out.push_back(l);
  return out;
}

const Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

std::string num(double v) {
  fmt::memory_buffer b;
  appendNcNumber(b, v);
  return fmt::to_string(b);
}

TEST(MpfWriter, Numbers) {
  EXPECT_EQ(num(100), "100");
  EXPECT_EQ(num(2.5), "2.5");
  EXPECT_EQ(num(1.0 / 3.0), "0.333333");
  EXPECT_EQ(num(-12.3400001), "-12.34");
  EXPECT_EQ(num(-1e-7), "0");
  EXPECT_EQ(num(-0.0), "0");
  EXPECT_EQ(num(0.0000006), "0.000001");
  EXPECT_EQ(num(-1234567.8912345), "-1234567.891235");
}

// What the positions assume, as comments, then one block of reset words.
TEST(MpfWriter, Header) {
  for (const std::string coords : {"mcs", "wcs"}) {
    std::vector<std::string> l;
    std::istringstream is(mpfHeader(coords));
    for (std::string line; std::getline(is, line);) l.push_back(line);
    ASSERT_GE(l.size(), 5u);
    EXPECT_EQ(l[0], "; ncoffset compensated path (coords " + coords + ")");
    for (size_t i = 0; i + 1 < l.size(); ++i) EXPECT_EQ(l[i].rfind("; ", 0), 0u) << l[i];
    const std::string reset =
        coords == "mcs" ? "G90 G71 G94 G40 G17 D0 ; reset: " : "G90 G71 G94 G40 G17 ; reset: ";
    EXPECT_EQ(l.back().rfind(reset, 0), 0u) << l.back();  // (without --diameter)
    const std::string text = mpfHeader(coords);
    EXPECT_EQ(text.find(coords == "mcs" ? "(MCS)" : "(WCS)") != std::string::npos, true);
    EXPECT_EQ(text.find("SUPA") != std::string::npos, coords == "mcs");
  }
}

TEST(MpfWriter, NumbersWithDecimals) {
  auto n = [](double v, int d) {
    fmt::memory_buffer b;
    appendNcNumber(b, v, d);
    return fmt::to_string(b);
  };
  EXPECT_EQ(n(30.000000000000004, 3), "30");
  EXPECT_EQ(n(-7.1e-15, 9), "0");
  EXPECT_EQ(n(1.0 / 3.0, 0), "0");
  EXPECT_EQ(n(1.0 / 3.0, 10), "0.3333333333");
  EXPECT_EQ(n(1e20, 3), "100000000000000000000");  // never an exponent in NC text
  EXPECT_EQ(n(-2.5e15, 2), "-2500000000000000");
}

TEST(MpfWriter, LinesFeedOnlyWhenItChangesAndTheEnd) {
  auto p = program({lineSeg(3, Motion::G0, {0, 0, 0}, {0, 0, 5}),
                    lineSeg(4, Motion::G1, {0, 0, 5}, {10, 0, 5}, 100),
                    lineSeg(5, Motion::G1, {10, 0, 5}, {10, 1.0 / 3, 5}, 100),
                    lineSeg(6, Motion::G0, {10, 1.0 / 3, 5}, {10, 0, 50}),
                    lineSeg(7, Motion::G1, {10, 0, 50}, {0, 0, 50}, 100),
                    lineSeg(8, Motion::G1, {0, 0, 50}, {0, 0, 0}, 12.5)});
  std::vector<std::string> want = {"N1 G0 X0 Y0 Z5 ; line 3",
                                   "N2 G1 X10 Y0 Z5 F100 ; line 4",
                                   "N3 G1 X10 Y0.333333 Z5 ; line 5",
                                   "N4 G0 X10 Y0 Z50 ; line 6",
                                   "N5 G1 X0 Y0 Z50 ; line 7",
                                   "N6 G1 X0 Y0 Z0 F12.5 ; line 8",
                                   "M30"};
  EXPECT_EQ(p, want);
}

// G95 (a lathe's feed per revolution, G96/G97 too) and G93 in a block of their own before the
// first feed of that unit; F is written again after the change (docs/turning.md).
TEST(MpfWriter, FeedUnitWhenItChanges) {
  auto rev = [](Segment s) {
    s.feed_unit = FeedUnit::MmPerRev;
    return s;
  };
  auto p = program({rev(lineSeg(3, Motion::G1, {0, 0, 0}, {10, 0, 0}, 0.2)),
                    rev(lineSeg(4, Motion::G1, {10, 0, 0}, {10, 0, -5}, 0.2)),
                    rev(lineSeg(5, Motion::G0, {10, 0, -5}, {20, 0, 5})),
                    lineSeg(6, Motion::G1, {20, 0, 5}, {20, 0, 0}, 0.2),
                    rev(lineSeg(7, Motion::G1, {20, 0, 0}, {25, 0, 0}, 0.2))});
  std::vector<std::string> want = {
      "G95 ; feed in mm/rev",     "N1 G1 X10 Y0 Z0 F0.2 ; line 3", "N2 G1 X10 Y0 Z-5 ; line 4",
      "N3 G0 X20 Y0 Z5 ; line 5", "G94 ; feed in mm/min",          "N4 G1 X20 Y0 Z0 F0.2 ; line 6",
      "G95 ; feed in mm/rev",     "N5 G1 X25 Y0 Z0 F0.2 ; line 7", "M30"};
  EXPECT_EQ(p, want);
}

// --diameter: the header says so and DIAMON follows the reset block.
TEST(MpfWriter, DiameterHeader) {
  const std::string h = mpfHeader("mcs", true);
  EXPECT_NE(h.find("G90 G71 G94 G40 G17 D0 ; reset"), std::string::npos);
  EXPECT_NE(h.find("\nDIAMON ; the transverse axis in diameter\n"), std::string::npos);
  EXPECT_LT(h.find("G90 G71 G94"), h.find("\nDIAMON"));
  EXPECT_EQ(mpfHeader("mcs").find("\nDIAMON"), std::string::npos);
}

TEST(MpfWriter, ArcsInEachPlaneWithThePlaneWhenItChanges) {
  auto p = program({
      arcSeg(1, Motion::G2, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, kZ),
      arcSeg(2, Motion::G3, {0, 10, 0}, {-10, 0, 0}, {0, 0, 0}, kZ),
      arcSeg(3, Motion::G2, {-10, 0, 0}, {0, 0, 10}, {0, 0, 0}, kY),
      arcSeg(4, Motion::G3, {0, 0, 10}, {0, 10, 0}, {0, 0, 0}, kX),
  });
  std::vector<std::string> want = {"G17",
                                   "N1 G2 X0 Y10 Z0 I=AC(0) J=AC(0) F100 ; line 1",
                                   "N2 G3 X-10 Y0 Z0 I=AC(0) J=AC(0) ; line 2",
                                   "G18",
                                   "N3 G2 X0 Y0 Z10 I=AC(0) K=AC(0) ; line 3",
                                   "G19",
                                   "N4 G3 X0 Y10 Z0 J=AC(0) K=AC(0) ; line 4",
                                   "M30"};
  EXPECT_EQ(p, want);
}

// Normal along -Z: G2 seen from -Z is G3 seen from +Z (and so for each plane).
TEST(MpfWriter, NegativeNormalReversesTheSense) {
  auto p = program({arcSeg(1, Motion::G2, {5, 1, 2}, {1, 5, 2}, {1, 1, 2}, {0, 0, -1}),
                    arcSeg(2, Motion::G3, {1, 5, 2}, {1, 5, 2}, {1, 1, 2}, {0, -1, 0})});
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0], "G17");
  EXPECT_EQ(p[1], "N1 G3 X1 Y5 Z2 I=AC(1) J=AC(1) F100 ; line 1");
  EXPECT_EQ(p[2], "G18");
  EXPECT_EQ(p[3], "N2 G2 X1 Y5 Z2 I=AC(1) K=AC(2) ; line 2");
}

TEST(MpfWriter, HelixWithTurns) {
  auto p = program({arcSeg(9, Motion::G3, {10, 0, 0}, {0, 10, -6}, {0, 0, 0}, kZ, 40, 2)});
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], "N1 G3 X0 Y10 Z-6 I=AC(0) J=AC(0) TURN=2 F40 ; line 9");
}

// An arc about a tilted axis (a rotated frame in MCS) cannot be a G2/G3: one-degree chords.
TEST(MpfWriter, TiltedArcAsChords) {
  const double s = std::sqrt(0.5);
  Segment a = arcSeg(4, Motion::G3, {10, 0, 0}, {0, 10 * s, 10 * s}, {0, 0, 0}, {0, -s, s});
  auto p = program({a});
  ASSERT_EQ(p.size(), 1u + 90u + 1u);
  EXPECT_EQ(p[0], "; G3 about a tilted axis: 90 chords");
  EXPECT_EQ(p[1].rfind("N1 G1 X9.998477 Y0.123407 Z0.123407 F100 ; line 4", 0), 0u) << p[1];
  EXPECT_EQ(p[90], "N90 G1 X0 Y7.071068 Z7.071068 ; line 4");
}

// A circle at rapid traverse (a G0 block's corner circle under radius compensation: no feed)
// cannot be a G2/G3 at rapid: G0 chords of at most one degree.
TEST(MpfWriter, RapidArcAsG0Chords) {
  Segment a = arcSeg(7, Motion::G3, {50, -5, 0}, {55, 0, 0}, {50, 0, 0}, kZ);
  a.has_feed = false;
  auto p = program({a});
  // program() leaves out the header, as for the tilted arc above.
  ASSERT_EQ(p.size(), 1u + 90u + 1u);
  EXPECT_EQ(p[0], "; G3 at rapid traverse: 90 chords");
  EXPECT_EQ(p[1].rfind("N1 G0 X50.087262 Y-4.999238 Z0 ; line 7", 0), 0u) << p[1];
  EXPECT_EQ(p[90], "N90 G0 X55 Y0 Z0 ; line 7");
}

TEST(MpfWriter, MessagesWarningsFilesAndTheAlarm) {
  static const std::vector<std::string> kNames = {"MAIN.MPF", "SUB.SPF"};
  FileNames names = [](int i) -> const std::string& { return kNames.at(static_cast<size_t>(i)); };
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    MpfWriter w(f.get(), "mcs", names);
    w.segment(lineSeg(2, Motion::G0, {0, 0, 0}, {1, 0, 0}));
    w.message({"MAIN.MPF", 3}, "two\nlines");
    Segment sub = lineSeg(7, Motion::G1, {1, 0, 0}, {2, 0, 0}, 10);
    sub.file = 1;
    w.segment(sub);
    w.warning({"SUB.SPF", 8}, 10763, "path component of the block is zero");
    Alarm a = makeAlarm(14040, "SUB.SPF", 9, "error in end point of circle");
    w.finish(&a);
    w.finish(nullptr);  // ignored
  }
  std::string text = readAll(f.get());
  EXPECT_EQ(text, mpfHeader("mcs") +
                      "; file MAIN.MPF\n"
                      "N1 G0 SUPA X1 Y0 Z0 ; line 2\n"
                      "; MSG: two lines (MAIN.MPF:3)\n"
                      "; file SUB.SPF\n"
                      "N2 G1 SUPA X2 Y0 Z0 F10 ; line 7\n"
                      "; warning 10763: path component of the block is zero (SUB.SPF:8)\n"
                      "; ALARM 14040 at SUB.SPF:9: error in end point of circle\n"
                      "M0 ; incomplete: the source program stopped at the alarm above\n"
                      "M30\n");
}

}  // namespace
}  // namespace ncoffset::out
