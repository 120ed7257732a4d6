// Parser of one NC block (src/lang/parser.hpp): line normalisation, statement kinds, syntax
// alarms and the line-head scan used by the control-structure pre-scan.
#include "lang/parser.hpp"

#include <gtest/gtest.h>

#include <string>

#include "ncoffset/alarm.hpp"
#include "parse_alarm.hpp"

namespace ncoffset::lang {
namespace {

Block parse(std::string_view text, const ParseLimits& limits = {}) {
  Block b;
  parseBlock(text, 7, b, limits);
  return b;
}

double num(const Block& b, int node) {
  const Node& n = b.node(node);
  EXPECT_EQ(n.kind, NodeKind::Number);
  return n.number;
}

// The value of a word: plain numbers (X10) are kept in the statement, expressions in nodes.
double wordValue(const Block& b, const Stmt& s) {
  if (s.literal) return s.literal_value;
  return num(b, s.expr);
}
bool wordIsInt(const Block& b, const Stmt& s) {
  return s.literal ? s.literal_int : b.node(s.expr).is_int;
}

// ---- normalizeLine ---------------------------------------------------------------------------

TEST(NormalizeLine, UpperCasesAndCutsComment) {
  std::string out;
  int bad = -1;
  ASSERT_TRUE(normalizeLine("g1 x10 y20 ; move fast", out, &bad));
  EXPECT_EQ(out, "G1 X10 Y20 ");
  ASSERT_TRUE(normalizeLine("; only a comment", out, &bad));
  EXPECT_EQ(out, "");
}

TEST(NormalizeLine, KeepsStringLiteralsAsWritten) {
  std::string out;
  ASSERT_TRUE(normalizeLine("msg(\"Hello; World\") ; note", out, nullptr));
  EXPECT_EQ(out, "MSG(\"Hello; World\") ");
  // Characters outside printable ASCII are allowed inside a string.
  ASSERT_TRUE(normalizeLine("msg(\"Ma\xC3\x9F\") x1", out, nullptr));
  EXPECT_EQ(out, "MSG(\"Ma\xC3\x9F\") X1");
}

TEST(NormalizeLine, TabsBecomeBlanks) {
  std::string out;
  ASSERT_TRUE(normalizeLine("g1\tx1\t", out, nullptr));
  EXPECT_EQ(out, "G1 X1 ");
}

// A CR inside a line (the reader takes a CR before the LF with the line end), a form feed or a
// vertical tab is no blank but a bad byte (issue 14, item 7); in a comment or string it is kept.
TEST(NormalizeLine, CarriageReturnFormFeedAndVerticalTabAreBadBytes) {
  std::string out;
  int bad = 0;
  EXPECT_FALSE(normalizeLine("G1 X10 F100\rY10\rZ-5", out, &bad));
  EXPECT_EQ(bad, 12);
  EXPECT_FALSE(normalizeLine("g1\tx1\r", out, &bad));
  EXPECT_EQ(bad, 6);
  EXPECT_FALSE(normalizeLine("\fG1 X1", out, &bad));
  EXPECT_EQ(bad, 1);
  EXPECT_FALSE(normalizeLine("G1\vX1", out, &bad));
  EXPECT_EQ(bad, 3);
  EXPECT_TRUE(normalizeLine("G1 X1 ; \r\f", out, &bad));
  EXPECT_TRUE(normalizeLine("MSG(\"a\rb\")", out, &bad));
}

TEST(Parser, CarriageReturnInsideALineRaises99011NamingIt) {
  Block b;
  try {
    parseBlock("G1 X10 F100\rY10\rZ-5", 1, b);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::BadCharacter));
    EXPECT_NE(e.text().find("0x0D (carriage return not followed by a line feed) at column 12"),
              std::string::npos)
        << e.text();
  }
  EXPECT_EQ(parseAlarm("G1 X1\f"), toInt(AlarmNumber::BadCharacter));
}

TEST(NormalizeLine, BadBytesOutsideCommentsAndStrings) {
  std::string out;
  int bad = 0;
  EXPECT_FALSE(normalizeLine("G1\x01X10", out, &bad));
  EXPECT_EQ(bad, 3);
  EXPECT_FALSE(normalizeLine("G1 X\xE4", out, &bad));
  EXPECT_EQ(bad, 5);
  EXPECT_FALSE(normalizeLine(std::string_view("X1\0", 3), out, &bad));
  EXPECT_EQ(bad, 3);
  // Non-ASCII in a comment is fine.
  EXPECT_TRUE(normalizeLine("G1 X1 ; \xE4\xF6\xFC \x01", out, &bad));
  EXPECT_EQ(out, "G1 X1 ");
}

