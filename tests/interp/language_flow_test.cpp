// Issue 15 through the public API: global user data and macros across runs (init file, then
// program), program section repetition, repeated labels, text archives (docs/language.md).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "lang/macro_table.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset {
namespace {

class Collect final : public PathSink {
 public:
  std::vector<Segment> segments;
  std::vector<std::string> messages;
  void segment(const Segment& s) override { segments.push_back(s); }
  void message(const SourceLoc&, const std::string& t) override { messages.push_back(t); }
  void finish(const Alarm*) override {}
};

std::vector<double> xs(const Collect& c) {
  std::vector<double> v;
  for (const auto& s : c.segments) v.push_back(s.end.x);
  return v;
}

TEST(LanguageFlow, GudFromAnInitFileIsSeenAndWrittenAndReportedByVars) {
  Channel ch;
  Collect sink;
  RunResult init = ch.runInitText("G.DEF",
                                  "%_N_SGUD_DEF\n"
                                  "DEF NCK REAL RTP=100\n"
                                  "DEF CHAN SYNR INT PASSES=2, LEFT\n"
                                  "M30\n",
                                  sink);
  ASSERT_FALSE(init.alarm) << init.alarm->text;
  RunResult r = ch.runText("P.MPF", "G0 X=RTP\nLEFT=PASSES+1\nM30\n", sink);
  ASSERT_FALSE(r.alarm) << r.alarm->text;
  ASSERT_EQ(sink.segments.size(), 1u);
  EXPECT_DOUBLE_EQ(sink.segments[0].end.x, 100);
  std::ostringstream os;
  ch.writeVariablesJson(os);
  EXPECT_NE(os.str().find("\"RTP\": 100"), std::string::npos) << os.str();
  EXPECT_NE(os.str().find("\"LEFT\": 3"), std::string::npos) << os.str();
}

TEST(LanguageFlow, InitMacrosStayProgramMacrosGo) {
  Channel ch;
  Collect sink;
  ASSERT_FALSE(ch.runInitText("M.DEF", "DEFINE FAST AS G0\n", sink).alarm);
  RunResult r = ch.runText("A.MPF", "DEFINE FAR AS 50\nFAST X=FAR\n", sink);
  ASSERT_FALSE(r.alarm) << r.alarm->text;
  EXPECT_EQ(xs(sink), std::vector<double>{50});
  // A second program: FAST is still a macro, FAR (of the first program) is no longer one.
  RunResult again = ch.runText("B.MPF", "FAST X=FAR\n", sink);
  ASSERT_TRUE(again.alarm);
  EXPECT_EQ(again.alarm->number, 12550);
}

TEST(LanguageFlow, MacroExpansionKeepsStringsCommentsAndSystemNames) {
  lang::MacroTable t;
  t.define("AA", "G1", false);
  std::string out;
  EXPECT_TRUE(t.expand("aa X1 ; AA", out, 100));
  EXPECT_EQ(out, "G1 X1 ; AA");
  EXPECT_FALSE(t.expand("MSG(\"AA\") $AA=1 AAB=2 N10 10AA", out, 100));
  EXPECT_FALSE(t.expand("DEFINE BB AS AA", out, 100));  // a definition's text stays as written
  EXPECT_THROW(t.expand("AA AA AA AA", out, 8), AlarmError);
}

TEST(LanguageFlow, BareRepeatIsALoopAndRepeatWithLabelsASection) {
  Channel ch;
  Collect sink;
  RunResult r = ch.runText("R.MPF",
                           "R1=0 G1 F100\n"
                           "REPEAT\n"
                           "  R1=R1+1 X=R1\n"
                           "UNTIL R1>=2\n"
                           "AA: X10\n"
                           "BB: X11\n"
                           "REPEAT AA BB P=1\n"
                           "REPEATB AA\n"
                           "M30\n",
                           sink);
  ASSERT_FALSE(r.alarm) << r.alarm->text;
  EXPECT_EQ(xs(sink), (std::vector<double>{1, 2, 10, 11, 10, 11, 10}));
}

TEST(LanguageFlow, ArchiveGivenAsProgramText) {
  Channel ch;
  Collect sink;
  RunResult r = ch.runText("ARC.MPF",
                           "%_N_SUB_A_SPF\nG1 X7 F10\nM17\n"
                           "%_N_MAIN_MPF\nG0 X1\nSUB_A\nG0 X2\nM30\n",
                           sink);
  ASSERT_FALSE(r.alarm) << r.alarm->text;
  EXPECT_EQ(xs(sink), (std::vector<double>{1, 7, 2}));
  // Line numbers are those of the archive.
  EXPECT_EQ(sink.segments[1].line, 2);
  EXPECT_EQ(sink.segments[2].line, 7);
}

}  // namespace
}  // namespace ncoffset
