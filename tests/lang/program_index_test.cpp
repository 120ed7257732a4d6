// Control-structure pre-scan (src/lang/program_index.hpp): partner links, labels, and the
// structure alarms 12640/12641 with the offending line.
#include "lang/program_index.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

struct Indexed {
  std::shared_ptr<SourceFile> file;
  std::unique_ptr<ProgramIndex> index;

  // Byte offset of the start of 1-based line `n`.
  size_t offset(int n) const {
    TextPos pos;
    std::string_view line;
    while (pos.line < n && nextLine(file->text(), pos, line)) {
    }
    EXPECT_EQ(pos.line, n);
    return pos.offset;
  }
  // Line numbers of the partner/end of the structure statement on line `n` (0 if none).
  int partner(int n) const {
    const ControlLink* l = index->link(offset(n));
    return l ? l->partner.line : 0;
  }
  int end(int n) const {
    const ControlLink* l = index->link(offset(n));
    return l ? l->end.line : 0;
  }
};

Indexed build(const std::string& text, int max_depth = 16, size_t max_line = 65536) {
  Indexed r;
  r.file = SourceFile::fromString("TEST.MPF", text);
  r.index = std::make_unique<ProgramIndex>(*r.file, max_depth, max_line);
  return r;
}

struct Failure {
  int number = 0;
  int line = 0;
};
Failure failure(const std::string& text, int max_depth = 16) {
  auto file = SourceFile::fromString("TEST.MPF", text);
  try {
    ProgramIndex idx(*file, max_depth, 65536);
  } catch (const AlarmError& e) {
    return {e.number(), e.line()};
  }
  return {};
}

TEST(NextLine, SplitsLfAndCrlf) {
  std::string_view text = "A\r\nBB\n\nC";
  TextPos pos;
  std::string_view line;
  ASSERT_TRUE(nextLine(text, pos, line));
  EXPECT_EQ(line, "A");
  EXPECT_EQ(pos.line, 2);
  ASSERT_TRUE(nextLine(text, pos, line));
  EXPECT_EQ(line, "BB");
  ASSERT_TRUE(nextLine(text, pos, line));
  EXPECT_EQ(line, "");
  ASSERT_TRUE(nextLine(text, pos, line));
  EXPECT_EQ(line, "C");
  EXPECT_FALSE(nextLine(text, pos, line));
}

TEST(ProgramIndex, IfElseEndif) {
  Indexed p = build(
      "G1 X1 F100\n"  // 1
      "IF R1==1\n"    // 2
      "G1 X2\n"       // 3
      "ELSE\n"        // 4
      "G1 X3\n"       // 5
      "ENDIF\n"       // 6
      "M30\n");
  EXPECT_EQ(p.partner(2), 4);
  EXPECT_EQ(p.end(2), 6);
  EXPECT_EQ(p.partner(4), 6);
  EXPECT_EQ(p.partner(6), 2);
  EXPECT_EQ(p.partner(1), 0);
  EXPECT_EQ(p.partner(3), 0);
}

TEST(ProgramIndex, IfWithoutElse) {
  Indexed p = build("IF R1==1\nG1 X2\nENDIF\n");
  EXPECT_EQ(p.partner(1), 3);
  EXPECT_EQ(p.end(1), 3);
  EXPECT_EQ(p.partner(3), 1);
}

TEST(ProgramIndex, NestedLoops) {
  Indexed p = build(
      "FOR R1=1 TO 3\n"      // 1
      "  WHILE R2<2\n"       // 2
      "    REPEAT\n"         // 3
      "      LOOP\n"         // 4
      "        GOTOF OUT\n"  // 5
      "      ENDLOOP\n"      // 6
      "    UNTIL R3>1\n"     // 7
      "  ENDWHILE\n"         // 8
      "ENDFOR\n"             // 9
      "OUT:\n");             // 10
  EXPECT_EQ(p.partner(1), 9);
  EXPECT_EQ(p.partner(9), 1);
  EXPECT_EQ(p.partner(2), 8);
  EXPECT_EQ(p.partner(8), 2);
  EXPECT_EQ(p.partner(3), 7);
  EXPECT_EQ(p.partner(7), 3);
  EXPECT_EQ(p.partner(4), 6);
  EXPECT_EQ(p.partner(6), 4);
  ASSERT_NE(p.index->label("OUT"), nullptr);
  EXPECT_EQ(p.index->label("OUT")->line, 10);
}

