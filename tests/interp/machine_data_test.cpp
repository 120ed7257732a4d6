// Machine and setting data (src/interp/machine_data.hpp): lookup by name and number, the
// defaults of spec §10, range checks (12160) and values that are not modelled (99013).
#include "interp/machine_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {
namespace {

int setAlarm(MachineData& md, std::string_view name, double value) {
  int id = md.find(name);
  EXPECT_GE(id, 0) << name;
  if (id < 0) return -1;
  try {
    md.set(id, value);
  } catch (const AlarmError& e) {
    return e.number();
  }
  return 0;
}

TEST(MachineData, FindByNameAndNumber) {
  MachineData md;
  int sd = md.find("$SC_TOOL_LENGTH_CONST");
  ASSERT_GE(sd, 0);
  EXPECT_EQ(md.find("SD42940"), sd);
  EXPECT_EQ(md.spec(sd).number, 42940);
  EXPECT_STREQ(md.spec(sd).name, "TOOL_LENGTH_CONST");
  EXPECT_EQ(md.spec(sd).cls, DataClass::ChannelSd);

  int mc = md.find("$MC_CUTTING_EDGE_DEFAULT");
  ASSERT_GE(mc, 0);
  EXPECT_EQ(md.find("MD20270"), mc);
  EXPECT_EQ(md.spec(mc).cls, DataClass::ChannelMd);

  int mn = md.find("$MN_FRAME_ANGLE_INPUT_MODE");
  ASSERT_GE(mn, 0);
  EXPECT_EQ(md.find("MD10600"), mn);
}

TEST(MachineData, UnknownOrWrongClass) {
  MachineData md;
  EXPECT_EQ(md.find("SD20270"), -1);                // a machine datum, not a setting datum
  EXPECT_EQ(md.find("MD42940"), -1);                // a setting datum, not a machine datum
  EXPECT_EQ(md.find("$MC_TOOL_LENGTH_CONST"), -1);  // SD under an MD prefix
  EXPECT_EQ(md.find("$SN_TOOL_LENGTH_CONST"), -1);  // NCK instead of channel
  EXPECT_EQ(md.find("$SC_NO_SUCH_DATUM"), -1);
  EXPECT_EQ(md.find("SD99999"), -1);
  EXPECT_EQ(md.find("SD"), -1);
  EXPECT_EQ(md.find("SD42940X"), -1);
  EXPECT_EQ(md.find("$XX_TOOL_LENGTH_CONST"), -1);
  EXPECT_EQ(md.find(""), -1);
  EXPECT_EQ(md.find("$SC_"), -1);
  try {
    md.get("$SC_NO_SUCH_DATUM");
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::NameNotDefined));
  }
}

TEST(MachineData, DefaultsOfSpecSection10) {
  MachineData md;
  struct Expect {
    const char* name;
    double value;
  };
  const Expect defaults[] = {
      {"MD10600", 1},      // RPY angles
      {"MD10610", 0},      // mirror about the programmed axis
      {"MD20240", 3},      // CUTCOM_MAXNUM_CHECK_BLOCKS
      {"MD20250", 3},      // CUTCOM_MAXNUM_DUMMY_BLOCKS (details Q5: default 3)
      {"MD20210", 100},    // CUTCOM_CORNER_LIMIT
      {"MD20270", 1},      // CUTTING_EDGE_DEFAULT
      {"MD21000", 0.01},   // CIRCLE_ERROR_CONST
      {"MD21010", 0.001},  // CIRCLE_ERROR_FACTOR
      {"MD22550", 0},      // tool change with T
      {"MD22560", 6},      // TOOL_CHANGE_M_CODE
      {"MD28050", 100},    // R0..R99
      {"SD42440", 1},      // FRAME_OFFSET_INCR_PROG
      {"SD42442", 1},      // TOOL_OFFSET_INCR_PROG
      {"MD18110", 6},      // MM_MAX_SUMCORR_PER_CUTTEDGE (ncoffset's default)
      {"MD20272", 0},      // SUMCORR_DEFAULT: no DL with a D selection
      {"SD42900", 0},     {"SD42910", 0}, {"SD42920", 0},
      {"SD42930", 0},     {"SD42940", 0}, {"SD42950", 0},
  };
  for (const Expect& e : defaults) {
    ASSERT_GE(md.find(e.name), 0) << e.name;
    EXPECT_EQ(md.get(e.name), e.value) << e.name;
  }
  EXPECT_EQ(md.get("$MC_CUTCOM_MAXNUM_CHECK_BLOCKS"), 3);
  EXPECT_EQ(md.get("$MC_TOOL_CHANGE_M_CODE"), 6);
}

