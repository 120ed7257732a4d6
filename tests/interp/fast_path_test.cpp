// The per-block fast paths of the front of the pipeline (docs/performance.md section 25) against
// their general twins. A block of plain address words (G1 X10 CR=5) is parsed by
// Parser::simpleWords and collected by the interpreter without looking at statement kinds; the
// same block with ` S=(0)` appended (an S word with an expression, which does nothing here)
// takes the general parser and the general statement loop. Random programs of such blocks
// must give the same segments and the same alarm (number, line, column) both ways. Blocks of
// X, Y, Z, G0..G3, F and CR= alone are collected as they are scanned, without statements
// (Interpreter::plainLine, section 30; G40, G41 and G42 too since section 34); with ` S0`
// appended (an S word, which plainWord leaves to collectWord) they take the plain statements of
// simpleWords, a third way compared too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "interp/motion_builder.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset {
namespace {

class CollectSink final : public PathSink {
 public:
  std::vector<Segment> segments;
  void segment(const Segment& s) override { segments.push_back(s); }
  void finish(const Alarm*) override {}
};

struct Outcome {
  std::vector<Segment> segments;
  std::optional<Alarm> alarm;
};

Outcome run(const std::string& text, const std::filesystem::path& dir = {}) {
  Outcome r;
  CollectSink sink;
  Channel ch;
  RunResult result = ch.runText("T.MPF", text, sink, dir);
  r.segments = sink.segments;
  r.alarm = result.alarm;
  return r;
}

void expectSameVec(const Vec3& a, const Vec3& b) {
  EXPECT_EQ(a.x, b.x);  // bit for bit: both ways compute the same
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

// The tests' pseudo-random numbers below n (a linear congruential generator: the same programs
// everywhere).
struct Random {
  unsigned seed;
  unsigned operator()(unsigned n) {
    seed = seed * 1103515245u + 12345u;
    return (seed >> 16) % n;
  }
};

// The fast way's outcome, after comparing it with the general way's.
// `general_builder`: the general way also builds every motion by MotionBuilder::build.
Outcome expectSame(const std::string& fast_text, const std::string& general_text,
                   const std::filesystem::path& dir = {}, bool general_builder = false) {
  SCOPED_TRACE(fast_text);
  Outcome fast = run(fast_text, dir);
  interp::MotionBuilder::short_way = !general_builder;
  const Outcome general = run(general_text, dir);
  interp::MotionBuilder::short_way = true;
  EXPECT_EQ(fast.alarm.has_value(), general.alarm.has_value());
  if (fast.alarm.has_value() != general.alarm.has_value()) return fast;
  if (fast.alarm) {
    EXPECT_EQ(fast.alarm->number, general.alarm->number);
    EXPECT_EQ(fast.alarm->where.line, general.alarm->where.line);
    EXPECT_EQ(fast.alarm->where.column, general.alarm->where.column);
  }
  EXPECT_EQ(fast.segments.size(), general.segments.size());
  if (fast.segments.size() != general.segments.size()) return fast;
  for (size_t i = 0; i < fast.segments.size(); ++i) {
    const Segment& a = fast.segments[i];
    const Segment& b = general.segments[i];
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.motion, b.motion);
    expectSameVec(a.start, b.start);
    expectSameVec(a.end, b.end);
    expectSameVec(a.centre, b.centre);
    EXPECT_EQ(a.feed, b.feed);
    EXPECT_EQ(a.has_feed, b.has_feed);
  }
  return fast;
}

// One program written three ways: as it is, with ` S=(0)` after every block (the general parser
// and statement loop) and with ` S0` (the plain statements of simpleWords).
struct ThreeWays {
  std::string fast, general, statements;
  explicit ThreeWays(const std::string& head) : fast(head), general(head), statements(head) {}
  void add(const std::string& block) {
    fast += block + "\n";
    general += block + " S=(0)\n";
    statements += block + " S0\n";
  }
  // The plain way's outcome, after comparing both fast ways with the general one.
  Outcome compare() const {
    expectSame(statements, general);
    return expectSame(fast, general);
  }
};

// Random programs of 5..29 blocks of 1..4 words from `words` (a number after each word that
// ends in a letter, '=' or '-'), each compared with its twin; odd programs take only the first
// `safe` words. More than `min_segments` programs must make segments and more than `min_alarm`
// end in an alarm, so that both kinds of outcome are compared.
void compareRandomPrograms(const std::vector<const char*>& words, unsigned safe, unsigned seed,
                           int min_segments, int min_alarm) {
  int with_segments = 0, with_alarm = 0;
  const char* const numbers[] = {"10", "-2.5", "0.125", "100", "+3", ".5", "7", "-40.75", "0"};
  Random next{seed};
  for (int program = 0; program < 300; ++program) {
    ThreeWays three("$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nT1 D1\nG0 X0 Y0 Z0 F100\n");
    const unsigned choice = program % 2 ? safe : static_cast<unsigned>(words.size());
    const unsigned blocks = 5 + next(25);
    for (unsigned k = 0; k < blocks; ++k) {
      std::string block;
      if (next(3) == 0) {
        block += 'N';
        block += std::to_string(10 * (k + 1));
        block += ' ';
      }
      const unsigned count = 1 + next(4);
      for (unsigned w = 0; w < count; ++w) {
        std::string word = words[next(choice)];
        const char last = word.back();
        if (last == '=' || (last >= 'A' && last <= 'Z') || last == '-')
          word += numbers[next(sizeof numbers / sizeof *numbers)];
        if (w) block += ' ';
        block += word;
      }
      three.add(block);
    }
    const Outcome o = three.compare();
    with_segments += o.segments.size() > 2;
    with_alarm += o.alarm.has_value();
  }
  EXPECT_GT(with_segments, min_segments);
  EXPECT_GT(with_alarm, min_alarm);
}

TEST(FrontFastPath, PlainBlocksCollectAsTheGeneralPath) {
  // The first 14 words raise no alarm in any order; the others may (G2 without its end or
  // radius, G5, F-1, an address twice, ...).
  const std::vector<const char*> words = {
      "G0", "G1", "G90", "G91", "G64", "M3",  "T1",  "D1",    "F",     "X",    "Y",
      "Z",  "S",  "X",   "G2",  "G3",  "G17", "G18", "G5",    "G41",   "G40",  "M30",
      "D0", "F-", "I",   "J",   "K",   "CR=", "AR=", "TURN=", "DISC=", "OFFN="};
  compareRandomPrograms(words, 14, 4711, 60, 60);
}

// A block whose words plainWord collected alone is cleared for the next block by resetting only
// those words (BlockWords::clearPlain, docs/performance.md section 27): plain blocks after
// blocks with other words, contour definitions (CHF=, RND=, RNDM=, which keep block end writing
// to the words) and dwells must give what the general path gives.
TEST(FrontFastPath, PlainBlocksAfterOtherBlocksAsTheGeneralPath) {
  const std::vector<const char*> words = {
      "G1",  "X",   "Y",   "Z",   "F",  "RND=",  "RNDM=", "M3",  "T1", "D1",  "G91",   "G90",
      "G64", "G0",  "CR=", "G2",  "G3", "CHF=",  "G4",    "I",   "J",  "AR=", "TURN=", "OFFN=",
      "G41", "G40", "G17", "G18", "F-", "DISC=", "G5",    "M30", "D0", "K",   "X"};
  // The contour words end many programs with an alarm: fewer run through (32 of 300).
  compareRandomPrograms(words, 13, 815, 25, 60);
}

// The approach and retraction lines of a compensated contour (G41 G1 X10 Y0, G40 G1 X-25 Y-20)
// are plain lines (section 34): G group 7 must reach the compensation as gCompensation sets it,
// in every order and mix with the other words, alarms included (a plane change under G41, G2
// without its radius, ...).
TEST(FrontFastPath, CompensationWordsCollectAsTheGeneralPath) {
  const std::vector<const char*> words = {
      "G41", "X",  "Y",   "G1",  "G42", "G40", "X",  "Y",   "G0",  "F", "Z",
      "G2",  "G3", "CR=", "G17", "G18", "G5",  "M3", "G41", "G40", "G-"};
  // Most programs end in an alarm (an address twice, the compensation's own alarms on random
  // moves): fewer run through (29 of 300).
  compareRandomPrograms(words, 10, 2026, 20, 60);
}

// Laps of the issue 22 contour (bench/trc_contour.py): G41 and G42 laps, each with its approach
// and retraction line, all three ways.
TEST(FrontFastPath, CompensatedContourAsTheGeneralPath) {
  const char* const lap[] = {"G0 X-20 Y-20",
                             "G1 Z-1 F1000",
                             "G41 G1 X10 Y0",
                             "G2 X0 Y10 CR=10",
                             "G1 X0 Y50",
                             "G2 X10 Y60 CR=10",
                             "G1 X90 Y60",
                             "G2 X100 Y50 CR=10",
                             "G1 X100 Y10",
                             "G2 X90 Y0 CR=10",
                             "G1 X10 Y0",
                             "G40 G1 X-25 Y-20",
                             "G0 Z5",
                             "G0 X-20 Y-20",
                             "N70 G42 G1 X10 Y0",
                             "G1 X90 Y0",
                             "G3 X100 Y10 CR=10",
                             "G1 X100 Y50",
                             "G3 X90 Y60 CR=10",
                             "G1 X10 Y60",
                             "G3 X0 Y50 CR=10",
                             "G1 X0 Y10",
                             "G3 X10 Y0 CR=10",
                             "G40 G1 X-25 Y-20",
                             "G0 Z5"};
  ThreeWays three("$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50\n$TC_DP6[1,1]=4\nG17 G90 G94 G71\nT1 D1\n");
  for (int pass = 0; pass < 3; ++pass)
    for (const char* line : lap) three.add(line);
  const Outcome o = three.compare();
  EXPECT_FALSE(o.alarm.has_value());
  EXPECT_EQ(o.segments.size(), 72u);  // the moves of the three passes, as both paths make them
}

// Circles by their centre (I, J, K: plainWord and plainLineWord collect them since
// docs/performance.md §53, MotionBuilder::centreArc builds them): the contour's laps with I J,
// full circles, the G18 and G19 planes, inch, incremental ends, a helix with TURN=, I=AC(..) and
// I=IC(..), the applicate's parameter, an end off the circle, I twice, CR= with a centre, and a
// thread's lead K under G33 on a plain line, all three ways and with MotionBuilder::build.
TEST(FrontFastPath, CirclesByCentreAsTheGeneralPath) {
  const char* const lines[] = {"G41 G1 X10 Y0",
                               "G2 X0 Y10 I0 J10",
                               "G1 X0 Y50",
                               "G2 X10 Y60 I10 J0",
                               "G1 X90 Y60",
                               "G2 X100 Y50 J-10",
                               "G1 X100 Y10",
                               "G2 X90 Y0 I-10",
                               "G1 X10 Y0",
                               "G40 G1 X-25 Y-20",
                               "G3 I5 J5",
                               "G3 X-15 Y-10 I5 J5 F200",
                               "G18 G2 Z5 X-10 K5 I0",
                               "G17 G91 G3 X10 Y10 I10 Z-1",
                               "G90 G19 G2 Y-10 Z4 J-5 K5",
                               "G17 G70 G2 X0 Y0 J0.19685",
                               "G71 G3 X20 Y0 I10 J0 TURN=2 Z-3",
                               "G2 X0 Y0 I=AC(10) J=AC(0)",
                               "G3 X20 Y0 I=IC(10) J=IC(0)"};
  ThreeWays three(
      "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50\n$TC_DP6[1,1]=4\nG17 G90 G94 G71\nT1 D1\n"
      "G0 X-20 Y-20 Z0 F500\n");
  for (const char* line : lines) three.add(line);
  std::string fast = three.fast, general = three.general;
  const Outcome o = three.compare();
  EXPECT_FALSE(o.alarm.has_value());
  EXPECT_EQ(o.segments.size(), 20u);  // the G0 of the head and one for each line
  expectSame(fast, general, {}, true);
  // Each ends the program with its alarm (the same number, line and column both ways).
  const char* const alarms[] = {"G2 X10 Y0 I3 J0",
                                "G2 X20 Y0 I10 I10",
                                "G2 X20 Y0 I10 K0",
                                "G2 X20 Y0 I10 CR=10",
                                "G2 X20 Y0 I0 J0",
                                "G1 X20 I10",
                                "G33 Z-10 K1.5\nZ-20 K1.5 CR=5",
                                "G2 X20 Y0.5 I10"};
  for (const char* end : alarms) {
    ThreeWays bad("G17 G0 X0 Y0 Z0 F100\n");
    bad.add(end);
    EXPECT_TRUE(bad.compare().alarm.has_value()) << end;
  }
  // A thread's lead on plain lines (K under the modal G33) runs.
  ThreeWays thread("G18 G0 X20 Z0\nS1000 M3\nG33 Z-10 K1.5\n");
  thread.add("Z-20 K1.5");
  thread.add("X22 Z-30 K1.5");
  const Outcome t = thread.compare();
  EXPECT_FALSE(t.alarm.has_value());
  EXPECT_EQ(t.segments.size(), 4u);
}

// Random programs of circle words in every plane and order, as the general path: nearly all end
// in an alarm (an end point off the circle, a parameter twice, the applicate's parameter, a
// centre without G2/G3), whose number, line and column are compared.
TEST(FrontFastPath, CircleWordsCollectAsTheGeneralPath) {
  const std::vector<const char*> words = {"G2",  "G3",  "X",   "Y",   "I",  "J",   "G1",
                                          "G17", "G18", "G19", "K",   "Z",  "CR=", "G91",
                                          "G90", "F",   "G41", "G40", "I-", "J-"};
  compareRandomPrograms(words, 6, 1953, 1, 250);
}

// The plain line is scanned where it stands when a newline follows it, in a copy otherwise (the
// last line of a text without its newline): CR LF, a CR left inside the line (CR CR LF) and a
// last line ending in CR=, all as the general path.
TEST(FrontFastPath, LineEndsAsTheGeneralPath) {
  const char* const lines[] = {"G1 X10 Y0 F100",   "G2 X0 Y10 CR=10", "G1 Y50",
                               "G3 X10 Y60 CR=10", "G1 X40 CR=3",     "G2 X50 Y50 CR=10"};
  for (const char* eol : {"\n", "\r\n", "\r\r\n", "\r"}) {
    SCOPED_TRACE(::testing::PrintToString(std::string(eol)));
    std::string fast = "G0 X0 Y0 Z0\n", general = fast;
    for (const char* line : lines) {
      const bool last = line == lines[std::size(lines) - 1];
      fast += std::string(line) + (last ? "" : eol);
      general += std::string(line) + " S=(0)" + (last ? "" : eol);
    }
    const Outcome o = expectSame(fast, general);
    // G1 .. CR=3 ends each program with the circle alarm after four moves (the alarm's column
    // compared above); a CR inside a line is no character of a block (an alarm at once), and a
    // CR alone ends no line.
    const bool clean =
        std::string(eol).find("\r\r") == std::string::npos && std::string(eol) != "\r";
    EXPECT_TRUE(o.alarm.has_value());
    EXPECT_EQ(o.segments.size(), clean ? 4u : 0u);
  }
}

// The motion builder keeps the compensation settings, the tool tip and the tool length vector of
// the last plain block while only plain lines run (MotionBuilder::buildPlain, section 35): plain
// lines between lines that change them (G41/G42/G40, OFFN=, DISC=, D, tool data, the plane,
// CUTCONON, G450/G451, G91, G70, frames) must give what the same lines give when each one takes
// the general path (` S=(0)`) and MotionBuilder::build, where the settings are built anew for
// every block.
TEST(FrontFastPath, PlainBlocksKeepTheSettingsAsTheGeneralPath) {
  const char* const settings[] = {"G41",       "G42",
                                  "G40",       "OFFN=1.5",
                                  "DISC=2",    "D0",
                                  "D1",        "G17",
                                  "G18",       "G91",
                                  "G90",       "G70",
                                  "G71",       "G450",
                                  "G451",      "CUTCONON",
                                  "CUTCONOF",  "TRANS X5",
                                  "MIRROR Y0", "G54",
                                  "G500",      "$TC_DP6[1,1]=3",
                                  "G0",        "G1"};
  const char* const numbers[] = {"10", "-2.5", "0.125", "40", "-7", "0"};
  Random next{2026};
  int with_segments = 0, with_alarm = 0;
  for (int program = 0; program < 300; ++program) {
    std::string fast = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nT1 D1\nG0 X0 Y0 Z0 F100\n";
    std::string general = fast;
    for (unsigned k = 0, blocks = 5 + next(30); k < blocks; ++k) {
      std::string block;
      const unsigned kind = next(10);
      if (kind < 3) {
        block += settings[next(sizeof settings / sizeof *settings)];
      } else {
        block += kind == 3 ? (next(2) ? "G2" : "G3") : (next(4) ? "G1" : "G0");
        for (const char* axis : {"X", "Y", "Z"}) {
          if (kind != 3 && next(2) == 0) continue;  // a circle: its end point in any plane
          block += ' ';
          block += axis;
          block += numbers[next(sizeof numbers / sizeof *numbers)];
        }
        if (kind == 3) block += " CR=500";
      }
      fast += block + "\n";
      general += block + " S=(0)\n";
    }
    const Outcome o = expectSame(fast, general, {}, true);
    with_segments += o.segments.size() > 8;
    with_alarm += o.alarm.has_value();
  }
  EXPECT_GT(with_segments, 150);
  EXPECT_GT(with_alarm, 10);
}

// A subprogram with SAVE gives back the G groups at its return (leaveSubprogram): the plain line
// after it must not keep the settings its last plain line had.
TEST(FrontFastPath, PlainBlockAfterASaveReturnAsTheGeneralPath) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "ncoffset_fast_path_save";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "PQ_KEEP.SPF") << "PROC PQ_KEEP SAVE\nG451 CUTCONON\nG1 X60 Y40\n"
                                        "X80\nRET\n";
  const std::string head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4\nT1 D1\nG0 X0 Y0 Z0 F100\n";
  const char* const lines[] = {"G41 G1 X20 Y0", "X40", "PQ_KEEP", "X100 Y40",
                               "Y100",          "X0",  "Y0",      "G40 X-10"};
  std::string fast = head, general = head;
  for (const char* line : lines) {
    fast += line;
    fast += '\n';
    general += line;
    general += " S=(0)\n";
  }
  const Outcome o = expectSame(fast, general, dir, true);
  EXPECT_FALSE(o.alarm.has_value());
  EXPECT_GT(o.segments.size(), 8u);
  std::filesystem::remove_all(dir);
}

