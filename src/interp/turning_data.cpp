// The machine data of turning (docs/turning.md): MD20100 $MC_DIAMETER_AX_DEF (the transverse
// axis, an axis name) and MD20150 $MC_GCODE_RESET_VALUES[group - 1] for the G groups the path
// depends on (6 plane, 14 G90/G91, 15 feed type, 29 diameter programming); and the system
// variable $AA_IW (FM P1, PM-NC "List of G functions").
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

namespace {

// The number of G codes of the modelled groups of MD20150 (index = group - 1); 0: the group is
// not modelled.
int groupSize(int index) {
  switch (index) {
    case 5:  // group 6: G17, G18, G19
      return 3;
    case 13:  // group 14: G90, G91
      return 2;
    case 14:  // group 15: G93, G94, G95, G96, G97
      return 5;
    case 28:  // group 29: DIAMOF, DIAMON, DIAM90, DIAMCYCOF
      return 4;
    default:
      return 0;
  }
}

// "X", X (an axis name) or "" (no transverse axis) as the index 0..2 or -1.
int transverseFrom(const Value& v) {
  if (v.type == Type::Symbol || v.type == Type::Axis || v.type == Type::String) {
    if (v.str.empty()) return -1;
    for (int i = 0; i < 3; ++i)
      if (v.str.size() == 1 && v.str[0] == "XYZ"[i]) return i;
    raise(AlarmNumber::NotModelled,
          fmt::format("transverse axis {} is not modelled by ncoffset (geometry axes X, Y, Z only)",
                      v.str));
  }
  raise(AlarmNumber::TypeMismatch, "MD20100 DIAMETER_AX_DEF takes an axis name (\"X\")");
}

bool isResetValues(std::string_view name) {
  return name == "$MC_GCODE_RESET_VALUES" || name == "MD20150";
}

}  // namespace

// The G group `index + 1` at its reset value `value` (1-based position in the group).
void Interpreter::applyResetValue(int index, int value) {
  switch (index) {
    case 5:
      modal_.plane = value == 1 ? Plane::G17 : value == 2 ? Plane::G18 : Plane::G19;
      return;
    case 13:
      modal_.incremental = value == 2;
      return;
    case 14:
      setFeedType(static_cast<FeedType>(value - 1));  // G93, G94, G95, G96, G97 in order
      return;
    case 28: {
      const DiamMode m[] = {DiamMode::Off, DiamMode::On, DiamMode::On90, DiamMode::CycOff};
      setDiameterMode(m[value - 1], "MD20150 $MC_GCODE_RESET_VALUES[28]");
      return;
    }
    default:
      return;
  }
}

int Interpreter::resetIndex(std::span<const Value> idx, bool indexed) const {
  if (!indexed || idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, "$MC_GCODE_RESET_VALUES needs [G group - 1]");
  const double n = lang::toNumber(idx[0], "G group index");
  if (!(n >= 0 && n < 60) || n != std::floor(n))
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index 1: $MC_GCODE_RESET_VALUES[{}]", n));
  const int index = static_cast<int>(n);
  if (groupSize(index) == 0)
    raise(AlarmNumber::UnitsOrData,
          fmt::format("MD20150 $MC_GCODE_RESET_VALUES[{}] (G group {}) is not modelled by "
                      "ncoffset (modelled: [5] plane, [13] G90/G91, [14] feed type, [28] "
                      "diameter programming)",
                      index, index + 1));
  return index;
}

bool Interpreter::turningDataRead(std::string_view name, std::span<const Value> idx, bool indexed,
                                  Value& out) {
  if (isResetValues(name)) {
    out = Value::integer(reset_values_[static_cast<size_t>(resetIndex(idx, indexed))]);
    return true;
  }
  if (name != "$MC_DIAMETER_AX_DEF" && name != "MD20100") return false;
  if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
  const int tx = transverseAxis();
  out = Value::string(tx < 0 ? std::string() : std::string(1, "XYZ"[tx]));
  return true;
}

bool Interpreter::turningDataWrite(std::string_view name, std::span<const Value> idx, bool indexed,
                                   const Value& v) {
  if (isResetValues(name)) {
    const int index = resetIndex(idx, indexed);
    const double value = lang::toNumber(v, "machine data");
    if (!(value >= 1 && value <= groupSize(index)) || value != std::floor(value))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: MD20150[{}] = {} (allowed 1 .. {})", index, value,
                        groupSize(index)));
    reset_values_[static_cast<size_t>(index)] = static_cast<int>(value);
    // Init files run before the program, which starts from reset: the group takes its reset
    // value now.
    applyResetValue(index, static_cast<int>(value));
    return true;
  }
  const int id = data_.find(name);
  if (id >= 0 && id == md_base_function_mask_) {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
    const double value = lang::toNumber(v, "machine data");
    if (value != 0 && value != 4)
      raise(AlarmNumber::UnitsOrData,
            fmt::format("MD30460 BASE_FUNCTION_MASK = {} is not modelled by ncoffset (only 0 "
                        "and 4: bit 2, axis-specific diameter programming permitted)",
                        value));
    data_.set(id, axisIndexOf(idx[0]), value);
    updateDiameter();
    return true;
  }
  if (id < 0 || id != md_transverse_) return false;
  if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
  data_.set(id, transverseFrom(v));
  resetDiameterAxes();
  return true;
}

}  // namespace ncoffset::interp
