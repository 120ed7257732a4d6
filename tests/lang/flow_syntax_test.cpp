// The syntax of issue 15 (src/lang/control_parser.cpp): REPEAT/REPEATB with labels and pass
// count, DEFINE .. AS, DEF NCK/CHAN with attributes (docs/language.md).
#include <gtest/gtest.h>

#include <string>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"
#include "parse_alarm.hpp"

namespace ncoffset::lang {
namespace {

Block parse(std::string_view text) {
  Block b;
  parseBlock(text, 1, b);
  return b;
}

TEST(FlowSyntax, RepeatForms) {
  Block b = parse("repeat start_1 end_1 p=2*3");
  ASSERT_EQ(b.stmts.size(), 1u);
  const Stmt& s = b.stmts[0];
  EXPECT_EQ(s.name, "REPEAT");
  EXPECT_EQ(b.node(s.target).text, "START_1");
  EXPECT_EQ(b.node(s.expr2).text, "END_1");
  EXPECT_GE(s.expr, 0);

  Block one = parse("REPEAT LBL P3");
  EXPECT_EQ(one.stmts[0].expr2, -1);
  EXPECT_GE(one.stmts[0].expr, 0);

  Block ends = parse("REPEAT LBL ENDLABEL");
  EXPECT_EQ(ends.node(ends.stmts[0].expr2).text, "ENDLABEL");
  EXPECT_EQ(ends.stmts[0].expr, -1);

  Block blockwise = parse("REPEATB LBL P=4");
  EXPECT_EQ(blockwise.stmts[0].name, "REPEATB");
  EXPECT_EQ(blockwise.stmts[0].expr2, -1);

  Block loop = parse("REPEAT   ");  // the bare REPEAT of REPEAT .. UNTIL
  EXPECT_EQ(loop.stmts[0].target, -1);
}

TEST(FlowSyntax, RepeatErrors) {
  EXPECT_EQ(parseAlarm("REPEATB"), 12080);        // label missing
  EXPECT_EQ(parseAlarm("REPEAT P=2"), 12080);     // P alone is no label
  EXPECT_EQ(parseAlarm("REPEAT A1 P=2"), 12080);  // not a label name
  EXPECT_EQ(parseAlarm("REPEATB AA BB"), 12080);  // REPEATB takes one label
  EXPECT_EQ(parseAlarm("REPEAT AA BB P=2 X1"), 12080);
}

TEST(FlowSyntax, Define) {
  Block b = parse("define Line as g1 X=10 ; comment");
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(b.stmts[0].name, "DEFINE");
  EXPECT_EQ(b.node(b.stmts[0].target).text, "LINE");
  EXPECT_EQ(b.node(b.stmts[0].expr).text, "G1 X=10");
  EXPECT_EQ(parseAlarm("DEFINE LINE G1"), 12080);  // AS missing
  EXPECT_EQ(parseAlarm("DEFINE LINE AS"), 12080);  // text missing
}

TEST(FlowSyntax, GlobalDefinitionsWithAttributes) {
  Block b = parse("DEF NCK SYNRW APWP 3 APRP 7 REAL PHU 1 LLI -1.5 ULI 20 DEPTH=5, DEPTH2");
  ASSERT_EQ(b.decls.size(), 2u);
  for (const auto& d : b.decls) {
    EXPECT_TRUE(d.global);
    EXPECT_EQ(d.type, VarType::Real);
    EXPECT_TRUE(d.attributes.has_lower);
    EXPECT_DOUBLE_EQ(d.attributes.lower, -1.5);
    EXPECT_TRUE(d.attributes.has_upper);
    EXPECT_DOUBLE_EQ(d.attributes.upper, 20);
  }
  EXPECT_EQ(b.decls[0].name, "DEPTH");
  Block local = parse("DEF STRING[8] ST=\"A\"");
  EXPECT_FALSE(local.decls[0].global);
  EXPECT_EQ(parseAlarm("DEF CHAN LLI REAL X1"), 12080);  // LLI without its value
}

}  // namespace
}  // namespace ncoffset::lang
