// Expression evaluation (src/lang/evaluator.hpp): priorities (PM-NC p444), functions in
// degrees, domain alarms 14051, REAL comparison tolerance, result types.
#include "lang/evaluator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

// A tiny environment: a few named variables, R<n> = 10*n, no extra functions.
class FakeEnv final : public Environment {
 public:
  std::map<std::string, Value, std::less<>> vars{
      {"IA", Value::integer(1)},
      {"IB", Value::integer(2)},
      {"RX", Value::real(0.5)},
      {"STR", Value::string("AB")},
  };
  bool read(std::string_view name, std::span<const Value> indices, bool indexed,
            Value& out) override {
    if (indexed) {
      if (name != "ARR" || indices.size() != 1) return false;
      out = Value::integer(100 + indices[0].num);
      return true;
    }
    auto it = vars.find(name);
    if (it == vars.end()) return false;
    out = it->second;
    return true;
  }
  Value readR(double number) override { return Value::real(10 * number); }
  Value call(std::string_view name, std::span<const Value>) override {
    raise(AlarmNumber::NameNotDefined, "unknown function " + std::string(name));
  }
  Value chain(const Value& a, const Value&) override { return a; }
};

class EvaluatorTest : public ::testing::Test {
 protected:
  FakeEnv env;
  Evaluator ev{env};
  Block block;

  Value eval(const std::string& expr) {
    parseBlock("R1=" + expr, 1, block);
    return ev.eval(block, block.stmts.at(0).expr);
  }
  double num(const std::string& expr) { return toNumber(eval(expr)); }
  bool truth(const std::string& expr) {
    Value v = eval(expr);
    EXPECT_EQ(v.type, Type::Bool) << expr;
    return v.num != 0;
  }
  int alarm(const std::string& expr) {
    try {
      eval(expr);
    } catch (const AlarmError& e) {
      return e.number();
    }
    return 0;
  }
};

constexpr double kEps = 1e-12;

// ---- priorities ------------------------------------------------------------------------------

TEST_F(EvaluatorTest, ArithmeticPriorities) {
  EXPECT_EQ(num("2+3*4"), 14);
  EXPECT_EQ(num("(2+3)*4"), 20);
  EXPECT_EQ(num("10-4-3"), 3);  // left associative
  EXPECT_EQ(num("48/4/2"), 6);
  EXPECT_EQ(num("-2*3"), -6);
  EXPECT_EQ(num("2*-3"), -6);
  EXPECT_EQ(num("2+3 DIV 2"), 3);
  EXPECT_EQ(num("2+7 MOD 4"), 5);
  EXPECT_EQ(num("--3"), 3);
  EXPECT_EQ(num("+3"), 3);
}

TEST_F(EvaluatorTest, ComparisonsBindWeakest) {
  EXPECT_TRUE(truth("1+2==3"));
  EXPECT_TRUE(truth("2*3>5"));
  EXPECT_TRUE(truth("(1==1) AND (2==2)"));
  // Without parentheses: (1 == (1 AND 2)) == 2 -> TRUE == 2 -> FALSE.
  EXPECT_FALSE(truth("1==1 AND 2==2"));
  EXPECT_TRUE(truth("\"A\" << \"B\" == \"AB\""));
}

TEST_F(EvaluatorTest, NotBindsTighterThanArithmetic) {
  // (NOT 0) + 1 = TRUE + 1 = 2, not NOT(0+1).
  EXPECT_EQ(num("NOT 0 + 1"), 2);
  EXPECT_TRUE(truth("NOT (1==0)"));
  EXPECT_FALSE(truth("NOT TRUE"));
  EXPECT_EQ(eval("B_NOT 0").num, -1);
  EXPECT_EQ(eval("B_NOT 5").num, -6);
  EXPECT_EQ(eval("B_NOT 0").type, Type::Int);
}

TEST_F(EvaluatorTest, BitOperatorsAndTheirOrder) {
  EXPECT_EQ(num("5 B_AND 3"), 1);
  EXPECT_EQ(num("5 B_OR 3"), 7);
  EXPECT_EQ(num("5 B_XOR 3"), 6);
  EXPECT_EQ(num("'B1100' B_AND 'H0A'"), 8);
  // + before B_AND before B_XOR before B_OR.
  EXPECT_EQ(num("6 B_AND 3 + 1"), 4);
  EXPECT_EQ(num("4 B_OR 1 B_AND 2"), 4);
  EXPECT_EQ(num("3 B_XOR 1 B_OR 2"), 2);
  EXPECT_EQ(num("1 B_OR 6 B_XOR 2 B_AND 3"), 5);  // 1 | (6 ^ (2 & 3))
  // B_OR before AND.
  EXPECT_FALSE(truth("1 B_OR 2 AND 0"));
}

