// Expressions that cannot overflow the stack (issue 14, item 1): operator chains as long as the
// default line limit allows evaluate (the evaluator walks left operands in a loop), and every
// kind of real nesting (parentheses, unary operators, calls, indices, operators of rising
// priority) is bounded by ParseLimits::max_expression_depth, itself at most kMaxExpressionDepth
// (alarm 99003), in assignments, axis words, IF conditions and init-file assignments.
#include <gtest/gtest.h>

#include <string>

#include "lang/evaluator.hpp"
#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset::lang {
namespace {

// Every name reads as 1, every function returns its first argument, R<n> is n.
class OnesEnv final : public Environment {
 public:
  bool read(std::string_view, std::span<const Value>, bool, Value& out) override {
    out = Value::integer(1);
    return true;
  }
  Value readR(double number) override { return Value::real(number); }
  Value call(std::string_view, std::span<const Value> args) override {
    return args.empty() ? Value::real(0) : args[0];
  }
  Value chain(const Value& a, const Value&) override { return a; }
};

const size_t kLine = Limits{}.max_line_length;  // 65536: the longest block by default

// prefix + unit repeated + suffix, as long as fits in the default line limit.
std::string longest(const std::string& prefix, const std::string& unit,
                    const std::string& suffix = "") {
  const size_t n = (kLine - prefix.size() - suffix.size()) / unit.size();
  std::string s = prefix;
  s.reserve(kLine);
  for (size_t i = 0; i < n; ++i) s += unit;
  s += suffix;
  EXPECT_GT(s.size(), kLine - unit.size() - 1);
  EXPECT_LE(s.size(), kLine);
  return s;
}
size_t repeats(const std::string& text, const std::string& unit) {
  size_t n = 0;
  for (size_t at = text.find(unit); at != std::string::npos; at = text.find(unit, at + 1)) ++n;
  return n;
}

class ExpressionDepth : public ::testing::Test {
 protected:
  OnesEnv env;
  Evaluator ev{env};
  Block block;

