// Turning (docs/turning.md): diameter programming of the channel (G group 29: DIAMON, DIAM90,
// DIAMOF, DIAMCYCOF) and per axis (DIAMONA[ax], DIAM90A[ax], DIAMOFA[ax], DIACYCOFA[ax],
// DIAMCHANA[ax], DIAMCHAN) on the transverse axis of MD20100 $MC_DIAMETER_AX_DEF; the reset
// values of MD20150 $MC_GCODE_RESET_VALUES the path depends on; the feed types of G group 15
// and the spindle words without path effect (SETMS). PM-NC "Dimensions for turning", FM P1
// "Transverse axes".
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

namespace {

constexpr const char* kAxisNames = "XYZ";

// The factors of a mode: a diameter is twice the radius position. DIAMON: absolute and
// incremental values are diameters; DIAM90: absolute diameters, incremental radii; DIAMOF and
// DIAMCYCOF: radii.
void factors(DiamMode m, double& abs, double& inc) {
  abs = m == DiamMode::On || m == DiamMode::On90 ? 0.5 : 1;
  inc = m == DiamMode::On ? 0.5 : 1;
}

DiamMode asChannelMode(DiamAxis a) {
  switch (a) {
    case DiamAxis::On:
      return DiamMode::On;
    case DiamAxis::On90:
      return DiamMode::On90;
    case DiamAxis::CycOff:
      return DiamMode::CycOff;
    default:
      return DiamMode::Off;
  }
}

}  // namespace

int Interpreter::transverseAxis() const {
  return static_cast<int>(data_.get(md_transverse_));
}

// An axis may be programmed in diameter when it is the transverse axis of MD20100 or MD30460
// bit 2 permits it (FM P1 "Axis-specific diameter programming").
bool Interpreter::diameterPermitted(int axis) const {
  return axis == transverseAxis() ||
         (static_cast<long long>(data_.get(md_base_function_mask_, axis)) & 4) != 0;
}

void Interpreter::updateDiameter() {
  for (int i = 0; i < 3; ++i) {
    modal_.diam_permitted[i] = diameterPermitted(i);
    const DiamAxis a = modal_.diam_axis[i];
    factors(a == DiamAxis::Chan ? modal_.diam : asChannelMode(a), modal_.diam_abs[i],
            modal_.diam_inc[i]);
  }
}

// MD20100 changed: its axis follows the channel's group 29, every other axis programs radii.
void Interpreter::resetDiameterAxes() {
  const int tx = transverseAxis();
  for (int i = 0; i < 3; ++i) modal_.diam_axis[i] = i == tx ? DiamAxis::Chan : DiamAxis::Off;
  updateDiameter();
}

void Interpreter::setDiameterMode(DiamMode m, std::string_view word) {
  if ((m == DiamMode::On || m == DiamMode::On90) && transverseAxis() < 0)
    raise(AlarmNumber::NoTransverseAxis,
          fmt::format("no transverse axis exists for {}: MD20100 $MC_DIAMETER_AX_DEF names none "
                      "(an init file sets it: $MC_DIAMETER_AX_DEF=\"X\")",
                      word));
  modal_.diam = m;
  updateDiameter();
}

// DIAMON, DIAM90, DIAMOF, DIAMCYCOF, DIAMCHAN (a named word); false for every other name.
bool Interpreter::diameterWord(std::string_view w) {
  if (w.size() < 6 || w.substr(0, 4) != "DIAM") return false;
  if (w == "DIAMON") {
    setDiameterMode(DiamMode::On, w);
  } else if (w == "DIAM90") {
    setDiameterMode(DiamMode::On90, w);
  } else if (w == "DIAMOF") {
    setDiameterMode(DiamMode::Off, w);
  } else if (w == "DIAMCYCOF") {
    setDiameterMode(DiamMode::CycOff, w);
  } else if (w == "DIAMCHAN") {
    // Every axis permitted for diameter programming takes over the channel's state.
    for (int i = 0; i < 3; ++i)
      if (diameterPermitted(i)) modal_.diam_axis[i] = DiamAxis::Chan;
    updateDiameter();
  } else {
    return false;
  }
  return true;
}

// DIAMONA[ax], DIAM90A[ax], DIAMOFA[ax], DIACYCOFA[ax], DIAMCHANA[ax].
bool Interpreter::diameterAxisCall(std::string_view name, std::span<const Value> args) {
  DiamAxis mode;
  if (name == "DIAMONA")
    mode = DiamAxis::On;
  else if (name == "DIAM90A")
    mode = DiamAxis::On90;
  else if (name == "DIAMOFA")
    mode = DiamAxis::Off;
  else if (name == "DIACYCOFA")
    mode = DiamAxis::CycOff;
  else if (name == "DIAMCHANA")
    mode = DiamAxis::Chan;
  else
    return false;
  if (args.size() != 1)
    raise(AlarmNumber::WrongCallParams, fmt::format("{}[axis] takes one axis", name));
  const int ax = axisIndexOf(args[0]);
  if (!diameterPermitted(ax))
    raise(AlarmNumber::NoTransverseAxis,
          fmt::format("no transverse axis: {}[{}] needs {} as the transverse axis (MD20100) or "
                      "permitted by MD30460 bit 2",
                      name, kAxisNames[ax], kAxisNames[ax]));
  modal_.diam_axis[ax] = mode;
  updateDiameter();
  return true;
}

// A position of axis `ax` as the program reads it ($P_EP, $AA_IW): a diameter where DIAMON or
// DIAM90 is active for the axis (PM-NC: "also when reading the actual values in the WCS").
double Interpreter::readPosition(double radius_value, int ax) const {
  return modal_.diam_abs[ax] == 1 ? radius_value : radius_value * 2;
}

// An extended address of turning; false for every other name. Not inlined into the word loop.
bool Interpreter::turningWord(const lang::Stmt& st) {
  if (st.name == "LIMS") {
    // LIMS=: the spindle speed limit of G96/G961 (PM-NC "Constant cutting rate"): no path
    // effect.
    const double v = st.literal ? st.literal_value : eval_.number(block_, st.expr);
    if (!(v >= 0 && v <= 1e9))
      raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: LIMS={}", v));
    return true;
  }
  return false;
}

void Interpreter::setFeedType(FeedType t) {
  modal_.feed_type = t;
  switch (t) {
    case FeedType::G93:
      modal_.feed_unit = FeedUnit::InverseTime;
      return;
    case FeedType::G95:
    case FeedType::G96:
    case FeedType::G97:
      modal_.feed_unit = FeedUnit::MmPerRev;
      return;
    default:
      modal_.feed_unit = FeedUnit::MmPerMin;
      return;
  }
}

}  // namespace ncoffset::interp