TEST_F(EvaluatorTest, LogicOperatorsAndTheirOrder) {
  EXPECT_TRUE(truth("TRUE AND TRUE"));
  EXPECT_FALSE(truth("TRUE AND FALSE"));
  EXPECT_TRUE(truth("TRUE XOR FALSE"));
  EXPECT_FALSE(truth("TRUE XOR TRUE"));
  EXPECT_TRUE(truth("FALSE OR TRUE"));
  // AND before XOR before OR.
  EXPECT_TRUE(truth("TRUE OR FALSE AND FALSE"));
  EXPECT_TRUE(truth("TRUE XOR TRUE OR TRUE"));
  EXPECT_TRUE(truth("TRUE OR TRUE XOR TRUE"));
  EXPECT_FALSE(truth("TRUE XOR TRUE AND TRUE"));
  // Numbers are TRUE when not zero.
  EXPECT_TRUE(truth("2 AND 3"));
  EXPECT_FALSE(truth("0 OR 0.0"));
}

TEST_F(EvaluatorTest, ConcatBetweenLogicAndComparison) {
  EXPECT_EQ(eval("1+1 << 2").str, "22");
  EXPECT_EQ(eval("\"X=\" << 1.5").str, "X=1.5");
  EXPECT_EQ(eval("\"N\" << 10").str, "N10");
  EXPECT_EQ(eval("TRUE << \"\"").str, "TRUE");
  EXPECT_EQ(eval("STR << STR").str, "ABAB");
  EXPECT_EQ(eval("\"A\" << \"B\"").type, Type::String);
}

// ---- DIV / MOD -------------------------------------------------------------------------------

TEST_F(EvaluatorTest, DivTruncatesTowardZero) {
  EXPECT_EQ(num("7 DIV 2"), 3);
  EXPECT_EQ(num("-7 DIV 2"), -3);
  EXPECT_EQ(num("7 DIV -2"), -3);
  EXPECT_EQ(num("-7 DIV -2"), 3);
  EXPECT_EQ(eval("7 DIV 2").type, Type::Int);
  EXPECT_EQ(eval("7.5 DIV 2").type, Type::Int);
  EXPECT_EQ(num("7.5 DIV 2"), 3);
}

TEST_F(EvaluatorTest, ModKeepsSignOfDividend) {
  EXPECT_EQ(num("7 MOD 3"), 1);
  EXPECT_EQ(num("-7 MOD 3"), -1);
  EXPECT_EQ(num("7 MOD -3"), 1);
  EXPECT_EQ(num("-7 MOD -3"), -1);
  EXPECT_EQ(eval("7 MOD 3").type, Type::Int);
  EXPECT_DOUBLE_EQ(num("7.5 MOD 2"), 1.5);
  EXPECT_EQ(eval("7.5 MOD 2").type, Type::Real);
}