  // The value of the statement `k` of `text` (its expression), parsed with `limits`.
  Value value(const std::string& text, size_t k = 0, const ParseLimits& limits = {}) {
    parseBlock(text, 1, block, limits);
    return ev.eval(block, block.stmts.at(k).expr);
  }
  int alarm(const std::string& text, const ParseLimits& limits = {}) {
    try {
      value(text, 0, limits);
    } catch (const AlarmError& e) {
      return e.number();
    }
    return 0;
  }
  std::string alarmText(const std::string& text, const ParseLimits& limits = {}) {
    try {
      value(text, 0, limits);
    } catch (const AlarmError& e) {
      return e.text();
    }
    return "";
  }
};

// ---- chains of every binary operator, as long as one block may be ----------------------------

TEST_F(ExpressionDepth, ArithmeticChains) {
  const std::string plus = longest("R1=1", "+1");
  EXPECT_EQ(plus.size(), kLine);
  EXPECT_EQ(toNumber(value(plus)), 1 + static_cast<double>(repeats(plus, "+")));
  const std::string minus = longest("R1=100000", "-1");
  EXPECT_EQ(toNumber(value(minus)), 100000 - static_cast<double>(repeats(minus, "-")));
  EXPECT_EQ(toNumber(value(longest("R1=3", "*1"))), 3);
  Value quotient = value(longest("R1=3", "/1"));
  EXPECT_EQ(quotient.type, Type::Real);
  EXPECT_EQ(quotient.num, 3);
  EXPECT_EQ(toNumber(value(longest("R1=7", " DIV 1"))), 7);
  EXPECT_EQ(toNumber(value(longest("R1=7", " MOD 5"))), 2);
}

TEST_F(ExpressionDepth, LogicalBitAndComparisonChains) {
  EXPECT_TRUE(toBool(value(longest("R1=1", " AND 1"))));
  EXPECT_TRUE(toBool(value(longest("R1=0", " OR 0", " OR 1"))));
  const std::string x = longest("R1=1", " XOR 1");
  EXPECT_EQ(toBool(value(x)), (repeats(x, "XOR") + 1) % 2 == 1);
  EXPECT_EQ(toNumber(value(longest("R1=255", " B_AND 255"))), 255);
  EXPECT_EQ(toNumber(value(longest("R1=1", " B_OR 0"))), 1);
  EXPECT_TRUE(toBool(value(longest("R1=1", "==1"))));
  EXPECT_EQ(toNumber(value(longest("R1=R5", ":R6"))), 5);  // frame chain (env: the left one)
}

// Mixed priorities: every `*` chain is the right operand of a `+`, which the parser nests once.
TEST_F(ExpressionDepth, MixedPriorityChain) {
  const std::string text = longest("R1=0", "+2*3*1");
  EXPECT_EQ(toNumber(value(text)), 6 * static_cast<double>(repeats(text, "+")));
}

// ---- the same in every place an expression stands ----------------------------------------------

TEST_F(ExpressionDepth, AxisWordIfConditionAndInitAssignment) {
  // G1 F100 X=1-0-0-...: the X word's expression.
  const std::string axis = longest("G1 F100 X=1", "-0");
  parseBlock(axis, 1, block);
  ASSERT_EQ(block.stmts.size(), 3u);
  EXPECT_EQ(block.stmts[2].name, "X");
  EXPECT_EQ(toNumber(ev.eval(block, block.stmts[2].expr)), 1);
  // IF 1+1+...==n: the condition.
  const std::string cond = longest("IF 1", "+1", "==1");
  parseBlock(cond, 1, block);
  ASSERT_EQ(block.stmts.at(0).name, "IF");
  EXPECT_FALSE(toBool(ev.eval(block, block.stmts[0].expr)));
  EXPECT_TRUE(toBool(value(longest("IF 1", "*1", "==1"))));
  // An init file's $TC_DP6[1,1]=0+0+...+5.
  const std::string init = longest("$TC_DP6[1,1]=0", "+0", "+5");
  parseBlock(init, 1, block);
  ASSERT_EQ(block.stmts.at(0).kind, StmtKind::Assign);
  EXPECT_EQ(block.node(block.stmts[0].target).kind, NodeKind::Index);
  EXPECT_EQ(toNumber(ev.eval(block, block.stmts[0].expr)), 5);
}

// ---- real nesting: bounded by the depth limit, never by the stack -----------------------------

TEST_F(ExpressionDepth, NestingAsLongAsALineIsTheDepthAlarm) {
  const char* openers[] = {"(", "-", "+", "NOT ", "B_NOT ", "ABS(", "SIN(", "R[", "ARR[", "1+("};
  for (const char* opener : openers) {
    SCOPED_TRACE(opener);
    const std::string text = longest("R1=", opener);
    EXPECT_EQ(alarm(text), toInt(AlarmNumber::ExpressionDepth));
    parseBlock("G1 X1 F100", 1, block);  // the block is usable after the alarm
    EXPECT_EQ(alarm(longest("G1 F100 X=", opener)), toInt(AlarmNumber::ExpressionDepth));
    EXPECT_EQ(alarm(longest("IF ", opener)), toInt(AlarmNumber::ExpressionDepth));
    EXPECT_EQ(alarm(longest("$TC_DP6[1,1]=", opener)), toInt(AlarmNumber::ExpressionDepth));
  }
}

// The largest limit is kMaxExpressionDepth; larger requests are clamped to it, so that even
// 100,000 levels end in the alarm, naming the limit that applied.
TEST_F(ExpressionDepth, LimitIsClampedToWhatTheStackAllows) {
  EXPECT_EQ(kMaxExpressionDepth, Limits::kMaxExpressionDepth);
  const ParseLimits huge{100000};
  for (const char* opener : {"(", "-", "NOT ", "ABS(", "R["}) {
    SCOPED_TRACE(opener);
    std::string text = "R1=";
    for (int i = 0; i < 100000; ++i) text += opener;
    text += "1";
    EXPECT_EQ(alarm(text, huge), toInt(AlarmNumber::ExpressionDepth));
    EXPECT_NE(alarmText(text, huge).find("limit of 1000"), std::string::npos);
  }
}

// At the largest limit, the deepest nesting it allows parses and evaluates (the evaluator's
// own bound is never reached by what the parser accepts); one level more is the alarm.
TEST_F(ExpressionDepth, DeepestAllowedNestingEvaluates) {
  const ParseLimits max{kMaxExpressionDepth};
  const int n = kMaxExpressionDepth - 1;  // the expression itself is one level
  auto nest = [](const std::string& open, const std::string& close, int levels) {
    std::string s = "R1=";
    for (int i = 0; i < levels; ++i) s += open;
    s += "7";
    for (int i = 0; i < levels; ++i) s += close;
    return s;
  };
  EXPECT_EQ(toNumber(value(nest("(", ")", n), 0, max)), 7);
  EXPECT_EQ(toNumber(value(nest("ABS(", ")", n), 0, max)), 7);
  EXPECT_EQ(toNumber(value(nest("-", "", n), 0, max)), n % 2 ? -7 : 7);
  EXPECT_EQ(toBool(value(nest("NOT ", "", n), 0, max)), n % 2 == 0);
  EXPECT_EQ(alarm(nest("(", ")", n + 1), max), toInt(AlarmNumber::ExpressionDepth));
  EXPECT_EQ(alarm(nest("ABS(", ")", n + 1), max), toInt(AlarmNumber::ExpressionDepth));
  EXPECT_EQ(alarm(nest("-", "", n + 1), max), toInt(AlarmNumber::ExpressionDepth));
}

// The evaluator bounds its own recursion too: a block built otherwise than by the parser (here
// 5000 nested negations) ends in the alarm, not in a stack overflow.
TEST_F(ExpressionDepth, EvaluatorBoundsHandBuiltNesting) {
  Block b;
  Node leaf;
  leaf.kind = NodeKind::Number;
  leaf.number = 1;
  b.nodes.push_back(leaf);
  for (int i = 1; i <= 5000; ++i) {
    Node neg;
    neg.kind = NodeKind::Unary;
    neg.op = Op::Neg;
    neg.a = i - 1;
    b.nodes.push_back(neg);
  }
  try {
    ev.eval(b, 5000);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::ExpressionDepth));
  }
  EXPECT_EQ(toNumber(ev.eval(b, kMaxExpressionDepth - 1)), -1);  // and it recovers
}

