// The additional axes in the interpreter (docs/language.md "Axes"): their words, their motion
// and its event, their machine data and their reads. A program without them pays one flag test
// per block (BlockWords::extra_axes) and nothing else.
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "core/not_modelled.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::AxisMode;
using lang::Stmt;
using lang::Value;

// An axis word by its configured name: a renamed geometry axis (X1=10) or an additional axis
// (A90, A=DC(90), U1=5). False when `name` names no axis.
bool Interpreter::axisWord(const Stmt& st) {
  const std::string_view name = st.name;
  // (wordValue is inlined into block_words.cpp only.)
  auto value = [&] { return st.literal ? st.literal_value : eval_.number(block_, st.expr); };
  if (int i = axes_.geometry(name); i >= 0) {
    if (words_.axis[i])
      raise(AlarmNumber::AddressTwice, fmt::format("address {} programmed too often", name));
    words_.axis[i] = true;
    words_.axis_value[i] = value();
    words_.axis_mode[i] = st.mode;
    return true;
  }
  const int k = axes_.find(name, false);
  if (k < 0) return false;
  axes_.collect({k, value(), st.mode});
  words_.extra_axes = true;
  return true;
}

// The settable frame of G500/G54..G57/G505..G599 (0..99).
size_t Interpreter::settableIndex() const {
  const int f = modal_.frame_select;
  return static_cast<size_t>(f == 500 ? 0 : f < 100 ? f - 53 : f - 500);
}

// The block's additional axes: frame words, or their motion (with the event, before the
// block's segments) and the block's motion (also when the geometry stays: a row of its own).
bool Interpreter::axesBlock(bool consumed, bool geometry_motion) {
  const bool inch = modal_.units == Units::G70 || modal_.units == Units::G700;
  if (!words_.frame_command.empty()) {
    axes_.clearWords();
    return false;  // frameCommand took them (finishBlock)
  }
  if (consumed) {
    if (words_.axial_offset == 58 || words_.axial_offset == 59)
      axes_.axialOffset(words_.axial_offset, inch);
    axes_.clearWords();
    return false;
  }
  axes_.move(modal_.incremental, inch, settableIndex(), words_.suppress_frames != 0);
  AxesEvent e{line_, file_, {}};
  for (const auto& w : axes_.words())
    if (!axes_.axes()[static_cast<size_t>(w.axis)].output)
      core::notModelled(
          fmt::format("axis {} without an output column", axes_.axes()[w.axis].name),
          "the output columns are the channel axes an init file configures: name the axis "
          "there ($MC_AXCONF_CHANAX_NAME_TAB[3]=\"A\", docs/language.md \"Axes\")");
  for (size_t k = 0; k < axes_.axes().size(); ++k)
    if (axes_.axes()[k].output)
      e.positions.push_back(options_.coords == CoordSystem::MCS
                                ? axes_.mcs(static_cast<int>(k))
                                : axes_.wcs(static_cast<int>(k), settableIndex()));
  axes_.clearWords();
  sink_.axes(e);
  // TCOABS with a holder whose angles are channel axes: the tool length follows their position
  // at the start of the next block (W1 2.5.4 "the axis position ... at the start of the current
  // block is used").
  const auto angles =
      carrier_.number > 0 ? carrierAxisAngles(carrier_.number) : std::array<double, 2>{NAN, NAN};
  if (carrier_.mode == tool::CarrierAngles::Absolute &&
      (!std::isnan(angles[0]) || !std::isnan(angles[1]))) {
    carrier_.axis_moved = true;
    carrier_.pending = true;
  }
  const BlockContext at{line_, file_, feed_before_, motion_before_};
  const bool is_arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  if (geometry_motion || !is_arc) return motion_.build(words_, modal_, at);
  // An additional axis alone under G2/G3: the geometry stays, the axis moves at the feed.
  ModalState linear = modal_;
  linear.motion = Motion::G1;
  return motion_.build(words_, linear, at);
}

// The output columns of a run (docs/output-formats.md): the additional axes the init files
// configured (MD20080). Without that configuration an additional axis has no column, and moving
// it is alarm 99010 (axesBlock): the header is written before the program runs, and a program
// without additional axes keeps exactly its columns.
void Interpreter::announceAxes() {
  axes_.clearWords();
  std::vector<std::string> names;
  for (size_t k = 0; k < axes_.axes().size(); ++k) {
    const ExtraAxis& a = axes_.axes()[k];
    const bool used = axes_.configured() && !a.name.empty();
    axes_.setOutput(static_cast<int>(k), used);
    if (used) names.push_back(a.name);
  }
  if (!names.empty()) sink_.axisNames(names);
}

namespace {
// MD20060 / MD20080 / MD10000: the table a name stands for ("" for none).
std::string_view nameTable(std::string_view name) {
  if (name == "$MC_AXCONF_GEOAX_NAME_TAB" || name == "MD20060") return "GEOAX";
  if (name == "$MC_AXCONF_CHANAX_NAME_TAB" || name == "MD20080") return "CHANAX";
  if (name == "$MN_AXCONF_MACHAX_NAME_TAB" || name == "MD10000") return "MACHAX";
  return {};
}
bool isRotaryFlag(std::string_view name) {
  return name == "$MA_IS_ROT_AX" || name == "MD30300";
}
bool isModuloFlag(std::string_view name) {
  return name == "$MA_ROT_IS_MODULO" || name == "MD30310";
}
}  // namespace