// normalizeLine copies plain text eight bytes at a time (the last group overlapping) and
// everything else byte by byte; shifting a line by k blanks moves every character across those
// groups, and must shift the result (or the bad column) by k and change nothing else.
TEST(NormalizeLine, SameResultAtEveryAlignment) {
  const std::string base = "G1 X10.5 Y-2 CR=10 F1000";
  const char specials[] = {';', 'a', '"', '\t', '\x01', '\xE4', 'z', '\r'};
  for (size_t len = 1; len <= base.size(); ++len) {
    for (size_t at = 0; at <= len; ++at) {
      for (char special : specials) {
        std::string text = base.substr(0, len);
        if (at < len) text[at] = special;
        std::string expected;
        int expected_bad = 0;
        const bool expected_ok = normalizeLine(text, expected, &expected_bad);
        for (size_t k = 1; k <= 9; ++k) {
          std::string out;
          int bad = 0;
          const bool ok = normalizeLine(std::string(k, ' ') + text, out, &bad);
          ASSERT_EQ(ok, expected_ok) << text << " shifted by " << k;
          if (ok)
            EXPECT_EQ(out, std::string(k, ' ') + expected) << text << " shifted by " << k;
          else
            EXPECT_EQ(bad, expected_bad + static_cast<int>(k)) << text << " shifted by " << k;
        }
      }
    }
  }
}

TEST(Parser, BadCharacterRaises99011) {
  EXPECT_EQ(parseAlarm("G1 X\xE4"), toInt(AlarmNumber::BadCharacter));
  EXPECT_EQ(parseAlarm("G1 X1 ; \xE4"), 0);
}

// ---- words -----------------------------------------------------------------------------------

TEST(Parser, NumericAddressesSplitWithoutSpaces) {
  Block b = parse("G1X10Y-5.5Z+.5");
  EXPECT_EQ(b.line, 7);
  ASSERT_EQ(b.stmts.size(), 4u);
  const char* names[] = {"G", "X", "Y", "Z"};
  const double values[] = {1, 10, -5.5, 0.5};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(b.stmts[i].kind, StmtKind::Word);
    EXPECT_EQ(b.stmts[i].name, names[i]);
    EXPECT_FALSE(b.stmts[i].has_equals);
    EXPECT_EQ(b.stmts[i].mode, AxisMode::Default);
    EXPECT_DOUBLE_EQ(wordValue(b, b.stmts[i]), values[i]);
  }
  EXPECT_TRUE(wordIsInt(b, b.stmts[0]));
  EXPECT_FALSE(wordIsInt(b, b.stmts[2]));
  EXPECT_EQ(b.stmts[0].column, 1);
  EXPECT_EQ(b.stmts[1].column, 3);
}

TEST(Parser, LowerCaseIsAccepted) {
  Block b = parse("g1 x10");
  ASSERT_EQ(b.stmts.size(), 2u);
  EXPECT_EQ(b.stmts[1].name, "X");
}

TEST(Parser, NumberForms) {
  Block b = parse("X1.5EX3 Y='H1F' F.5");
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_DOUBLE_EQ(wordValue(b, b.stmts[0]), 1500);
  EXPECT_FALSE(wordIsInt(b, b.stmts[0]));
  EXPECT_DOUBLE_EQ(wordValue(b, b.stmts[1]), 31);
  EXPECT_DOUBLE_EQ(wordValue(b, b.stmts[2]), 0.5);
  Block c = parse("R1='H1F' R2='B101' R3=1.5EX-2");
  ASSERT_EQ(c.stmts.size(), 3u);
  EXPECT_DOUBLE_EQ(wordValue(c, c.stmts[0]), 31);
  EXPECT_DOUBLE_EQ(wordValue(c, c.stmts[1]), 5);
  EXPECT_DOUBLE_EQ(wordValue(c, c.stmts[2]), 0.015);
  // Shortest decimal forms convert exactly like strtod.
  Block d = parse("X0.1 Y123456.789");
  EXPECT_EQ(wordValue(d, d.stmts[0]), 0.1);
  EXPECT_EQ(wordValue(d, d.stmts[1]), 123456.789);
}

TEST(Parser, AddressWithExpression) {
  Block b = parse("X=R1+2");
  ASSERT_EQ(b.stmts.size(), 1u);
  const Stmt& s = b.stmts[0];
  EXPECT_EQ(s.kind, StmtKind::Word);
  EXPECT_EQ(s.name, "X");
  EXPECT_TRUE(s.has_equals);
  const Node& e = b.node(s.expr);
  ASSERT_EQ(e.kind, NodeKind::Binary);
  EXPECT_EQ(e.op, Op::Add);
  EXPECT_EQ(b.node(e.a).kind, NodeKind::RParam);
  EXPECT_EQ(b.node(e.a).number, 1);
  EXPECT_EQ(num(b, e.b), 2);
}

