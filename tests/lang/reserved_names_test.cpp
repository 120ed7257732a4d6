// The names a DEF may not define and the form of a variable name (src/lang/reserved_names.hpp),
// and the DEF checks that use them (issue 14, item 5).
#include "lang/reserved_names.hpp"

#include <gtest/gtest.h>

#include <string>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

int defAlarm(const std::string& text) {
  Block b;
  try {
    parseBlock(text, 1, b);
  } catch (const AlarmError& e) {
    return e.number();
  }
  return 0;
}

TEST(ReservedNames, AddressesKeywordsAndPredefinedNames) {
  for (const char*
           name : {"X",       "F",       "R",      "X1",       "R5",    "G17",    "I1",
                   "MD20270", "SD42940", "CR",     "AR",       "DISC",  "TURN",   "IF",
                   "DEF",     "GOTOF",   "CASE",   "PROC",     "NOT",   "B_AND",  "DIV",
                   "TRUE",    "INT",     "STRING", "SIN",      "ATAN2", "CTRANS", "AC",
                   "IC",      "MSG",     "SET",    "REP",      "TO",    "OF",     "DEFAULT",
                   "NORM",    "CDON",    "SUPA",   "RET",      "TRANS", "AROT",   "STOPRE",
                   "BRISK",   "TRAORI",  "MCALL",  "LENTOAX",  "ADIS",  "SOFTA",  "TOFFL",
                   "DL",      "CYCLE81", "SETAL",  "WORKPIECE"})  // the last: names.md's table
    EXPECT_TRUE(isPredefinedName(name)) << name;
  for (const char* name : {"LEN", "CNT2", "XPOS", "R_MAX", "MDX", "SDA1", "_COORD", "ABC", "DEFX",
                           "IFX", "CR1A", "X1A"})
    EXPECT_FALSE(isPredefinedName(name)) << name;
}

TEST(ReservedNames, VariableNameForm) {
  EXPECT_EQ(variableNameProblem("LEN"), nullptr);
  EXPECT_EQ(variableNameProblem("_A"), nullptr);
  EXPECT_EQ(variableNameProblem("__"), nullptr);
  EXPECT_EQ(variableNameProblem("A_"), nullptr);
  EXPECT_EQ(variableNameProblem(std::string(31, 'A')), nullptr);
  EXPECT_STREQ(variableNameProblem(std::string(32, 'A')),
               "variable names have at most 31 characters");
  for (const char* name : {"_1", "A1B", "$AB", "A$", "Q"})
    EXPECT_NE(variableNameProblem(name), nullptr) << name;
}

TEST(ReservedNames, DefChecksTheName) {
  EXPECT_EQ(defAlarm("DEF REAL CR"), toInt(AlarmNumber::AlreadyDefined));
  EXPECT_EQ(defAlarm("DEF INT IF"), toInt(AlarmNumber::AlreadyDefined));
  EXPECT_EQ(defAlarm("DEF REAL X1"), toInt(AlarmNumber::AlreadyDefined));
  EXPECT_EQ(defAlarm("DEF REAL LEN, SIN"),
            toInt(AlarmNumber::AlreadyDefined));  // every name of a list
  EXPECT_EQ(defAlarm("DEF CHAN FRAME TRANS"), toInt(AlarmNumber::AlreadyDefined));
  EXPECT_EQ(defAlarm("DEF REAL _1"), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(defAlarm("DEF REAL " + std::string(32, 'A')), toInt(AlarmNumber::SyntaxError));
  EXPECT_EQ(defAlarm("DEF REAL " + std::string(31, 'A')), 0);
  EXPECT_EQ(defAlarm("DEF REAL LEN=1, _POS[3], CNT_2"), 0);
  // One-letter names (docs/language.md "Variable names"): refused where the letter is an
  // address of the block, I/J/K only as scalars; the others accepted.
  for (char c : std::string("DFGHLMNPRSTXYZIJK"))
    EXPECT_EQ(defAlarm(std::string("DEF REAL ") + c), toInt(AlarmNumber::AlreadyDefined)) << c;
  for (char c : std::string("ABCEOQUVW")) EXPECT_EQ(defAlarm(std::string("DEF REAL ") + c), 0) << c;
  EXPECT_EQ(defAlarm("DEF INT K[2], I[3]"), 0);
  EXPECT_EQ(defAlarm("DEF INT M[2]"), toInt(AlarmNumber::AlreadyDefined));
}

}  // namespace
}  // namespace ncoffset::lang