// An embedding program that asks Channel for more than the stack allows gets the clamped
// limits: 100,000 parentheses in a 200 KB block end in alarm 99003 naming the limit 1000.
TEST(ExpressionDepthChannel, ChannelClampsTheLimits) {
  class Sink final : public PathSink {
   public:
    void segment(const Segment&) override {}
    void finish(const Alarm*) override {}
  } sink;
  RunOptions options;
  options.limits.max_expression_depth = 1 << 30;
  options.limits.max_line_length = size_t{1} << 40;
  Channel channel(options);
  const std::string program =
      "R1=" + std::string(100000, '(') + "1" + std::string(100000, ')') + "\nM30\n";
  RunResult r = channel.runText("DEEP.MPF", program, sink);
  ASSERT_EQ(r.status, RunResult::Status::Alarm);
  EXPECT_EQ(r.alarm->number, toInt(AlarmNumber::ExpressionDepth));
  EXPECT_NE(r.alarm->text.find("limit of 1000"), std::string::npos) << r.alarm->text;
  // A block longer than the largest line limit (4 MiB) is alarm 99001, whatever was asked.
  const std::string huge = "R1=1" + std::string(Limits::kMaxLineLength, ' ') + "\nM30\n";
  r = channel.runText("HUGE.MPF", huge, sink);
  ASSERT_EQ(r.status, RunResult::Status::Alarm);
  EXPECT_EQ(r.alarm->number, toInt(AlarmNumber::LineTooLong));
}

// An alarm inside a long chain leaves nothing behind: the next expression evaluates normally.
TEST_F(ExpressionDepth, AlarmInsideAChain) {
  EXPECT_EQ(alarm(longest("R1=1", "+1", "/0")), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(toNumber(value("R1=2+3*4")), 14);
}

}  // namespace
}  // namespace ncoffset::lang
