#include "interp/machine_data.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

namespace {

using C = DataClass;
constexpr double kBig = 1e12;

// The machine and setting data ncoffset knows (a table, constant-initialised: no order of
// static initialisation to care about).
constexpr DataSpec kTable[] = {
    // NC machine data
    {10280, "PROG_FUNCTION_MASK", C::NckMd, 0, true, 0, 0, true, "comparison mode of REAL"},
    {10600, "FRAME_ANGLE_INPUT_MODE", C::NckMd, 1, true, 1, 1, true,
     "1 = RPY angles (2 = Euler is not modelled)"},
    {10610, "MIRROR_REF_AX", C::NckMd, 0, true, 0, 0, true, "0 = mirror about the programmed axis"},
    {18088, "MM_NUM_TOOL_CARRIER", C::NckMd, 10, true, 0, 1000, false,
     "toolholders with orientation capability $TC_CARR (a control's default is 0)"},
    {18102, "MM_TYPE_OF_CUTTING_EDGE", C::NckMd, 0, true, 0, 1, false,
     "1 = flat D numbers (D without T)"},
    {18105, "MM_MAX_CUTTING_EDGE_NO", C::NckMd, 9, true, 1, 32000, false, "highest D number"},
    {18106, "MM_MAX_CUTTING_EDGE_PERTOOL", C::NckMd, 9, true, 1, 32000, false,
     "cutting edges per tool"},
    {18110, "MM_MAX_SUMCORR_PER_CUTTEDGE", C::NckMd, 6, true, 0, 6, false,
     "sum offsets (DL) per cutting edge"},
    {18112, "MM_KIND_OF_SUMCORR", C::NckMd, 0, true, 0, kBig, false,
     "bit 4: setup offsets $TC_ECP.. exist"},
    {18114, "MM_ENABLE_TOOL_ORIENT", C::NckMd, 2, true, 0, 3, false, "tool orientation data"},
    {18116, "MM_NUM_TOOL_ENV", C::NckMd, 0, true, 0, kBig, false, "tool environments"},
    {18601, "MM_NUM_GLOBAL_USER_FRAMES", C::NckMd, 0, true, 0, 100, false,
     "global settable frames"},
    // Channel machine data
    {20100, "DIAMETER_AX_DEF", C::ChannelMd, -1, true, -1, 2, false,
     "transverse axis, written as an axis name (turning_data.cpp)"},
    {20110, "RESET_MODE_MASK", C::ChannelMd, 0, true, 0, kBig, false, "reset behaviour"},
    {20120, "TOOL_RESET_VALUE", C::ChannelMd, 0, true, 0, kBig, false, "tool at reset"},
    {20121, "TOOL_PRESEL_RESET_VALUE", C::ChannelMd, 0, true, 0, kBig, false,
     "preselected tool at reset"},
    {20130, "CUTTING_EDGE_RESET_VALUE", C::ChannelMd, 0, true, 0, kBig, false, "edge at reset"},
    {20184, "TOCARR_BASE_FRAME_NUMBER", C::ChannelMd, -1, true, -1, -1, true,
     "table offset of a P/M toolholder in $P_PARTFR (MD28082 bit 2), not in a base frame"},
    {20202, "WAB_MAXNUM_DUMMY_BLOCKS", C::ChannelMd, 5, true, 0, 1000, false,
     "SAR: blocks without motion"},
    {20204, "WAB_CLEARANCE_TOLERANCE", C::ChannelMd, 0.01, false, 0, kBig, false,
     "SAR: reversal tolerance"},
    {20210, "CUTCOM_CORNER_LIMIT", C::ChannelMd, 100, false, 0, 150, false,
     "G451 -> circle above this angle"},
    {20220, "CUTCOM_MAX_DISC", C::ChannelMd, 50, true, 0, 75, false, "upper limit of DISC"},
    {20230, "CUTCOM_CURVE_INSERT_LIMIT", C::ChannelMd, 10, false, 0, 150, false,
     "flat outside corners"},
    {20240, "CUTCOM_MAXNUM_CHECK_BLOCKS", C::ChannelMd, 3, true, 2, 150, false,
     "TRC look-ahead blocks"},
    {20250, "CUTCOM_MAXNUM_DUMMY_BLOCKS", C::ChannelMd, 3, true, 0, 150, false,
     "TRC blocks without plane motion"},
    {20252, "CUTCOM_MAXNUM_SUPPR_BLOCKS", C::ChannelMd, 0, true, 0, 150, false,
     "TRC suppressed blocks"},
    {20270, "CUTTING_EDGE_DEFAULT", C::ChannelMd, 1, true, -1, 32000, false,
     "edge after tool change"},
    {20272, "SUMCORR_DEFAULT", C::ChannelMd, 0, true, -1, 6, false,
     "DL after an edge selection (-1: keep)"},
    {20360, "TOOL_PARAMETER_DEF_MASK", C::ChannelMd, 0, true, 0, 0, true,
     "diameter interpretation not modelled"},
    {21000, "CIRCLE_ERROR_CONST", C::ChannelMd, 0.01, false, 0, kBig, false,
     "circle end point tolerance (mm)"},
    {21010, "CIRCLE_ERROR_FACTOR", C::ChannelMd, 0.001, false, 0, kBig, false,
     "circle end point tolerance factor"},
    {21080, "CUTCOM_PARALLEL_ORI_LIMIT", C::ChannelMd, 0, false, 0, 180, false,
     "TRC parallel orientation"},
    {21186, "TOCARR_ROT_OFFSET_FROM_FR", C::ChannelMd, 0, true, 0, 0, true,
     "toolholder rotary axis offsets from $TC_CARR24/25, not from the work offset"},
    {22550, "TOOL_CHANGE_MODE", C::ChannelMd, 0, true, 0, 1, false, "0: T changes, 1: M6 changes"},
    {22560, "TOOL_CHANGE_M_CODE", C::ChannelMd, 6, true, 0, 99999, false,
     "M code of the tool change"},
    {28050, "MM_NUM_R_PARAM", C::ChannelMd, 100, true, 0, 32535, false, "number of R parameters"},
    {28080, "MM_NUM_USER_FRAMES", C::ChannelMd, 100, true, 5, 100, false, "settable frames"},
    {28085, "MM_LINK_TOA_UNIT", C::ChannelMd, 1, true, 1, 1, false, "TO unit of the channel"},
    // Setting data
    // Axis machine data: dynamics only, no effect on the path geometry.
    {30460, "BASE_FUNCTION_MASK", C::AxisMd, 0, true, 0, 4, false,
     "bit 2: axis-specific diameter programming permitted"},
    {32000, "MAX_AX_VELO", C::AxisMd, 10000, false, 0, 1e9, false,
     "maximum axis velocity (mm/min)"},
    {32020, "JOG_VELO", C::AxisMd, 2000, false, 0, 1e9, false, "JOG velocity (mm/min)"},
    {32300, "MAX_AX_ACCEL", C::AxisMd, 1, false, 0, 1e6, false, "maximum axis acceleration (m/s2)"},
    {42440, "FRAME_OFFSET_INCR_PROG", C::ChannelSd, 1, true, 0, 1, false,
     "1: offset change traversed with G91, 0: only the programmed path"},
    {42442, "TOOL_OFFSET_INCR_PROG", C::ChannelSd, 1, true, 0, 1, false,
     "1: tool offset traversed with G91, 0: only the programmed path"},
    {42480, "STOP_CUTCOM_STOPRE", C::ChannelSd, 0, true, 0, 1, false,
     "1: alarm 10778 at a preprocessor stop with TRC"},
    {42900, "MIRROR_TOOL_LENGTH", C::ChannelSd, 0, true, 0, 1, false,
     "mirror geometry+base lengths"},
    {42910, "MIRROR_TOOL_WEAR", C::ChannelSd, 0, true, 0, 1, false, "mirror wear lengths"},
    {42920, "WEAR_SIGN_CUTPOS", C::ChannelSd, 0, true, 0, 1, false,
     "wear sign by cutting edge position"},
    {42930, "WEAR_SIGN", C::ChannelSd, 0, true, 0, 1, false, "invert all wear"},
    {42935, "WEAR_TRANSFORM", C::ChannelSd, 0, true, 0, 0, true,
     "wear transformation (TOWxxx) not modelled"},
    {42940, "TOOL_LENGTH_CONST", C::ChannelSd, 0, true, -kBig, kBig, false,
     "length assignment kept on plane change"},
    {42942, "TOOL_LENGTH_CONST_T", C::ChannelSd, 0, true, 0, 0, true, "not modelled"},
    {42950, "TOOL_LENGTH_TYPE", C::ChannelSd, 0, true, -kBig, kBig, false,
     "length assignment by tool class"},
    {42960, "TOOL_TEMP_COMP", C::ChannelSd, 0, false, 0, 0, true,
     "temperature compensation not modelled"},
    {42974, "TOCARR_FINE_CORRECTION", C::ChannelSd, 0, true, 0, 1, false,
     "1: the toolholder's fine offsets $TC_CARR41..65 count"},
    {42980, "TOFRAME_MODE", C::ChannelSd, 0, true, 0, 0, true,
     "TOFRAME as TOROT (docs/toolholders.md)"},
};

}  // namespace