// A plain line is read and collected in one pass (Interpreter::lineInPlace, docs/performance.md
// §44) where the program's text ends with a newline; without that last newline every line is
// read by nextLine and collected by plainLine, its twin. Random programs of plain lines and
// others (blanks, tabs, block numbers, empty lines, a modal call, a rounding, a '\0' or a CR
// inside a line, comments, macros, alarms) with LF, CR LF and CR CR LF ends, and a line beyond
// --max-line-length, both ways.
TEST(FrontFastPath, LinesInPlaceAsNextLine) {
  using namespace std::string_literals;
  // Lines that run (the first `safe`), then lines that end the program with an alarm or take
  // the general way for good (a macro).
  const std::string lines[] = {"G1 X10 Y0 F100",
                               "  G1 Y50 ",
                               "N20 G1 X10 Y60",
                               "N30",
                               "",
                               "\tG1\tX40 ",
                               "G1 X5 ; note",
                               "R1=2 G1 X=R1",
                               "G0 X1 Y2 Z3",
                               "G41 G1 X-5 Y1",
                               "G40 G1 X0 Y0",
                               "G1 X.5 F+20",
                               "G2 X10 Y0 CR=50",
                               "MCALL CYCLE82(10,0,1,-6,0,1)",
                               "MCALL",
                               "G1 X20 Y5 RND=1",
                               "G1 X7\0 Y2"s,
                               "CR=5 G2 X0 Y0",
                               "G1 X1 X2",
                               "G1 X3\rY4",
                               "DEFINE MM AS G1 X3",
                               "MM",
                               "G1 X1" + std::string(70000, ' ') + "Y2"};
  const unsigned safe = 16;
  const char* const ends[] = {"\n", "\n", "\r\n", "\r\r\n"};
  Random next{7};
  int with_segments = 0, with_alarm = 0;
  for (int program = 0; program < 200; ++program) {
    std::string text = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nT1 D1\nG0 X0 Y0 Z0 F100\n";
    const unsigned count = 3 + next(18);
    for (unsigned k = 0; k < count; ++k) {
      // Even programs: only lines that run, LF and CR LF; odd ones: anything.
      const bool any = program % 2 != 0 || next(12) == 0;
      text += lines[next(any ? static_cast<unsigned>(std::size(lines)) : safe)];
      text += k + 1 == count ? "\n" : ends[next(any ? 4 : 3)];
    }
    const Outcome o = expectSame(text, text.substr(0, text.size() - 1));
    with_segments += o.segments.size() > 2;
    with_alarm += o.alarm.has_value();
  }
  EXPECT_GT(with_segments, 50);
  EXPECT_GT(with_alarm, 50);
}

}  // namespace
}  // namespace ncoffset