// The axis of an index `[A]`, `[X1]`, `[AX4]`: 0..2 a geometry axis, 3 + k the additional axis
// k (channel or machine axis name); alarm 12550 for no axis of this channel.
int Interpreter::anyAxis(const Value& v, std::string_view what) const {
  if (!v.isText() && v.type != lang::Type::Symbol)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", what));
  std::string s;
  for (char c : v.str) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (int i = axes_.geometry(s); i >= 0) return i;
  if (int k = axes_.find(s, true); k >= 0) return 3 + k;
  // The default machine axis names of the geometry axes (X1, Y1, Z1 with MD10000 default).
  if (s.size() == 2 && s[1] == '1' && s[0] >= 'X' && s[0] <= 'Z') return s[0] - 'X';
  raise(AlarmNumber::NameNotDefined,
        fmt::format("{}[{}]: axis {} is not defined in this channel", what, v.str, v.str));
}

// $MC_AXCONF_..._NAME_TAB[n], $MA_IS_ROT_AX[ax], $MA_ROT_IS_MODULO[ax]; $AA_IW, $AA_IM, $P_EP
// of an additional axis. False for every other name (and for those of a geometry axis).
bool Interpreter::axisDataRead(std::string_view name, std::span<const Value> idx, bool indexed,
                               Value& out) {
  if (name.size() < 3 || (name[0] != '$' && name[0] != 'M')) return false;
  if (auto table = nameTable(name); !table.empty()) {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [n]", name));
    out = Value::string(axes_.name(table, static_cast<int>(lang::toNumber(idx[0], "index"))));
    return true;
  }
  const bool flag = isRotaryFlag(name) || isModuloFlag(name);
  const bool position = name == "$AA_IW" || name == "$AA_IM" || name == "$P_EP";
  if (!flag && !position) return false;
  if (!indexed || idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
  const int ax = anyAxis(idx[0], name);
  if (ax < 3) {
    if (flag) out = Value::integer(0);  // the geometry axes are linear
    return flag;
  }
  const int k = ax - 3;
  const ExtraAxis& a = axes_.axes()[static_cast<size_t>(k)];
  if (flag) {
    out = Value::integer(isRotaryFlag(name) ? a.rotary : a.modulo);
    return true;
  }
  if (name != "$P_EP") mainRunStop();  // a main-run variable: implicit preprocessing stop
  out = Value::real(name == "$AA_IM" ? axes_.mcs(k) : axes_.wcs(k, settableIndex()));
  return true;
}

// $P_UIFR[n,A,TR], $P_UIFR[n,A,FI], $P_UIFR[n,A,MI], $P_PFRAME[A,TR], ... of an additional axis:
// its translation and mirroring (K2 "Frames"; RT and SC act on geometry axes only).
bool Interpreter::axisFrameWrite(std::string_view name, std::span<const Value> idx,
                                 const Value& v) {
  const bool uifr = name == "$P_UIFR" && idx.size() == 3;
  const bool pframe = (name == "$P_PFRAME" || name == "$P_IFRAME") && idx.size() == 2;
  if (!uifr && !pframe) return false;
  const size_t base = uifr ? 1 : 0;
  if (!idx[base].isText() && idx[base].type != lang::Type::Symbol) return false;
  const int ax = anyAxis(idx[base], name);
  if (ax < 3) return false;
  const std::string comp = lang::toText(idx[base + 1]);
  const double x = lang::toNumber(v, "frame component");
  if (!(std::fabs(x) <= 1e9))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {}[..,{}] = {}", name, comp, x));
  AxisFrame& f = name == "$P_PFRAME" ? axes_.programmable()
                 : uifr ? axes_.settableFrame(static_cast<size_t>(lang::toNumber(idx[0], "frame")))
                        : axes_.settableFrame(settableIndex());
  const size_t k = static_cast<size_t>(ax - 3);
  const bool linear = !axes_.axes()[k].rotary;
  if (comp == "TR")
    f.coarse[k] = linear ? toMm(x) : x;
  else if (comp == "FI")
    f.fine[k] = linear ? toMm(x) : x;
  else if (comp == "MI")
    f.mirror[k] = x != 0;
  else
    core::notModelled(fmt::format("{}[..,{},{}]", name, idx[base].str, comp),
                      "rotation and scaling act on the geometry axes only");
  return true;
}

bool Interpreter::axisDataWrite(std::string_view name, std::span<const Value> idx, bool indexed,
                                const Value& v) {
  if (name.size() < 3 || (name[0] != '$' && name[0] != 'M')) return false;
  if (indexed && name[1] == 'P' && axisFrameWrite(name, idx, v)) return true;
  if (auto table = nameTable(name); !table.empty()) {
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [n]", name));
    axes_.setName(table, static_cast<int>(lang::toNumber(idx[0], "index")), lang::toText(v));
    return true;
  }
  if (!isRotaryFlag(name) && !isModuloFlag(name)) return false;
  if (!indexed || idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
  const int ax = anyAxis(idx[0], name);
  const bool on = lang::toNumber(v, "machine data") != 0;
  if (ax < 3) {
    if (on)
      core::notModelled(fmt::format("{}[{}]=1", name, idx[0].str),
                        "a geometry axis is linear in ncoffset");
    return true;
  }
  if (isRotaryFlag(name))
    axes_.setRotary(ax - 3, on);
  else
    axes_.setModulo(ax - 3, on);
  return true;
}

}  // namespace ncoffset::interp
