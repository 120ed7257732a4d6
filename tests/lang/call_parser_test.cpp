// The subprogram statements of the parser (src/lang/call_parser.cpp): PROC with formal
// parameters and attributes, EXTERN, MCALL, CALL, PCALL, EXTCALL, L123(args).
#include <gtest/gtest.h>

#include <string>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"
#include "parse_alarm.hpp"

namespace ncoffset::lang {
namespace {

Block parse(std::string_view text) {
  Block b;
  parseBlock(text, 1, b, {});
  return b;
}

TEST(CallParser, ProcFormalParameters) {
  Block b = parse(
      "PROC NAME(REAL A, INT B, STRING[20] S, AXIS AXN, VAR REAL R, VAR REAL ARR[3], "
      "VAR REAL M[,3]) SAVE DISPLOF");
  ASSERT_EQ(b.stmts.size(), 1u);
  const Stmt& st = b.stmts[0];
  EXPECT_EQ(st.name, "PROC");
  EXPECT_EQ(b.node(st.target).text, "NAME");
  EXPECT_EQ(st.ext, 7);
  EXPECT_EQ(st.expr2, kProcSave | kProcDisplof);
  ASSERT_EQ(b.decls.size(), 7u);
  EXPECT_EQ(b.decls[0].type, VarType::Real);
  EXPECT_FALSE(b.decls[0].by_ref);
  EXPECT_EQ(b.decls[1].type, VarType::Int);
  EXPECT_EQ(b.decls[2].type, VarType::String);
  EXPECT_EQ(b.decls[2].string_length, 20);
  EXPECT_EQ(b.decls[3].type, VarType::Axis);
  EXPECT_TRUE(b.decls[4].by_ref);
  EXPECT_EQ(b.decls[5].dims[0], 3);
  EXPECT_EQ(b.decls[5].dims[1], 0);
  EXPECT_EQ(b.decls[6].dims[0], -1);  // open first dimension
  EXPECT_EQ(b.decls[6].dims[1], 3);
  EXPECT_EQ(b.decls[6].name, "M");
}

TEST(CallParser, ProcWithoutParametersAndAllAttributes) {
  Block b = parse("PROC CONTOUR SAVE SBLOF DISPLOF ACTBLOCNO ICYCOF PREPRO");
  EXPECT_EQ(b.stmts[0].ext, 0);
  EXPECT_EQ(b.stmts[0].expr2,
            kProcSave | kProcSblof | kProcDisplof | kProcActblocno | kProcIcycof | kProcPrepro);
}

TEST(CallParser, ProcErrors) {
  EXPECT_EQ(parseAlarm("PROC NAME(REAL ARR[3])"), 12080);       // arrays only with VAR
  EXPECT_EQ(parseAlarm("PROC NAME(REAL A) SAVE FAST"), 12080);  // unknown attribute
  EXPECT_EQ(parseAlarm("PROC NAME(REAL)"), 12080);              // the name is missing
  EXPECT_EQ(parseAlarm("PROC NAME(DOUBLE A)"), 12080);          // no such type
  EXPECT_EQ(parseAlarm("PROC NAME(REAL A"), 12080);
  EXPECT_EQ(parseAlarm("PROC NAME(REAL X1)"), 12170);  // a predefined name
}

TEST(CallParser, ExternTypesOnly) {
  Block b = parse("EXTERN NAME(REAL, VAR REAL[3], STRING[8], VAR INT[,2])");
  EXPECT_EQ(b.stmts[0].name, "EXTERN");
  EXPECT_EQ(b.stmts[0].ext, 4);
  EXPECT_TRUE(b.decls[1].by_ref);
  EXPECT_EQ(b.decls[1].dims[0], 3);
  EXPECT_EQ(b.decls[2].string_length, 8);
  EXPECT_EQ(b.decls[3].dims[0], -1);
  EXPECT_TRUE(b.decls[0].name.empty());
}

TEST(CallParser, ModalCall) {
  Block on = parse("MCALL CYCLE_X(1,,3)");
  const Node& n = on.node(on.stmts[0].target);
  EXPECT_EQ(n.kind, NodeKind::Call);
  EXPECT_EQ(n.text, "CYCLE_X");
  EXPECT_EQ(n.b, 3);
  Block l = parse("MCALL L70");
  EXPECT_EQ(l.node(l.stmts[0].target).text, "L70");
  Block off = parse("MCALL");
  EXPECT_EQ(off.stmts[0].target, -1);
}

TEST(CallParser, CallForms) {
  Block c = parse("CALL \"PART\" BLOCK START_L TO N200");
  EXPECT_GE(c.stmts[0].expr, 0);
  EXPECT_EQ(c.node(c.stmts[0].target).text, "START_L");
  EXPECT_EQ(c.node(c.stmts[0].expr2).kind, NodeKind::BlockNo);
  Block same = parse("CALL BLOCK AA TO BB");
  EXPECT_EQ(same.stmts[0].expr, -1);
  Block p = parse("PCALL /_N_WKS_DIR/_N_SHAFT_WPD/_N_SHAFT_SPF(1,2)");
  EXPECT_EQ(p.node(p.stmts[0].target).text, "SHAFT");
  Block e = parse("EXTCALL (\"/EXT/PART.SPF\")");
  EXPECT_EQ(e.stmts[0].name, "EXTCALL");
  Block l = parse("L123(1, 2)");
  EXPECT_EQ(l.stmts[0].kind, StmtKind::ProcCall);
  EXPECT_EQ(l.stmts[0].name, "L123");
  EXPECT_EQ(parseAlarm("MCALL NAME X10 Y"), 12080);
}

}  // namespace
}  // namespace ncoffset::lang