std::span<const DataSpec> MachineData::table() {
  return kTable;
}

MachineData::MachineData() {
  for (const auto& s : table()) {
    values_.push_back(s.default_value);
    axis_values_.push_back({s.default_value, s.default_value, s.default_value});
  }
}

const DataSpec& MachineData::spec(int id) const {
  return table()[static_cast<size_t>(id)];
}

int MachineData::find(std::string_view name) const {
  const auto& t = table();
  // Number forms SD42940 / MD20270.
  if (name.size() > 2 && (name.substr(0, 2) == "SD" || name.substr(0, 2) == "MD")) {
    bool digits = true;
    for (char c : name.substr(2)) digits = digits && c >= '0' && c <= '9';
    if (digits && name.size() <= 8) {
      int number = std::atoi(std::string(name.substr(2)).c_str());
      bool sd = name[0] == 'S';
      for (size_t i = 0; i < t.size(); ++i) {
        bool is_sd = t[i].cls == DataClass::ChannelSd || t[i].cls == DataClass::NckSd;
        if (t[i].number == number && is_sd == sd) return static_cast<int>(i);
      }
      return -1;
    }
  }
  if (name.size() < 5 || name[0] != '$' || name[3] != '_') return -1;
  std::string_view prefix = name.substr(1, 2);
  std::string_view rest = name.substr(4);
  DataClass cls;
  if (prefix == "MN")
    cls = DataClass::NckMd;
  else if (prefix == "MC")
    cls = DataClass::ChannelMd;
  else if (prefix == "MA")
    cls = DataClass::AxisMd;
  else if (prefix == "SN")
    cls = DataClass::NckSd;
  else if (prefix == "SC")
    cls = DataClass::ChannelSd;
  else
    return -1;
  for (size_t i = 0; i < t.size(); ++i)
    if (t[i].cls == cls && rest == t[i].name) return static_cast<int>(i);
  return -1;
}

