// Program flow alone (src/interp/program_flow.hpp): levels, the read position, the jump search
// by label and block number (PM-JP "Program jumps": GOTOF forward, GOTOB backward, GOTO both),
// subprogram calls with pass counts.
#include "interp/program_flow.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {
namespace {

std::string lineText(ProgramFlow& f) {
  std::string_view text;
  lang::TextPos at;
  return f.nextLine(text, at) ? std::string(text) : std::string("<end>");
}

TEST(ProgramFlow, ReadsTheMainProgramLineByLine) {
  ProgramFlow f{Limits{}};
  LoadedProgram& p = f.load(lang::SourceFile::fromString("MAIN.MPF", "G0 X1\nG1 X2\nM30\n"));
  f.begin(p);
  EXPECT_EQ(lineText(f), "G0 X1");
  EXPECT_EQ(lineText(f), "G1 X2");
  EXPECT_EQ(lineText(f), "M30");
  EXPECT_EQ(lineText(f), "<end>");
}

TEST(ProgramFlow, JumpsToLabelsAndBlockNumbersInTheirDirection) {
  ProgramFlow f{Limits{}};
  LoadedProgram& p =
      f.load(lang::SourceFile::fromString("MAIN.MPF", "N10 X1\nMARK: X2\nN10 X3\nN20 X4\n"));
  f.begin(p);
  std::string_view text;
  lang::TextPos second, third;
  f.nextLine(text, second);
  f.nextLine(text, second);  // at MARK:
  f.nextLine(text, third);   // at the second N10
  JumpSearch forward{true, false, false}, backward{false, true, false};
  EXPECT_TRUE(f.jumpToBlockNumber(20, third.offset, forward));
  EXPECT_EQ(lineText(f), "N20 X4");
  EXPECT_TRUE(f.jumpToBlockNumber(10, third.offset, backward));  // the first N10
  EXPECT_EQ(lineText(f), "N10 X1");
  EXPECT_FALSE(f.jumpToBlockNumber(10, third.offset, JumpSearch{true, false, false}));
  EXPECT_TRUE(f.jumpToLabel("MARK", third.offset, backward));
  EXPECT_EQ(lineText(f), "MARK: X2");
  EXPECT_FALSE(f.jumpToLabel("MARK", third.offset, forward));
}

TEST(ProgramFlow, SubprogramWithPassCount) {
  const auto dir = std::filesystem::temp_directory_path() / "ncoffset_program_flow_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "SUB1.SPF") << "G1 X5\nM17\n";
  ProgramFlow f{Limits{}};
  f.setSearchDir(dir);
  f.begin(f.load(lang::SourceFile::fromString("MAIN.MPF", "SUB1 P2\nM30\n")));
  EXPECT_EQ(lineText(f), "SUB1 P2");
  f.call("SUB1", 2);
  EXPECT_EQ(f.depth(), 2u);
  EXPECT_EQ(lineText(f), "G1 X5");
  EXPECT_TRUE(f.leave());  // the second pass
  EXPECT_EQ(lineText(f), "G1 X5");
  EXPECT_FALSE(f.leave());
  EXPECT_EQ(f.depth(), 1u);
  EXPECT_EQ(lineText(f), "M30");
  std::filesystem::remove_all(dir);
}

TEST(ProgramFlow, CallAlarms) {
  Limits limits;
  limits.max_program_levels = 1;
  ProgramFlow f{limits};
  f.begin(f.load(lang::SourceFile::fromString("MAIN.MPF", "NOPE\n")));
  try {
    f.call("NOPE", 1);
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::SubprogramDepth));  // checked before the search
  }
  ProgramFlow g{Limits{}};
  g.begin(g.load(lang::SourceFile::fromString("MAIN.MPF", "NOPE\n")));
  try {
    g.call("NOPE", 1);
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::ProgramNotFound));
  }
}

}  // namespace
}  // namespace ncoffset::interp
