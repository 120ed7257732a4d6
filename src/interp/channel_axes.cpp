#include "interp/channel_axes.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/not_modelled.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::AxisMode;

double modulo360(double v) {
  double m = std::fmod(v, 360.0);
  if (m < 0) m += 360.0;
  return m >= 360.0 ? 0.0 : m;  // fmod of a tiny negative value
}

bool AxisFrame::empty() const {
  for (size_t k = 0; k < coarse.size(); ++k)
    if (coarse[k] != 0 || fine[k] != 0 || mirror[k]) return false;
  return true;
}

// The default channel (decision, docs/language.md "Axes"): A, B, C rotary modulo 360 (DIN 66217:
// the rotary axes about X, Y, Z), U, V, W linear (the secondary axes parallel to X, Y, Z).
ChannelAxes::ChannelAxes() {
  for (const char* n : {"A", "B", "C", "U", "V", "W"}) {
    ExtraAxis a;
    a.name = n;
    a.machine = std::string(n) + "1";
    a.rotary = a.modulo = n[0] <= 'C';
    axes_.push_back(a);
  }
  grow();
}

void ChannelAxes::grow() {
  programmable_.resize(axes_.size());
  for (auto& [n, f] : settable_) f.resize(axes_.size());
}

int ChannelAxes::find(std::string_view name, bool machine_names) const {
  for (size_t k = 0; k < axes_.size(); ++k)
    if (axes_[k].name == name || (machine_names && axes_[k].machine == name))
      return static_cast<int>(k);
  return -1;
}

int ChannelAxes::geometryAxisOf(std::string_view name, std::string_view what) const {
  if (int i = geometry(name); i >= 0) return i;
  if (find(name, true) >= 0)
    core::notModelled(fmt::format("{} of the additional axis {}", what, name),
                      "only the geometry axes take part here");
  raise(AlarmNumber::NameNotDefined,
        fmt::format("name {} not defined: no geometry axis of this channel ({}, {}, {})", name,
                    geo_[0], geo_[1], geo_[2]));
}

int ChannelAxes::geometry(std::string_view name) const {
  for (int i = 0; i < 3; ++i)
    if (geo_[static_cast<size_t>(i)] == name) return i;
  return -1;
}

namespace {
void checkAxisName(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 8 && std::isalpha(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: axis name \"{}\" (a letter, then letters or "
                      "digits, at most 8 characters)",
                      name));
}
}  // namespace

void ChannelAxes::setName(std::string_view table, int index, const std::string& raw) {
  std::string name;
  for (char c : raw) name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (table == "GEOAX") {
    if (index < 0 || index > 2)
      raise(AlarmNumber::ArrayIndex1,
            fmt::format("illegal array index 1: $MC_AXCONF_GEOAX_NAME_TAB[{}] (0..2)", index));
    checkAxisName(name);
    geo_[static_cast<size_t>(index)] = name;
    geo_renamed_ = geo_[0] != "X" || geo_[1] != "Y" || geo_[2] != "Z";
    return;
  }
  // MD20080 / MD10000: entries 0..2 are the channel / machine axes the geometry axes are
  // assigned to (MD20050 default 1, 2, 3); entries 3.. the additional axes.
  if (index < 0 || index >= static_cast<int>(kMaxAxes) + 3)
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index 1: {} entry {} (0..{})", table, index, kMaxAxes + 2));
  if (index < 3) {
    if (!name.empty()) checkAxisName(name);
    return;  // the geometry axes are programmed by their MD20060 names
  }
  const size_t k = static_cast<size_t>(index - 3);
  if (table == "CHANAX" && !configured_) {
    configured_ = true;  // the machine's own channel: only the axes its data name
    axes_.clear();
  }
  if (k >= axes_.size()) {
    if (name.empty()) return;
    axes_.resize(k + 1);
    for (size_t j = 0; j < axes_.size(); ++j)
      if (axes_[j].machine.empty()) axes_[j].machine = fmt::format("AX{}", j + 4);
  }
  if (!name.empty()) checkAxisName(name);
  if (table == "CHANAX") {
    axes_[k].name = name;
    // The default type by the name (DIN 66217): A, B, C rotary modulo 360, others linear;
    // MD30300/MD30310 after it say otherwise.
    axes_[k].rotary = axes_[k].modulo = name.size() == 1 && name[0] >= 'A' && name[0] <= 'C';
    axes_[k].machine_pos = 0;
  } else {
    axes_[k].machine = name;
  }
  grow();
}