TEST_F(EvaluatorTest, DivisionByZero) {
  EXPECT_EQ(alarm("1/0"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("1/0.0"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("1 DIV 0"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("1 MOD 0"), toInt(AlarmNumber::Arithmetic));
}

// ---- result types ----------------------------------------------------------------------------

TEST_F(EvaluatorTest, IntAndRealResultTypes) {
  EXPECT_EQ(eval("10").type, Type::Int);
  EXPECT_EQ(eval("10.0").type, Type::Real);
  EXPECT_EQ(eval("1+2").type, Type::Int);
  EXPECT_EQ(eval("1+2.0").type, Type::Real);
  EXPECT_EQ(eval("2*3").type, Type::Int);
  EXPECT_EQ(eval("IA-IB").type, Type::Int);
  EXPECT_EQ(eval("IA+RX").type, Type::Real);
  EXPECT_EQ(eval("-IA").type, Type::Int);
  EXPECT_EQ(eval("-RX").type, Type::Real);
  // '/' always gives REAL.
  EXPECT_EQ(eval("4/2").type, Type::Real);
  EXPECT_EQ(num("1/2"), 0.5);
  EXPECT_EQ(eval("1.5EX3").type, Type::Real);
  EXPECT_EQ(eval("'H1F'").type, Type::Int);
  EXPECT_EQ(eval("TRUE").type, Type::Bool);
  EXPECT_EQ(eval("1<2").type, Type::Bool);
  // Beyond the INT range the result is REAL.
  Value big = eval("2147483647+1");
  EXPECT_EQ(big.type, Type::Real);
  EXPECT_EQ(big.num, 2147483648.0);
}

TEST_F(EvaluatorTest, VariablesAndRParameters) {
  EXPECT_EQ(num("IA+IB"), 3);
  EXPECT_EQ(num("R5"), 50);
  EXPECT_EQ(num("R[2+1]"), 30);
  EXPECT_EQ(num("ARR[3]"), 103);
  EXPECT_EQ(alarm("NOSUCH+1"), toInt(AlarmNumber::NameNotDefined));
  EXPECT_EQ(alarm("NOSUCH[1]"), toInt(AlarmNumber::NameNotDefined));
}

TEST_F(EvaluatorTest, TypeMismatch) {
  EXPECT_EQ(alarm("STR+1"), toInt(AlarmNumber::TypeMismatch));
  EXPECT_EQ(alarm("STR==1"), toInt(AlarmNumber::TypeMismatch));
  EXPECT_EQ(alarm("SIN(STR)"), toInt(AlarmNumber::TypeMismatch));
  EXPECT_TRUE(truth("STR==\"AB\""));
  EXPECT_TRUE(truth("STR<>\"ab\""));
}

TEST_F(EvaluatorTest, AcIcOnlyAsWholeAddressValue) {
  EXPECT_EQ(alarm("AC(1)+1"), toInt(AlarmNumber::SyntaxError));
}

// ---- comparisons -----------------------------------------------------------------------------

TEST_F(EvaluatorTest, Comparisons) {
  EXPECT_TRUE(truth("1<2"));
  EXPECT_FALSE(truth("2<2"));
  EXPECT_TRUE(truth("2<=2"));
  EXPECT_TRUE(truth("3>2"));
  EXPECT_FALSE(truth("3>=4"));
  EXPECT_TRUE(truth("1<>2"));
  EXPECT_TRUE(truth("1><2"));
  EXPECT_FALSE(truth("2<>2"));
  EXPECT_TRUE(truth("2==2.0"));
}

TEST_F(EvaluatorTest, RealEqualityTolerance) {
  EXPECT_TRUE(truth("0.1+0.2==0.3"));
  EXPECT_FALSE(truth("0.1+0.2>0.3"));
  EXPECT_TRUE(truth("0.1+0.2>=0.3"));
  EXPECT_FALSE(truth("0.3<0.1+0.2"));
  EXPECT_FALSE(truth("0.1+0.2<>0.3"));
  EXPECT_TRUE(truth("1.0==1.0000000000001"));  // relative difference 1e-13
  EXPECT_FALSE(truth("1.0==1.00000000001"));   // relative difference 1e-11
  EXPECT_TRUE(truth("1.0<1.00000000001"));

  EXPECT_TRUE(realEqual(1e6, 1e6 * (1 + 5e-13)));
  EXPECT_FALSE(realEqual(1e6, 1e6 * (1 + 5e-12)));
  EXPECT_TRUE(realEqual(0, 0));
  EXPECT_FALSE(realEqual(0, 1e-300));
  EXPECT_TRUE(realEqual(-2.5, -2.5));
}

TEST(EvaluatorHelpers, RoundToIntHalfAwayFromZero) {
  EXPECT_EQ(roundToInt(2.5), 3);
  EXPECT_EQ(roundToInt(-2.5), -3);
  EXPECT_EQ(roundToInt(2.4999), 2);
  EXPECT_EQ(roundToInt(-0.4), 0);
}

TEST(EvaluatorHelpers, Conversions) {
  EXPECT_EQ(toText(Value::integer(-12)), "-12");
  EXPECT_EQ(toText(Value::real(0.1)), "0.1");
  EXPECT_EQ(toText(Value::boolean(false)), "FALSE");
  EXPECT_EQ(toText(Value::string("x")), "x");
  EXPECT_TRUE(toBool(Value::real(0.5)));
  EXPECT_FALSE(toBool(Value::integer(0)));
  try {
    toNumber(Value::string("x"));
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::TypeMismatch));
  }
  try {
    toNumber(Value::symbol("FOO"));
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::NameNotDefined));
  }
}

// ---- functions -------------------------------------------------------------------------------

TEST_F(EvaluatorTest, TrigonometryInDegrees) {
  EXPECT_NEAR(num("SIN(30)"), 0.5, kEps);
  EXPECT_NEAR(num("SIN(-90)"), -1, kEps);
  EXPECT_NEAR(num("COS(60)"), 0.5, kEps);
  EXPECT_NEAR(num("COS(180)"), -1, kEps);
  EXPECT_NEAR(num("TAN(45)"), 1, kEps);
  EXPECT_NEAR(num("TAN(-45)"), -1, kEps);
  EXPECT_NEAR(num("ASIN(0.5)"), 30, 1e-10);
  EXPECT_NEAR(num("ACOS(0.5)"), 60, 1e-10);
  EXPECT_NEAR(num("ACOS(-1)"), 180, 1e-10);
  EXPECT_NEAR(num("ATAN2(1,1)"), 45, 1e-10);
  EXPECT_NEAR(num("ATAN2(1,-1)"), 135, 1e-10);
  EXPECT_NEAR(num("ATAN2(-1,0)"), -90, 1e-10);
  EXPECT_NEAR(num("ATAN2(0,-1)"), 180, 1e-10);
  EXPECT_EQ(eval("SIN(30)").type, Type::Real);
  EXPECT_EQ(eval("SIN(0)").type, Type::Real);
}