TEST(Parser, AcAndIcDimensions) {
  Block b = parse("X=AC(5) Y=IC(-2) Z=3");
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[0].mode, AxisMode::AC);
  EXPECT_EQ(wordValue(b, b.stmts[0]), 5);
  EXPECT_EQ(b.stmts[1].mode, AxisMode::IC);
  const Node& y = b.node(b.stmts[1].expr);
  ASSERT_EQ(y.kind, NodeKind::Unary);
  EXPECT_EQ(y.op, Op::Neg);
  EXPECT_EQ(b.stmts[2].mode, AxisMode::Default);
  EXPECT_EQ(b.stmts[2].name, "Z");
  // I=AC(..) for an absolute centre.
  Block c = parse("G2 X10 I=AC(5) J=AC(0)");
  ASSERT_EQ(c.stmts.size(), 4u);
  EXPECT_EQ(c.stmts[2].name, "I");
  EXPECT_EQ(c.stmts[2].mode, AxisMode::AC);
  EXPECT_EQ(parseAlarm("X=AC(1,2)"), toInt(AlarmNumber::SyntaxError));
}

TEST(Parser, AddressExtension) {
  Block b = parse("M2=6 S1=1000 M30");
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[0].name, "M");
  EXPECT_EQ(b.stmts[0].ext, 2);
  EXPECT_EQ(wordValue(b, b.stmts[0]), 6);
  EXPECT_EQ(b.stmts[1].name, "S");
  EXPECT_EQ(b.stmts[1].ext, 1);
  EXPECT_EQ(b.stmts[2].name, "M");
  EXPECT_EQ(b.stmts[2].ext, -1);
  EXPECT_EQ(wordValue(b, b.stmts[2]), 30);
}

TEST(Parser, NamedAddresses) {
  Block b = parse("G2 X10 Y0 CR=-5 F=100");
  ASSERT_EQ(b.stmts.size(), 5u);
  EXPECT_EQ(b.stmts[3].kind, StmtKind::Word);
  EXPECT_EQ(b.stmts[3].name, "CR");
  EXPECT_TRUE(b.stmts[3].has_equals);
  EXPECT_EQ(b.stmts[4].kind, StmtKind::Word);
  EXPECT_EQ(b.stmts[4].name, "F");
}

// ---- assignments and calls -------------------------------------------------------------------

TEST(Parser, RParameterAssignment) {
  Block b = parse("R1=5 R[2]=R1*2 R10 = 1");
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[0].kind, StmtKind::Assign);
  EXPECT_EQ(b.stmts[0].name, "R");
  EXPECT_EQ(b.node(b.stmts[0].target).kind, NodeKind::RParam);
  EXPECT_EQ(b.node(b.stmts[0].target).number, 1);
  EXPECT_EQ(wordValue(b, b.stmts[0]), 5);
  EXPECT_EQ(b.stmts[1].kind, StmtKind::Assign);
  EXPECT_EQ(b.node(b.stmts[1].target).kind, NodeKind::RIndex);
  EXPECT_EQ(b.node(b.stmts[2].target).number, 10);
}

TEST(Parser, SystemVariableArrayAssignment) {
  Block b = parse("$TC_DP1[1,1]=3");
  ASSERT_EQ(b.stmts.size(), 1u);
  const Stmt& s = b.stmts[0];
  EXPECT_EQ(s.kind, StmtKind::Assign);
  EXPECT_EQ(s.name, "$TC_DP1");
  const Node& t = b.node(s.target);
  EXPECT_EQ(t.kind, NodeKind::Index);
  EXPECT_EQ(t.text, "$TC_DP1");
  ASSERT_EQ(t.b, 2);
  EXPECT_EQ(num(b, b.arg(t, 0)), 1);
  EXPECT_EQ(num(b, b.arg(t, 1)), 1);
  EXPECT_EQ(num(b, s.expr), 3);
}

TEST(Parser, FrameComponentAndNamedAssignments) {
  Block b = parse("$P_UIFR[1,X,TR]=10 $SC_TOOL_LENGTH_CONST=17 VAR1=2");
  ASSERT_EQ(b.stmts.size(), 3u);
  const Node& t = b.node(b.stmts[0].target);
  ASSERT_EQ(t.b, 3);
  EXPECT_EQ(b.node(b.arg(t, 1)).kind, NodeKind::Name);
  EXPECT_EQ(b.node(b.arg(t, 1)).text, "X");
  EXPECT_EQ(b.node(b.arg(t, 2)).text, "TR");
  EXPECT_EQ(b.stmts[1].kind, StmtKind::Assign);
  EXPECT_EQ(b.stmts[1].name, "$SC_TOOL_LENGTH_CONST");
  EXPECT_EQ(b.stmts[2].kind, StmtKind::Assign);
  EXPECT_EQ(b.stmts[2].name, "VAR1");
}