std::string ChannelAxes::name(std::string_view table, int index) const {
  if (table == "GEOAX") return index >= 0 && index < 3 ? geo_[static_cast<size_t>(index)] : "";
  if (index >= 0 && index < 3) return table == "CHANAX" ? geo_[static_cast<size_t>(index)] : "";
  const size_t k = static_cast<size_t>(index - 3);
  if (index < 0 || k >= axes_.size()) return "";
  return table == "CHANAX" ? axes_[k].name : axes_[k].machine;
}

void ChannelAxes::setRotary(int axis, bool rotary) {
  auto& a = axes_[static_cast<size_t>(axis)];
  a.rotary = rotary;
  if (!rotary) a.modulo = false;
}

void ChannelAxes::setModulo(int axis, bool modulo) {
  auto& a = axes_[static_cast<size_t>(axis)];
  a.modulo = modulo && a.rotary;
  if (a.modulo) a.machine_pos = modulo360(a.machine_pos);
}

void ChannelAxes::collect(const AxisWord& w) {
  for (const auto& o : words_)
    if (o.axis == w.axis)
      raise(AlarmNumber::AddressTwice, fmt::format("address {} programmed too often",
                                                   axes_[static_cast<size_t>(w.axis)].name));
  const auto& a = axes_[static_cast<size_t>(w.axis)];
  if (w.mode == AxisMode::DC || w.mode == AxisMode::ACP || w.mode == AxisMode::ACN) {
    if (!a.modulo)
      raise(w.mode == AxisMode::DC    ? AlarmNumber::DcNotAllowed
            : w.mode == AxisMode::ACP ? AlarmNumber::AcpNotAllowed
                                      : AlarmNumber::AcnNotAllowed,
            fmt::format("traverse instruction {} for axis {} not allowed (not a modulo rotary "
                        "axis: MD30300/MD30310)",
                        w.mode == AxisMode::DC    ? "DC"
                        : w.mode == AxisMode::ACP ? "ACP"
                                                  : "ACN",
                        a.name));
    if (!(w.value >= 0 && w.value < 360))
      raise(AlarmNumber::ModuloPosition,
            fmt::format("invalid modulo position programmed: {}={} (0 <= value < 360)", a.name,
                        w.value));
  } else if (w.mode != AxisMode::Default && w.mode != AxisMode::AC && w.mode != AxisMode::IC) {
    raise(AlarmNumber::NoTransverseAxis,
          fmt::format("no transverse axis: DAC/DIC/RAC/RIC are not allowed for axis {}", a.name));
  }
  if (!std::isfinite(w.value) || std::fabs(w.value) > 1e9)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: position {} of axis {}", w.value, a.name));
  words_.push_back(w);
}

AxisFrame& ChannelAxes::settableFrame(size_t n) {
  AxisFrame& f = settable_[n];
  f.resize(axes_.size());
  return f;
}

double ChannelAxes::offset(int k, size_t settable) const {
  const size_t i = static_cast<size_t>(k);
  double o = programmable_.coarse[i] + programmable_.fine[i];
  if (auto it = settable_.find(settable); it != settable_.end())
    o += it->second.coarse[i] + it->second.fine[i];
  return o;
}

bool ChannelAxes::mirrored(int k, size_t settable) const {
  const size_t i = static_cast<size_t>(k);
  bool m = programmable_.mirror[i];
  if (auto it = settable_.find(settable); it != settable_.end()) m = m != it->second.mirror[i];
  return m;
}

