// The variable store alone (src/interp/variable_store.hpp): R parameters per MD28050, scopes
// per program level, DEF checks and the limits of docs/limits.md.
#include "interp/variable_store.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ncoffset/alarm.hpp"
#include "support/alarm_of.hpp"

namespace ncoffset::interp {
namespace {

using test::alarmOf;

lang::Decl real(std::string_view name, int rows = 0, int cols = 0) {
  lang::Decl d;
  d.name = name;
  d.dims[0] = rows;
  d.dims[1] = cols;
  return d;
}

TEST(VariableStore, RParametersAreRangeChecked) {
  VariableStore s(Limits{}, 100);  // MD28050 default: R0..R99
  s.setR(99, 2.5);
  EXPECT_EQ(s.r(99), 2.5);
  EXPECT_TRUE(s.rWritten(99));
  EXPECT_FALSE(s.rWritten(0));
  EXPECT_EQ(alarmOf([&] { s.r(100); }), toInt(AlarmNumber::ArrayIndex1));
  EXPECT_EQ(alarmOf([&] { s.r(1.5); }), toInt(AlarmNumber::ArrayIndex1));
  EXPECT_EQ(alarmOf([&] { s.r(-1); }), toInt(AlarmNumber::ArrayIndex1));
  s.resizeR(200);
  EXPECT_EQ(s.r(99), 2.5);  // kept
  EXPECT_EQ(s.r(199), 0);
}

TEST(VariableStore, ScopesFollowTheProgramLevels) {
  VariableStore s(Limits{}, 10);
  s.beginRun();
  s.add("MAIN_V", s.prepare(real("MAIN_V")));
  s.pushScope();                         // a subprogram
  EXPECT_EQ(s.find("MAIN_V"), nullptr);  // locals of the main program are not visible
  s.add("SUB_V", s.prepare(real("SUB_V")));
  EXPECT_NE(s.find("SUB_V"), nullptr);
  s.clearScope();  // the next pass of the subprogram starts without variables
  EXPECT_EQ(s.find("SUB_V"), nullptr);
  s.popScope();
  EXPECT_NE(s.find("MAIN_V"), nullptr);
  s.endRun(true);  // the main program's variables stay for --vars
  EXPECT_EQ(s.mainVariables().count("MAIN_V"), 1u);
}

TEST(VariableStore, DefChecksNamesAndLimits) {
  Limits limits;
  limits.max_variables = 3;
  limits.max_array_elements = 10;
  limits.max_total_elements = 15;
  VariableStore s(limits, 10);
  s.beginRun();
  s.add("A1", s.prepare(real("A1", 10)));
  EXPECT_EQ(alarmOf([&] { s.prepare(real("A1")); }), toInt(AlarmNumber::AlreadyDefined));
  EXPECT_EQ(alarmOf([&] { s.prepare(real("R12")); }), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(alarmOf([&] { s.prepare(real("B", 11)); }), toInt(AlarmNumber::ArrayTooLarge));
  EXPECT_EQ(alarmOf([&] { s.prepare(real("B", 6)); }),
            toInt(AlarmNumber::ArrayTooLarge));  // 16 > 15
  s.add("B", s.prepare(real("B", 5)));
  s.pushScope();
  s.add("C", s.prepare(real("C")));
  EXPECT_EQ(alarmOf([&] { s.prepare(real("D")); }), toInt(AlarmNumber::TooManyVariables));
  s.popScope();  // the subprogram's variable is released
  EXPECT_EQ(s.prepare(real("D")).data.size(), 1u);
}

TEST(VariableStore, ElementIndexIsRowMajor) {
  VariableStore s(Limits{}, 10);
  s.beginRun();
  s.add("M", s.prepare(real("M", 2, 3)));
  const UserVariable& m = *s.find("M");
  std::vector<lang::Value> idx{lang::Value::integer(1), lang::Value::integer(2)};
  EXPECT_EQ(VariableStore::elementIndex(m, idx, "M"), 5u);
  idx[1] = lang::Value::integer(3);
  EXPECT_EQ(alarmOf([&] { VariableStore::elementIndex(m, idx, "M"); }),
            toInt(AlarmNumber::ArrayIndex2));
}

}  // namespace
}  // namespace ncoffset::interp