TEST(Parser, CallsAndProcedureCalls) {
  Block b = parse("SUB1");
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(b.stmts[0].kind, StmtKind::Call);
  EXPECT_EQ(b.stmts[0].name, "SUB1");
  Block m = parse("MSG(\"Hello\")");
  ASSERT_EQ(m.stmts.size(), 1u);
  EXPECT_EQ(m.stmts[0].kind, StmtKind::ProcCall);
  EXPECT_EQ(m.stmts[0].name, "MSG");
  const Node& c = m.node(m.stmts[0].expr);
  ASSERT_EQ(c.b, 1);
  EXPECT_EQ(m.node(m.arg(c, 0)).kind, NodeKind::String);
  EXPECT_EQ(m.node(m.arg(c, 0)).text, "Hello");
  Block t = parse("TRANS X10 Y=5");
  ASSERT_EQ(t.stmts.size(), 3u);
  EXPECT_EQ(t.stmts[0].kind, StmtKind::Call);
  EXPECT_EQ(t.stmts[0].name, "TRANS");
  // Left-out optional parameter is an empty Name node.
  Block e = parse("PROCX(1,,3)");
  const Node& pc = e.node(e.stmts[0].expr);
  ASSERT_EQ(pc.b, 3);
  EXPECT_EQ(e.node(e.arg(pc, 1)).kind, NodeKind::Name);
  EXPECT_TRUE(e.node(e.arg(pc, 1)).text.empty());
}

// ---- DEF -------------------------------------------------------------------------------------

TEST(Parser, DefScalarsWithInitialValues) {
  Block b = parse("DEF REAL A=1.5, B, C=2*3");
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(b.stmts[0].kind, StmtKind::Keyword);
  EXPECT_EQ(b.stmts[0].name, "DEF");
  ASSERT_EQ(b.decls.size(), 3u);
  EXPECT_EQ(b.decls[0].type, VarType::Real);
  EXPECT_EQ(b.decls[0].name, "A");
  EXPECT_EQ(num(b, b.decls[0].init), 1.5);
  EXPECT_EQ(b.decls[1].name, "B");
  EXPECT_EQ(b.decls[1].init, -1);
  EXPECT_EQ(b.node(b.decls[2].init).kind, NodeKind::Binary);
}

TEST(Parser, DefTypesArraysAndStrings) {
  Block a = parse("DEF INT K[3]=SET(1,2,3)");
  ASSERT_EQ(a.decls.size(), 1u);
  EXPECT_EQ(a.decls[0].type, VarType::Int);
  EXPECT_EQ(a.decls[0].dims[0], 3);
  EXPECT_EQ(a.decls[0].dims[1], 0);
  EXPECT_EQ(a.decls[0].init_count, 3);
  EXPECT_FALSE(a.decls[0].init_rep);

  Block m = parse("DEF REAL MM[2,3]=REP(0)");
  ASSERT_EQ(m.decls.size(), 1u);
  EXPECT_EQ(m.decls[0].dims[0], 2);
  EXPECT_EQ(m.decls[0].dims[1], 3);
  EXPECT_TRUE(m.decls[0].init_rep);
  EXPECT_EQ(m.decls[0].init_count, 1);

  Block s = parse("DEF STRING[20] NAME=\"abc\"");
  ASSERT_EQ(s.decls.size(), 1u);
  EXPECT_EQ(s.decls[0].type, VarType::String);
  EXPECT_EQ(s.decls[0].string_length, 20);
  EXPECT_EQ(s.node(s.decls[0].init).text, "abc");

  const std::pair<const char*, VarType> kinds[] = {
      {"DEF BOOL FLAG=TRUE", VarType::Bool}, {"DEF CHAR C", VarType::Char},
      {"DEF AXIS AX=X", VarType::Axis},      {"DEF FRAME FR", VarType::Frame},
      {"DEF NCK INT GG", VarType::Int},      {"DEF CHAN REAL HH", VarType::Real}};
  for (const auto& [text, type] : kinds) {
    Block d = parse(text);
    ASSERT_EQ(d.decls.size(), 1u) << text;
    EXPECT_EQ(d.decls[0].type, type) << text;
  }
}