TEST(ProgramIndex, NumbersLabelsSkipAndCaseDoNotHideKeywords) {
  Indexed p = build(
      "n10 if r1==1\r\n"         // 1
      "/N20 LBL1: else\r\n"      // 2
      ":30 endif ; comment\r\n"  // 3
      "; IF in a comment\r\n"    // 4
      "MSG(\"IF\")\r\n");        // 5
  EXPECT_EQ(p.partner(1), 2);
  EXPECT_EQ(p.partner(2), 3);
  EXPECT_EQ(p.partner(3), 1);
  ASSERT_NE(p.index->label("LBL1"), nullptr);
  EXPECT_EQ(p.index->label("LBL1")->line, 2);
  EXPECT_EQ(p.index->label("LBL1")->offset, p.offset(2));
}

TEST(ProgramIndex, IfWithJumpIsNoStructure) {
  Indexed p = build(
      "IF R1==1 GOTOF SKIP\n"   // 1
      "G1 X1 F10\n"             // 2
      "SKIP: G1 X2\n"           // 3
      "IF R1==2 GOTOB N10\n");  // 4
  EXPECT_EQ(p.partner(1), 0);
  ASSERT_NE(p.index->label("SKIP"), nullptr);
  EXPECT_EQ(p.index->label("SKIP")->line, 3);
  // A jump far to the right of a long condition is still found.
  std::string long_if = "IF " + std::string(200, ' ') + "R1==1 GOTOF SKIP\nSKIP:\n";
  EXPECT_EQ(failure(long_if).number, 0);
}

TEST(ProgramIndex, Labels) {
  Indexed p = build("START: G1 X1 F1\nG1 X2\nN40 END_2: M30\n");
  ASSERT_NE(p.index->label("START"), nullptr);
  EXPECT_EQ(p.index->label("START")->line, 1);
  EXPECT_EQ(p.index->label("START")->offset, 0u);
  ASSERT_NE(p.index->label("END_2"), nullptr);
  EXPECT_EQ(p.index->label("END_2")->line, 3);
  EXPECT_EQ(p.index->label("NOPE"), nullptr);
  // Label lookup uses the upper-cased name.
  Indexed q = build("lower: G1 X1\n");
  EXPECT_NE(q.index->label("LOWER"), nullptr);
}

// A label may stand more than once (the control takes the first it meets in the jump's
// direction): every line is kept, in file order.
TEST(ProgramIndex, DuplicateLabelKeepsEveryLine) {
  Indexed p = build("LBL: G1 X1\nG1 X2\nLBL: G1 X3\n");
  const auto* lines = p.index->labels("LBL");
  ASSERT_NE(lines, nullptr);
  ASSERT_EQ(lines->size(), 2u);
  EXPECT_EQ((*lines)[0].line, 1);
  EXPECT_EQ((*lines)[1].line, 3);
  EXPECT_EQ(p.index->label("LBL")->line, 1);
}

// REPEAT with a label repeats a section; only the bare REPEAT opens a loop.
TEST(ProgramIndex, RepeatWithLabelIsNoLoop) {
  Indexed p = build(
      "AA: G1 X1\n"           // 1
      "REPEAT AA P=2\n"       // 2
      "REPEAT\n"              // 3
      "  REPEATB AA\n"        // 4
      "UNTIL R1>0\n"          // 5
      "REPEAT AA BB P=3\n");  // 6
  EXPECT_EQ(p.partner(2), 0);
  EXPECT_EQ(p.partner(3), 5);
  EXPECT_EQ(p.partner(6), 0);
}