TEST(MachineData, TableIsConsistent) {
  const auto& t = MachineData::table();
  ASSERT_FALSE(t.empty());
  for (const DataSpec& s : t) {
    if (s.only_default) continue;
    EXPECT_LE(s.lo, s.default_value) << s.number;
    EXPECT_GE(s.hi, s.default_value) << s.number;
  }
  // Every datum is found by its own number form.
  MachineData md;
  for (size_t i = 0; i < t.size(); ++i) {
    bool sd = t[i].cls == DataClass::ChannelSd || t[i].cls == DataClass::NckSd;
    std::string name = (sd ? "SD" : "MD") + std::to_string(t[i].number);
    EXPECT_EQ(md.find(name), static_cast<int>(i)) << name;
  }
}

TEST(MachineData, SetWithinRange) {
  MachineData md;
  EXPECT_EQ(setAlarm(md, "SD42940", 17), 0);
  EXPECT_EQ(md.get("$SC_TOOL_LENGTH_CONST"), 17);
  EXPECT_EQ(setAlarm(md, "SD42940", -217), 0);
  EXPECT_EQ(md.get("SD42940"), -217);
  // INT data are rounded.
  EXPECT_EQ(setAlarm(md, "SD42940", 16.6), 0);
  EXPECT_EQ(md.get("SD42940"), 17);
  // REAL data keep their value.
  EXPECT_EQ(setAlarm(md, "MD21000", 0.05), 0);
  EXPECT_EQ(md.get("$MC_CIRCLE_ERROR_CONST"), 0.05);
  EXPECT_EQ(setAlarm(md, "MD20240", 2), 0);
  EXPECT_EQ(setAlarm(md, "MD20240", 150), 0);
}

TEST(MachineData, SetOutOfRange12160) {
  MachineData md;
  EXPECT_EQ(setAlarm(md, "MD20240", 1), toInt(AlarmNumber::ValueRange));
  EXPECT_EQ(setAlarm(md, "MD20240", 151), toInt(AlarmNumber::ValueRange));
  EXPECT_EQ(md.get("MD20240"), 3);  // unchanged
  EXPECT_EQ(setAlarm(md, "SD42900", 2), toInt(AlarmNumber::ValueRange));
  EXPECT_EQ(setAlarm(md, "MD21000", -0.1), toInt(AlarmNumber::ValueRange));
  EXPECT_EQ(setAlarm(md, "SD42940", std::numeric_limits<double>::quiet_NaN()),
            toInt(AlarmNumber::ValueRange));
  EXPECT_EQ(setAlarm(md, "SD42940", std::numeric_limits<double>::infinity()),
            toInt(AlarmNumber::ValueRange));
}

TEST(MachineData, ValuesNotModelled99013) {
  MachineData md;
  EXPECT_EQ(setAlarm(md, "MD10600", 2), toInt(AlarmNumber::UnitsOrData));  // Euler angles
  EXPECT_EQ(setAlarm(md, "SD42935", 1), toInt(AlarmNumber::UnitsOrData));  // WEAR_TRANSFORM
  EXPECT_EQ(setAlarm(md, "SD42942", 1), toInt(AlarmNumber::UnitsOrData));
  EXPECT_EQ(setAlarm(md, "MD18102", 2), toInt(AlarmNumber::ValueRange));  // 0 or 1 (flat D)
  // Writing the modelled default is accepted.
  EXPECT_EQ(setAlarm(md, "SD42935", 0), 0);
  EXPECT_EQ(setAlarm(md, "MD10600", 1), 0);
  try {
    md.set(md.find("SD42935"), 3);
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_NE(e.text().find("42935"), std::string::npos) << e.text();
  }
}

}  // namespace
}  // namespace ncoffset::interp