TEST_F(EvaluatorTest, TrigonometryDomainAlarms) {
  EXPECT_EQ(alarm("TAN(90)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("TAN(-270)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("TAN(450)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("ASIN(1.5)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("ACOS(-1.0001)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("ATAN2(0,0)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("TAN(180)"), 0);
}

TEST_F(EvaluatorTest, RootPowerAbs) {
  EXPECT_EQ(num("SQRT(16)"), 4);
  EXPECT_EQ(num("SQRT(0)"), 0);
  EXPECT_EQ(alarm("SQRT(-1)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(num("POT(3)"), 9);
  EXPECT_EQ(num("POT(-1.5)"), 2.25);
  EXPECT_EQ(num("ABS(-3)"), 3);
  EXPECT_EQ(eval("ABS(-3)").type, Type::Int);
  EXPECT_EQ(num("ABS(-2.5)"), 2.5);
  EXPECT_EQ(eval("ABS(-2.5)").type, Type::Real);
}

TEST_F(EvaluatorTest, Rounding) {
  EXPECT_EQ(num("TRUNC(2.7)"), 2);
  EXPECT_EQ(num("TRUNC(-2.7)"), -2);
  EXPECT_EQ(num("ROUND(2.5)"), 3);
  EXPECT_EQ(num("ROUND(-2.5)"), -3);
  EXPECT_EQ(num("ROUND(2.49)"), 2);
  EXPECT_EQ(num("ROUNDUP(2.1)"), 3);
  EXPECT_EQ(num("ROUNDUP(2.0)"), 2);
  EXPECT_EQ(num("ROUNDUP(-2.1)"), -2);
}

TEST_F(EvaluatorTest, ExpAndLn) {
  EXPECT_EQ(num("EXP(0)"), 1);
  EXPECT_NEAR(num("LN(EXP(2))"), 2, kEps);
  EXPECT_NEAR(num("EXP(1)"), std::exp(1.0), kEps);
  EXPECT_EQ(alarm("LN(0)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("LN(-1)"), toInt(AlarmNumber::Arithmetic));
  EXPECT_EQ(alarm("EXP(1000)"), toInt(AlarmNumber::Arithmetic));  // no finite result
}

TEST_F(EvaluatorTest, MinMaxStrlen) {
  EXPECT_EQ(num("MINVAL(3,2)"), 2);
  EXPECT_EQ(eval("MINVAL(3,2)").type, Type::Int);
  EXPECT_EQ(num("MAXVAL(1.5,2)"), 2);
  EXPECT_EQ(eval("MAXVAL(1.5,2)").type, Type::Real);
  EXPECT_EQ(num("MINVAL(-1,-1.5)"), -1.5);
  EXPECT_EQ(num("STRLEN(\"ABC\")"), 3);
  EXPECT_EQ(num("STRLEN(\"\")"), 0);
  EXPECT_EQ(num("STRLEN(STR)"), 2);
  EXPECT_EQ(eval("STRLEN(STR)").type, Type::Int);
}

TEST_F(EvaluatorTest, WrongArgumentCountAndUnknownFunction) {
  EXPECT_EQ(alarm("SIN(1,2)"), toInt(AlarmNumber::WrongCallParams));
  EXPECT_EQ(alarm("SQRT()"), toInt(AlarmNumber::WrongCallParams));
  EXPECT_EQ(alarm("ATAN2(1)"), toInt(AlarmNumber::WrongCallParams));
  EXPECT_EQ(alarm("MINVAL(1)"), toInt(AlarmNumber::WrongCallParams));
  EXPECT_EQ(alarm("NOFUNC(1)"), toInt(AlarmNumber::NameNotDefined));
}

TEST_F(EvaluatorTest, EvalOrSymbolKeepsUnknownNames) {
  parseBlock("R1=XYZ", 1, block);
  Value v = ev.evalOrSymbol(block, block.stmts[0].expr);
  EXPECT_EQ(v.type, Type::Symbol);
  EXPECT_EQ(v.str, "XYZ");
  parseBlock("R1=IA", 1, block);
  EXPECT_EQ(ev.evalOrSymbol(block, block.stmts[0].expr).type, Type::Int);
}

}  // namespace
}  // namespace ncoffset::lang