double MachineData::get(std::string_view name) const {
  int id = find(name);
  if (id < 0) raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", name));
  return get(id);
}

double MachineData::checked(int id, double value) const {
  const DataSpec& s = spec(id);
  if (!std::isfinite(value))
    raise(AlarmNumber::ValueRange, fmt::format("value range exceeded for {}", s.name));
  if (s.integer) value = std::round(value);
  if (s.only_default ? value != s.default_value : (value < s.lo || value > s.hi)) {
    raise(
        s.only_default ? AlarmNumber::UnitsOrData : AlarmNumber::ValueRange,
        s.only_default
            ? fmt::format("{} {} = {} is not modelled by ncoffset (only {}: {})",
                          s.cls == DataClass::ChannelSd || s.cls == DataClass::NckSd ? "SD" : "MD",
                          s.number, value, s.default_value, s.meaning)
            : fmt::format("value range exceeded: {} {} = {} (allowed {} .. {})",
                          s.cls == DataClass::ChannelSd || s.cls == DataClass::NckSd ? "SD" : "MD",
                          s.number, value, s.lo, s.hi));
  }
  return value;
}

void MachineData::set(int id, double value) {
  values_[static_cast<size_t>(id)] = checked(id, value);
}

void MachineData::set(int id, int axis, double value) {
  axis_values_[static_cast<size_t>(id)][static_cast<size_t>(axis)] = checked(id, value);
}

}  // namespace ncoffset::interp
