// The turning syntax of the parser (docs/turning.md): DIAMONA[X] and its siblings are procedure
// calls with the axis in brackets (no '='), X=DAC(..)/DIC/RAC/RIC set the word's mode, and those
// modes are refused for addresses that are no axis.
#include <gtest/gtest.h>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"
#include "parse_alarm.hpp"

namespace ncoffset::lang {
namespace {

TEST(TurningSyntax, AxisProceduresAreCallsWithTheAxisInBrackets) {
  for (const char* name : {"DIAMONA", "DIAM90A", "DIAMOFA", "DIACYCOFA", "DIAMCHANA"}) {
    Block b;
    parseBlock(std::string(name) + "[X] G1 X20", 1, b, {});
    ASSERT_EQ(b.stmts.size(), 3u) << name;
    EXPECT_EQ(b.stmts[0].kind, StmtKind::ProcCall) << name;
    EXPECT_EQ(b.stmts[0].name, name);
    const Node& call = b.node(b.stmts[0].expr);
    EXPECT_EQ(call.kind, NodeKind::Call);
    EXPECT_EQ(call.b, 1);  // one argument: the axis
  }
  // Any other name with brackets and no '=' stays a syntax error (an indexed variable).
  EXPECT_EQ(parseAlarm("R[1]"), toInt(AlarmNumber::SyntaxError));
}

TEST(TurningSyntax, DiameterAndRadiusModesOfOneWord) {
  Block b;
  parseBlock("X=DAC(50) Y=DIC(2) Z=RAC(3)", 1, b, {});
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[0].mode, AxisMode::DAC);
  EXPECT_EQ(b.stmts[1].mode, AxisMode::DIC);
  EXPECT_EQ(b.stmts[2].mode, AxisMode::RAC);
  Block c;
  parseBlock("X=RIC(1)", 1, c, {});
  EXPECT_EQ(c.stmts[0].mode, AxisMode::RIC);
  EXPECT_EQ(parseAlarm("G2 X10 I=DAC(5)"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("G2 X10 CR=DIC(5)"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("X=DAC(1,2)"), toInt(AlarmNumber::SyntaxError));
}

}  // namespace
}  // namespace ncoffset::lang