TEST(ProgramIndex, InvalidNesting12640) {
  Failure f = failure("G1 X1\nG1 X2\nENDIF\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 3);

  f = failure("IF R1\nWHILE R2\nENDIF\nENDWHILE\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 3);

  f = failure("G1\nELSE\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 2);

  f = failure("IF R1\nELSE\nELSE\nENDIF\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 3);

  f = failure("WHILE 1\nELSE\nENDWHILE\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 2);

  f = failure("REPEAT\nENDWHILE\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 2);

  f = failure("LOOP\nUNTIL R1\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 2);
}

TEST(ProgramIndex, UnterminatedStructureNamesItsOpeningLine) {
  Failure f = failure("G1 X1\nWHILE R1<3\nG1 X2\nG1 X3\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 2);

  f = failure("IF 1\nFOR R1=1 TO 2\nENDFOR\nG1\n");
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlNesting));
  EXPECT_EQ(f.line, 1);
}

std::string nestedIfs(int depth) {
  std::string s;
  for (int i = 0; i < depth; ++i) s += "IF R1==1\n";
  for (int i = 0; i < depth; ++i) s += "ENDIF\n";
  return s;
}

TEST(ProgramIndex, DepthLimit12641) {
  EXPECT_EQ(failure(nestedIfs(16)).number, 0);
  Failure f = failure(nestedIfs(17));
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlDepth));
  EXPECT_EQ(f.line, 17);

  f = failure("WHILE 1\nFOR R1=1 TO 2\nLOOP\nENDLOOP\nENDFOR\nENDWHILE\n", 2);
  EXPECT_EQ(f.number, toInt(AlarmNumber::ControlDepth));
  EXPECT_EQ(f.line, 3);
  // Sequential structures do not add up.
  EXPECT_EQ(failure("IF 1\nENDIF\nIF 1\nENDIF\nIF 1\nENDIF\n", 1).number, 0);
}

TEST(ProgramIndex, OverlongLinesAreLeftForExecution) {
  std::string text = "G1 X1\nIF R1==1 ; " + std::string(100, 'x') + "\nG1\n";
  auto file = SourceFile::fromString("T.MPF", text);
  EXPECT_NO_THROW(ProgramIndex(*file, 16, 50));
}

// The usual lines (an upper-case letter other than N, then a digit) are passed over sixteen
// or, with AVX2, 32 characters at a time (skipUsualLines, docs/performance.md sections 34 and
// 45); the labels and structures between them must get the offsets and line numbers that
// reading line by line gives, whatever the lengths, the line ends (LF, CR LF) and where the
// groups fall. Both widths, where the processor has AVX2.
// `numbered`: block numbers before the usual lines and some labels (N10 G1 X5, N10G1, N10 LBL3:,
// N10 alone, N10 IF ...), which the scan passes over by a look at their head (§53).
void labelsAmongUsualLines(bool numbered = false);
TEST(ProgramIndex, LabelsAmongUsualLinesOfEveryLength) {
  labelsAmongUsualLines();
}
TEST(ProgramIndex, LabelsAmongUsualLinesSixteenAtATime) {
  ProgramIndex::wide_scan = false;
  labelsAmongUsualLines();
  ProgramIndex::wide_scan = true;
}
TEST(ProgramIndex, LabelsAmongNumberedUsualLines) {
  labelsAmongUsualLines(true);
  ProgramIndex::wide_scan = false;
  labelsAmongUsualLines(true);
  ProgramIndex::wide_scan = true;
}

// A block number for a numbered program's line: N, 1 to 6 digits, no blank, a blank or a tab.
std::string blockNumber(const std::function<unsigned(unsigned)>& next) {
  const char* const gaps[] = {"", " ", " ", "\t", "  "};
  return "N" + std::to_string(1 + next(999999) / (next(2) ? 1 : 1000)) + gaps[next(5)];
}

void labelsAmongUsualLines(bool numbered) {
  unsigned seed = 2026;
  auto next = [&](unsigned n) {
    seed = seed * 1103515245u + 12345u;
    return (seed >> 16) % n;
  };
  for (int program = 0; program < 400; ++program) {
    std::string text;
    std::vector<std::pair<std::string, int>> labels;
    int line = 1, open = 0;
    const unsigned lines = 1 + next(program < 200 ? 120 : 600);
    for (unsigned k = 0; k < lines; ++k, ++line) {
      const unsigned kind = next(10);
      if (numbered && next(2)) text += blockNumber(next);
      if (kind == 0) {
        labels.emplace_back("LBL" + std::to_string(k), line);
        text += labels.back().first + ":";
      } else if (kind == 1 && open < 3) {
        text += "WHILE 0";
        ++open;
      } else if (kind == 2 && open > 0) {
        text += "ENDWHILE";
        --open;
      } else if (kind == 3) {
        text += next(2) ? "N10 G1" : "X";  // a block number, a letter alone
      } else if (numbered && kind == 4) {
        const char* const others[] = {"GOTOF LBL0", "R1=2", "; N10 G1", "", "G", "_N_A", "M30"};
        text += others[next(7)];  // after a block number: no usual line
      } else {
        text += static_cast<char>('A' + next(13));  // A..M
        text += std::string(1 + next(40), static_cast<char>('0' + next(10)));
      }
      text += next(4) == 0 ? "\r\n" : "\n";
    }
    for (; open > 0; --open, ++line) text += "ENDWHILE\n";
    if (next(2)) text += "G1";  // a last line without its newline
    const Indexed r = build(text);
    for (const auto& [name, at] : labels) {
      const TextPos* pos = r.index->label(name);
      ASSERT_NE(pos, nullptr) << text;
      EXPECT_EQ(pos->line, at) << text;
      EXPECT_EQ(pos->offset, r.offset(at)) << text;
    }
  }
}

}  // namespace
}  // namespace ncoffset::lang