// MCS = sign * WCS + offset (K2 "Frames": translation, then mirroring of the programmed value).
double ChannelAxes::wcs(int k, size_t settable) const {
  const auto& a = axes_[static_cast<size_t>(k)];
  double v = a.machine_pos - offset(k, settable);
  if (mirrored(k, settable)) v = -v;
  return a.modulo ? modulo360(v) : v;
}

// The travel of each axis by its mode (FM R2 "Modulo 360 degrees", PM-NC "Absolute dimensions
// for rotary axes"): on a modulo axis G90/AC moves towards the target within one turn (target >
// position: positive, MD30455 bit 2 = 0), DC the shorter way (180 degrees: positive), ACP
// positive, ACN negative; G91/IC by the value. The modulo machine position stays in [0, 360).
void ChannelAxes::move(bool incremental, bool inch, size_t settable, bool suppressed) {
  const size_t frame = suppressed ? static_cast<size_t>(-1) : settable;
  for (const AxisWord& w : words_) {
    auto& a = axes_[static_cast<size_t>(w.axis)];
    const double value = inch && !a.rotary ? w.value * 25.4 : w.value;
    const bool absolute = w.mode == AxisMode::AC || (w.mode == AxisMode::Default && !incremental) ||
                          w.mode == AxisMode::DC || w.mode == AxisMode::ACP ||
                          w.mode == AxisMode::ACN;
    const double from = suppressed ? a.machine_pos : wcs(w.axis, frame);
    double travel;
    if (!absolute) {
      travel = value;
    } else if (!a.modulo) {
      travel = value - from;
    } else {
      const double d = modulo360(value) - from;  // in (-360, 360)
      const double up = modulo360(d);            // the positive way, [0, 360)
      if (w.mode == AxisMode::ACP)
        travel = up;
      else if (w.mode == AxisMode::ACN)
        travel = up == 0 ? 0 : up - 360;
      else if (w.mode == AxisMode::DC)
        travel = up <= 180 ? up : up - 360;
      else
        travel = d;
    }
    if (mirrored(w.axis, frame)) travel = -travel;
    double pos = a.machine_pos + travel;
    if (!std::isfinite(pos) || std::fabs(pos) > 1e9)
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: position {} of axis {}", pos, a.name));
    a.machine_pos = a.modulo ? modulo360(pos) : pos;
  }
}

void ChannelAxes::frameCommand(std::string_view cmd, bool inch) {
  const bool replace = cmd == "TRANS" || cmd == "ROT" || cmd == "SCALE" || cmd == "MIRROR";
  if (replace) programmable_ = AxisFrame(), programmable_.resize(axes_.size());
  for (const AxisWord& w : words_) {
    const auto& a = axes_[static_cast<size_t>(w.axis)];
    const size_t i = static_cast<size_t>(w.axis);
    if (cmd == "TRANS" || cmd == "ATRANS") {
      // ATRANS adds in the coordinates of the frame before it: mirrored, the other way.
      const double v = inch && !a.rotary ? w.value * 25.4 : w.value;
      programmable_.coarse[i] += programmable_.mirror[i] && cmd == "ATRANS" ? -v : v;
    } else if (cmd == "MIRROR" || cmd == "AMIRROR") {
      programmable_.mirror[i] = !programmable_.mirror[i];
    } else {
      core::notModelled(fmt::format("{} {}", cmd, a.name),
                        "rotation and scaling act on the geometry axes only; an additional "
                        "axis in ROT/SCALE is not modelled");
    }
  }
}

void ChannelAxes::axialOffset(int g, bool inch) {
  for (const AxisWord& w : words_) {
    const auto& a = axes_[static_cast<size_t>(w.axis)];
    const double v = inch && !a.rotary ? w.value * 25.4 : w.value;
    (g == 58 ? programmable_.coarse : programmable_.fine)[static_cast<size_t>(w.axis)] = v;
  }
}

}  // namespace ncoffset::interp