TEST(Parser, DefErrors) {
  EXPECT_EQ(parseAlarm("DEF FOO A"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF STRING S"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF STRING[0] S"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT A[1,2,3]"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT A[0]"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT A[N]"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT A B"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("DEF INT K[3]=1"), toInt(AlarmNumber::SyntaxError));
}

// ---- control flow ----------------------------------------------------------------------------

TEST(Parser, IfWhileUntilCarryCondition) {
  for (const char* kw : {"IF", "WHILE", "UNTIL"}) {
    Block b = parse(std::string(kw) + " (R1==1) AND (R2<>2)");
    ASSERT_EQ(b.stmts.size(), 1u) << kw;
    EXPECT_EQ(b.stmts[0].kind, StmtKind::Keyword);
    EXPECT_EQ(b.stmts[0].name, kw);
    const Node& c = b.node(b.stmts[0].expr);
    ASSERT_EQ(c.kind, NodeKind::Binary);
    EXPECT_EQ(c.op, Op::And);
  }
}

TEST(Parser, IfWithJump) {
  Block b = parse("IF R1>=2 GOTOF LABEL1");
  ASSERT_EQ(b.stmts.size(), 2u);
  EXPECT_EQ(b.stmts[0].name, "IF");
  EXPECT_EQ(b.node(b.stmts[0].expr).op, Op::Ge);
  EXPECT_EQ(b.stmts[1].name, "GOTOF");
  EXPECT_EQ(b.stmts[1].jump, JumpKind::Gotof);
  EXPECT_EQ(b.node(b.stmts[1].target).kind, NodeKind::Name);
  EXPECT_EQ(b.node(b.stmts[1].target).text, "LABEL1");
}

TEST(Parser, BareStructureKeywords) {
  for (const char* kw : {"ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "REPEAT", "LOOP", "ENDLOOP"}) {
    Block b = parse(kw);
    ASSERT_EQ(b.stmts.size(), 1u) << kw;
    EXPECT_EQ(b.stmts[0].kind, StmtKind::Keyword);
    EXPECT_EQ(b.stmts[0].name, kw);
  }
}

TEST(Parser, ForLoop) {
  Block b = parse("FOR R1=1 TO 5");
  ASSERT_EQ(b.stmts.size(), 1u);
  const Stmt& s = b.stmts[0];
  EXPECT_EQ(s.name, "FOR");
  EXPECT_EQ(b.node(s.target).kind, NodeKind::RParam);
  EXPECT_EQ(b.node(s.target).number, 1);
  EXPECT_EQ(num(b, s.expr), 1);
  EXPECT_EQ(num(b, s.expr2), 5);
  Block v = parse("for i = 0 to n-1");
  ASSERT_EQ(v.stmts.size(), 1u);
  EXPECT_EQ(v.node(v.stmts[0].target).kind, NodeKind::Name);
  EXPECT_EQ(v.node(v.stmts[0].target).text, "I");
  EXPECT_EQ(v.node(v.stmts[0].expr2).op, Op::Sub);
}

TEST(Parser, JumpForms) {
  struct Case {
    const char* text;
    JumpKind jump;
    NodeKind kind;
    double number;
    const char* name;
  };
  const Case cases[] = {
      {"GOTOF LBL", JumpKind::Gotof, NodeKind::Name, 0, "LBL"},
      {"GOTOB N100", JumpKind::Gotob, NodeKind::BlockNo, 100, ""},
      {"GOTO :20", JumpKind::Goto, NodeKind::BlockNo, 20, ""},
      {"GOTOC 30", JumpKind::Gotoc, NodeKind::BlockNo, 30, ""},
      {"GOTOF DEST_VAR", JumpKind::Gotof, NodeKind::Name, 0, "DEST_VAR"},
  };
  for (const Case& c : cases) {
    Block b = parse(c.text);
    ASSERT_EQ(b.stmts.size(), 1u) << c.text;
    EXPECT_EQ(b.stmts[0].kind, StmtKind::Keyword) << c.text;
    EXPECT_EQ(b.stmts[0].jump, c.jump) << c.text;
    const Node& t = b.node(b.stmts[0].target);
    EXPECT_EQ(t.kind, c.kind) << c.text;
    if (c.kind == NodeKind::BlockNo)
      EXPECT_EQ(t.number, c.number) << c.text;
    else
      EXPECT_EQ(t.text, c.name) << c.text;
  }
  Block s = parse("GOTOF \"LBL\"");
  EXPECT_EQ(s.node(s.stmts[0].target).kind, NodeKind::String);
}

TEST(Parser, CaseArms) {
  Block b = parse("CASE(R1) OF 1 GOTOF A1 2 GOTOB N20 DEFAULT GOTOF C1");
  ASSERT_EQ(b.stmts.size(), 4u);
  EXPECT_EQ(b.stmts[0].kind, StmtKind::Keyword);
  EXPECT_EQ(b.stmts[0].name, "CASE");
  EXPECT_EQ(b.node(b.stmts[0].expr).kind, NodeKind::RParam);
  EXPECT_EQ(b.stmts[1].kind, StmtKind::CaseArm);
  EXPECT_EQ(wordValue(b, b.stmts[1]), 1);
  EXPECT_EQ(b.stmts[1].jump, JumpKind::Gotof);
  EXPECT_EQ(b.node(b.stmts[1].target).text, "A1");
  EXPECT_EQ(b.stmts[2].jump, JumpKind::Gotob);
  EXPECT_EQ(b.node(b.stmts[2].target).kind, NodeKind::BlockNo);
  EXPECT_EQ(b.node(b.stmts[2].target).number, 20);
  EXPECT_EQ(b.stmts[3].kind, StmtKind::CaseArm);
  EXPECT_EQ(b.stmts[3].expr, -1);
  EXPECT_EQ(b.node(b.stmts[3].target).text, "C1");
}

// ---- block head ------------------------------------------------------------------------------

TEST(Parser, BlockNumbersLabelsAndSkip) {
  Block n = parse("N10 G1 X1");
  EXPECT_TRUE(n.has_number);
  EXPECT_EQ(n.number, 10);
  EXPECT_EQ(n.stmts.size(), 2u);

  Block tight = parse("N10G1X5");
  EXPECT_EQ(tight.number, 10);
  EXPECT_EQ(tight.stmts.size(), 2u);

  Block c = parse(":20 X1");
  EXPECT_TRUE(c.has_number);
  EXPECT_EQ(c.number, 20);
  EXPECT_EQ(c.stmts.size(), 1u);

  Block l = parse("N30 START_1: G0 X0");
  EXPECT_EQ(l.number, 30);
  EXPECT_EQ(l.label, "START_1");
  EXPECT_EQ(l.stmts.size(), 2u);

  Block only = parse("MARK:");
  EXPECT_EQ(only.label, "MARK");
  EXPECT_TRUE(only.stmts.empty());
  EXPECT_FALSE(only.has_number);

  Block s = parse("/N40 X1");
  EXPECT_TRUE(s.skip);
  EXPECT_EQ(s.skip_level, 0);
  EXPECT_EQ(s.number, 40);
  Block s3 = parse("/3 X1");
  EXPECT_TRUE(s3.skip);
  EXPECT_EQ(s3.skip_level, 3);
  EXPECT_FALSE(parse("X1").skip);

  // An address followed by a digit is no label, a single letter is too short.
  Block x = parse("X10");
  EXPECT_TRUE(x.label.empty());
}

TEST(Parser, EmptyLinesAndComments) {
  EXPECT_TRUE(parse("").stmts.empty());
  EXPECT_TRUE(parse("   ").stmts.empty());
  EXPECT_TRUE(parse("; G1 X10").stmts.empty());
}

TEST(Parser, BlockIsReusable) {
  Block b;
  parseBlock("/N10 LBL: G1 X1 Y2 Z3", 1, b);
  parseBlock("X5", 2, b);
  EXPECT_EQ(b.line, 2);
  EXPECT_FALSE(b.has_number);
  EXPECT_TRUE(b.label.empty());
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(wordValue(b, b.stmts[0]), 5);
}

// The parser has a fast path for blocks of plain address words (G1 X10 CR=5); it must make
// exactly the statements the general path makes. A leading `CDON` (a bare name the fast path
// does not take) sends the same words through the general path, so each block below is parsed
// both ways and compared statement by statement (columns shifted by the 5 characters).
struct Parsed {
  int alarm = 0;
  Block block;
};
Parsed parseOrAlarm(const std::string& text) {
  Parsed r;
  try {
    parseBlock(text, 1, r.block);
  } catch (const AlarmError& e) {
    r.alarm = e.number();
  }
  return r;
}

void expectSameAsGeneralPath(const std::string& text) {
  SCOPED_TRACE(text);
  const Parsed fast = parseOrAlarm(text);
  const Parsed general = parseOrAlarm("CDON " + text);
  ASSERT_EQ(fast.alarm, general.alarm);
  if (fast.alarm) return;
  ASSERT_EQ(fast.block.stmts.size() + 1, general.block.stmts.size());
  for (size_t i = 0; i < fast.block.stmts.size(); ++i) {
    const Stmt& a = fast.block.stmts[i];
    const Stmt& b = general.block.stmts[i + 1];
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.ext, b.ext);
    EXPECT_EQ(a.mode, b.mode);
    EXPECT_EQ(a.has_equals, b.has_equals);
    EXPECT_EQ(a.column + 5, b.column);
    EXPECT_EQ(a.literal, b.literal);
    if (a.literal && b.literal) {
      EXPECT_EQ(a.literal_int, b.literal_int);
      EXPECT_EQ(a.literal_value, b.literal_value);  // bit for bit: same conversion
    }
  }
}

// The fast path takes a block as written when normalising would not change it, block number
// included; anything else is normalised first, as before.
TEST(Parser, PlainBlockAsWritten) {
  Block b = parse("N10 G1 X1.5 CR=2");
  EXPECT_TRUE(b.has_number);
  EXPECT_EQ(b.number, 10);
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[2].name, "CR");
  EXPECT_EQ(b.stmts[2].column, 13);
  Block c = parse("n10 g1 x1.5 ; comment");
  EXPECT_TRUE(c.has_number);
  ASSERT_EQ(c.stmts.size(), 2u);
  EXPECT_EQ(c.stmts[1].name, "X");
  EXPECT_EQ(wordValue(c, c.stmts[1]), 1.5);
  EXPECT_EQ(parseAlarm("N1234567890123456789 X1"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm(std::string_view("G1 X1\0 Y2", 10)), toInt(AlarmNumber::BadCharacter));
  EXPECT_EQ(parseAlarm("G1 X1 \x01"), toInt(AlarmNumber::BadCharacter));
}

TEST(Parser, PlainWordFastPathMatchesGeneralPath) {
  for (const char* text : {"G1 X10.5 Y-2 F1000",
                           "G3 X100 Y10 CR=10",
                           "G1X10Y-5.5Z+.5",
                           "T1 D1",
                           "M30",
                           "X-.5",
                           "X.",
                           "X-",
                           "X+-5",
                           "X1.2.3",
                           "X10 =5",
                           "M2=6",
                           "I1=5",
                           "R1=5",
                           "R1 X5",
                           "R-5",
                           "CR=1EX2",
                           "X1EX2",
                           "X10E5",
                           "CR =10",
                           "CR==10",
                           "CR=10X5",
                           "DISC=50 G41",
                           "G1\tX1",
                           "X123456789012345678",
                           "X1234567890123456789",
                           "X0.1234567890123456",
                           "CR=-.5",
                           "DISR=+5",
                           "ABC=5",
                           "G1 X1 Y2 Z3 A4",
                           "X=10",
                           "S1000 M3",
                           "F.5",
                           "G64 X1",
                           "G1 X10 CDON",
                           "X10$P",
                           "X10_A",
                           "G1 X1 ;"}) {
    expectSameAsGeneralPath(text);
  }
  // Random sequences of tokens: whatever the fast path takes, it must take the same way.
  const std::string tokens[] = {
      "X",    "G",    "CR", "R",  "M",    "I", "E",  "EX",   "=",    "-",
      "+",    ".",    "1",  "10", "5.25", " ", "\t", "0",    "==",   "(",
      "DISC", "Y",    "F",  "x",  "cr",   ";", "\r", "\x01", "\xE4", std::string(1, '\0'),
      "N",    "\"A\""};
  unsigned seed = 12345;
  for (int n = 0; n < 20000; ++n) {
    seed = seed * 1103515245u + 12345u;
    std::string text = (seed >> 16) % 2 ? "X" : "G";
    const int count = static_cast<int>((seed >> 8) % 9);
    for (int k = 0; k < count; ++k) {
      seed = seed * 1103515245u + 12345u;
      text += tokens[(seed >> 16) % std::size(tokens)];
    }
    expectSameAsGeneralPath(text);
    if (HasFailure()) break;
  }
}

// ---- syntax errors ---------------------------------------------------------------------------

TEST(Parser, SyntaxErrorsRaise12080) {
  const char* broken[] = {
      "X=",                    // no value after '='
      "=5",                    // '=' without address
      "R1",                    // R parameter without '='
      "R1=(2+3",               // missing ')'
      "R1=2+",                 // missing operand
      "R1=*2",                 // operand expected
      "X10.5.5",               // two decimal points
      "IF",                    // condition missing
      "FOR R1=1",              // TO missing
      "FOR =1 TO 2",           // loop variable missing
      "CASE R1 OF 1 GOTOF A",  // '(' missing
      "CASE(R1) 1 GOTOF A",    // OF missing
      "CASE(R1) OF 1 X10",     // GOTOF/GOTOB missing
      "GOTOF",                 // destination missing
      "MSG(\"open",            // unterminated string
      "R1='H1G'",              // bad hex digit
      "R1='X1'",               // unknown constant
      "R1='H1F",               // unterminated constant
      "$TC_DP1[1,1]",          // indexed variable without '='
      "$TC_DP1[1,1 =3",        // ']' missing
      "X1 )",                  // stray ')'
      "M100=5",                // address extension too large
      "R1=5 + 1 2",            // digits after an expression
  };
  for (const char* text : broken)
    EXPECT_EQ(parseAlarm(text), toInt(AlarmNumber::SyntaxError)) << text;
}

// EX directly after a number is its exponent or an error, never the next word (issue 14, item
// 6: `R1=1EX` used to be R1=1 and a call of EX.SPF).
TEST(Parser, ExWithoutExponentIsASyntaxError) {
  for (const char* text : {"R1=1EX", "G1 X1EX F100", "X1EX", "CR=5EX", "R1=2*1.5EX+", "X1EXY"})
    EXPECT_EQ(parseAlarm(text), toInt(AlarmNumber::SyntaxError)) << text;
  EXPECT_EQ(parseAlarm("G1 X1EX2 F100"), 0);
  EXPECT_EQ(parseAlarm("G1 X1 EXX"), 0);  // a name after a blank is a word of its own
}

TEST(Parser, AddressWithoutValueIsASyntaxError) {
  // A lone address letter has no value. It cannot be a subprogram call either: only names that
  // start with two letters (or _ and a letter) can be called by name (PM-NC 12/2019 p491).
  EXPECT_EQ(parseAlarm("G1 X"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("G1 X10 Y"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(parseAlarm("Z"), toInt(AlarmNumber::SyntaxError));
}

TEST(Parser, SyntaxAlarmNamesColumn) {
  Block b;
  try {
    parseBlock("G1 X10 Y=", 1, b);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::SyntaxError));
    EXPECT_NE(e.text().find("column"), std::string::npos) << e.text();
  }
}

TEST(Parser, ExpressionDepthLimit) {
  ParseLimits small;
  small.max_expression_depth = 5;
  EXPECT_EQ(parseAlarm("R1=((1))", small), 0);
  EXPECT_EQ(parseAlarm("R1=((((((((1))))))))", small), toInt(AlarmNumber::ExpressionDepth));
  EXPECT_EQ(parseAlarm("R1=--------1", small), toInt(AlarmNumber::ExpressionDepth));
  // The default limit of 64 is enough for ordinary nesting, not for 200 parentheses.
  std::string deep = "R1=" + std::string(200, '(') + "1" + std::string(200, ')');
  EXPECT_EQ(parseAlarm(deep), toInt(AlarmNumber::ExpressionDepth));
  std::string ok = "R1=" + std::string(20, '(') + "1" + std::string(20, ')');
  EXPECT_EQ(parseAlarm(ok), 0);
}

TEST(Parser, VeryDeepInputDoesNotCrash) {
  // 100k parentheses must end in the depth alarm, not a stack overflow.
  std::string deep = "R1=" + std::string(100000, '(') + "1";
  EXPECT_EQ(parseAlarm(deep), toInt(AlarmNumber::ExpressionDepth));
  std::string neg = "R1=" + std::string(100000, '-') + "1";
  EXPECT_EQ(parseAlarm(neg), toInt(AlarmNumber::ExpressionDepth));
}

// ---- expression shape (priorities) -----------------------------------------------------------

TEST(Parser, ComparisonsBindWeakest) {
  Block b = parse("R1=1+2==3");
  const Node& top = b.node(b.stmts[0].expr);
  EXPECT_EQ(top.op, Op::Eq);
  Block a = parse("R1=R2==1 AND R3==2");
  // (R2 == (1 AND R3)) == 2
  const Node& t = a.node(a.stmts[0].expr);
  ASSERT_EQ(t.op, Op::Eq);
  const Node& l = a.node(t.a);
  ASSERT_EQ(l.op, Op::Eq);
  EXPECT_EQ(a.node(l.b).op, Op::And);
  Block c = parse("R1=$P_UIFR[1]:CROT(Z,30)");
  EXPECT_EQ(c.node(c.stmts[0].expr).op, Op::Chain);
}

// ---- scanLineHead ----------------------------------------------------------------------------

TEST(ScanLineHead, KeywordAfterNumberAndLabel) {
  LineHead h = scanLineHead("N10 IF R1==1");
  EXPECT_EQ(h.keyword, "IF");
  EXPECT_TRUE(h.label.empty());
  EXPECT_FALSE(h.has_goto);

  h = scanLineHead("LOOP1: WHILE R1<3");
  EXPECT_EQ(h.label, "LOOP1");
  EXPECT_EQ(h.keyword, "WHILE");

  h = scanLineHead("/1 :20 ENDIF");
  EXPECT_EQ(h.keyword, "ENDIF");

  h = scanLineHead("N5 MARK:");
  EXPECT_EQ(h.label, "MARK");
  EXPECT_TRUE(h.keyword.empty());

  h = scanLineHead("IF(R1==1)");
  EXPECT_EQ(h.keyword, "IF");

  EXPECT_TRUE(scanLineHead("").keyword.empty());
  EXPECT_TRUE(scanLineHead("   ").keyword.empty());
}

TEST(ScanLineHead, IfAsJump) {
  EXPECT_TRUE(scanLineHead("IF R1==1 GOTOF END").has_goto);
  EXPECT_TRUE(scanLineHead("IF R1==1 GOTOB N10").has_goto);
  EXPECT_TRUE(scanLineHead("IF R1==1 GOTO LBL").has_goto);
  EXPECT_TRUE(scanLineHead("IF R1==1 GOTOC LBL").has_goto);
  EXPECT_TRUE(scanLineHead("IF R1==1 GOTOF").has_goto);
  // Names that merely contain GOTO are no jump.
  EXPECT_FALSE(scanLineHead("IF GOTO_VAR==1").has_goto);
  EXPECT_FALSE(scanLineHead("IF XGOTOF==1").has_goto);
  EXPECT_FALSE(scanLineHead("IF R1==1").has_goto);
  // Only IF is examined.
  EXPECT_FALSE(scanLineHead("WHILE R1 GOTOF X").has_goto);
}

}  // namespace
}  // namespace ncoffset::lang
