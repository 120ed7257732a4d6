// The words of the orientable toolholder (W1 2.5, PM-JP "TCARR, TCOABS, TCOFR", K2 "frames in
// tool direction"; docs/toolholders.md): TCARR=m, G group 42 (TCOABS, TCOFR, TCOFRZ/Y/X), PAROT/
// PAROTOF, TOROT/TOFRAME and their variants, TOROTOF, the data $TC_CARR.., $P_TCANG, $P_TCSOL.
// Nothing here runs for a block that programs none of them.
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Value;

namespace {

// Group 53: the name's variant (TOFRAME and TOROT act alike here: docs/toolholders.md).
int toolFrameOf(std::string_view w) {
  if (w == "TOROTOF") return static_cast<int>(ToolFrame::Off);
  if (w == "TOROT" || w == "TOROTZ" || w == "TOFRAME" || w == "TOFRAMEZ")
    return static_cast<int>(ToolFrame::Z);
  if (w == "TOROTY" || w == "TOFRAMEY") return static_cast<int>(ToolFrame::Y);
  if (w == "TOROTX" || w == "TOFRAMEX") return static_cast<int>(ToolFrame::X);
  return -1;
}

// A frame holding only the rotation `r`.
Frame rotationFrame(const Mat3& r) {
  Frame f;
  f.rotation = rpyAngles(r);
  return f;
}

}  // namespace

void Interpreter::toolholderNumber(double m) {
  if (!(m >= 0 && m <= 1e9) || m != std::floor(m))
    raise(AlarmNumber::CarrierNumber,
          fmt::format("toolholder number programmed incorrectly: TCARR={}", m));
  carrier_.programmed_number = static_cast<int>(m);
  carrier_.pending = true;
}

bool Interpreter::toolholderNamedWord(std::string_view w) {
  using tool::CarrierAngles;
  if (w == "TCOABS" || w == "TCOFR" || w == "TCOFRZ" || w == "TCOFRY" || w == "TCOFRX") {
    const CarrierAngles mode = w == "TCOABS"   ? CarrierAngles::Absolute
                               : w == "TCOFRY" ? CarrierAngles::FrameY
                               : w == "TCOFRX" ? CarrierAngles::FrameX
                                               : CarrierAngles::FrameZ;
    // A change of group 42 recalculates the tool length components (W1 2.5.2 "Group change").
    carrier_.mode_changed = carrier_.mode_changed || mode != carrier_.mode;
    carrier_.mode = mode;
  } else if (w == "PAROT" || w == "PAROTOF") {
    carrier_.parot = w == "PAROT" ? 1 : 0;
  } else if (int f = toolFrameOf(w); f >= 0) {
    carrier_.toframe = f;
  } else {
    return false;
  }
  carrier_.pending = true;
  return true;
}

// The machine positions of the rotary axes holder m names in $TC_CARR21/22, where they are
// axes an init file configures for the channel (docs/toolholders.md "Angles"); NaN otherwise
// (a manual head, or an axis of the default channel that no program can move: $TC_CARR13/14).
std::array<double, 2> Interpreter::carrierAxisAngles(int m) const {
  std::array<double, 2> out{tool::ToolCarriers::kNoAxis, tool::ToolCarriers::kNoAxis};
  const std::array<std::string, 2> names = carriers_.axisNames(m);
  for (size_t i = 0; i < 2; ++i) {
    if (names[i].empty()) continue;
    const int k = axes_.find(names[i], false);
    if (k >= 0 && axes_.axes()[static_cast<size_t>(k)].output) out[i] = axes_.mcs(k);
  }
  return out;
}

void Interpreter::executeCarrierWords() {
  CarrierState& c = carrier_;
  c.pending = false;
  bool frames_changed = false;
  const bool follow_axes = c.axis_moved && c.number > 0;
  c.axis_moved = false;
  if (c.programmed_number >= 0 || (c.mode_changed && c.number > 0) || follow_axes) {
    if (c.programmed_number >= 0) c.number = c.programmed_number;
    carriers_.setCount(static_cast<int>(data_.get(md_carriers_)));
    c.pose = carriers_.pose(c.number, c.mode, frames_.map().linear,
                            data_.get(sd_carrier_fine_) != 0, carrierAxisAngles(c.number));
    tools_.setCarrier(c.pose.tool_rotation, c.pose.tool_offset, c.number > 0);
    // Types P and M: the table offset as the system frame $P_PARTFR (W1 2.5.4, MD28082 bit 2).
    frames_.partFrame() = Frame{};
    frames_.partFrame().coarse = c.pose.part_offset;
    frames_changed = true;
    if (events_) toolEvent();
  }
  if (c.parot >= 0) {
    // PAROT: the workpiece coordinate system turns with the table (K2 2.4, "PAROT"); PAROTOF
    // removes that rotation. A holder without a table (type T) gives no rotation.
    frames_.workpieceFrame() = c.parot == 1 ? rotationFrame(c.pose.part_rotation) : Frame{};
    frames_changed = true;
  }
  if (c.toframe >= 0) {
    frames_.toolFrame() = c.toframe == 0
                              ? Frame{}
                              : rotationFrame(toolFrameRotation(static_cast<ToolFrame>(c.toframe)));
    frames_changed = true;
  }
  if (frames_changed) frames_.update();
  c.programmed_number = -1;
  c.mode_changed = false;
  c.parot = -1;
  c.toframe = -1;
}

// TOROT/TOFRAME (K2 "frame rotation in tool direction", PM-NC "TOFRAME, TOROT"): a rotation whose
// Z (TOROTY: Y, TOROTX: X) axis points along the tool: the plane's applicate turned by the
// holder, the other two axes the plane's abscissa and ordinate turned alike (FM-W1 2.5.2
// "Toolholder from G code of group 53"; the table of TOFRAMEX/Y in K2). It sits inside $P_IFRAME: a
// rotation of the settable frame is taken out so that the axis points along the tool in the
// machine.
Mat3 Interpreter::toolFrameRotation(ToolFrame variant) const {
  const PlaneAxes pa = planeAxes(modal_.plane);
  const Mat3& rt = tools_.carrierRotation();
  auto column = [&](int axis) {
    Vec3 e;
    e[axis] = 1;
    return rt * e;
  };
  const Vec3 abs = column(pa.abscissa), ord = column(pa.ordinate), app = column(pa.applicate);
  std::array<Vec3, 3> cols = variant == ToolFrame::Z   ? std::array<Vec3, 3>{abs, ord, app}
                             : variant == ToolFrame::Y ? std::array<Vec3, 3>{ord, app, abs}
                                                       : std::array<Vec3, 3>{app, abs, ord};
  Mat3 q;
  for (size_t i = 0; i < 3; ++i)
    for (size_t k = 0; k < 3; ++k) q.m[i][k] = cols[k][static_cast<int>(i)];
  return frames_.settableActive().rotationMatrix().transposed() * q;
}

bool Interpreter::readCarrier(std::string_view name, std::span<const Value> idx, bool indexed,
                              Value& out) {
  if (name == "$P_TCANG") {
    // The angles of the active holder: [1],[2] those in effect, [3],[4] TCOFR's other solution.
    if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_TCANG needs [1..4]");
    const double k = lang::toNumber(idx[0], "index");
    if (k != std::floor(k) || k < 1 || k > 4)
      raise(AlarmNumber::ArrayIndex1, fmt::format("illegal array index: $P_TCANG[{}]", k));
    const tool::CarrierPose& p = carrier_.pose;
    const bool frame = carrier_.mode != tool::CarrierAngles::Absolute && p.number > 0;
    const double a = k == 1   ? p.angle1
                     : k == 2 ? p.angle2
                              : (frame ? p.solutions[static_cast<size_t>(k - 1)] : 0.0);
    out = Value::real(a);
    return true;
  }
  if (name == "$P_TCSOL") {  // the number of solutions TCOFR found
    if (indexed) raise(AlarmNumber::ArrayIndex1, "$P_TCSOL takes no index");
    out = Value::integer(
        carrier_.mode == tool::CarrierAngles::Absolute ? 0 : carrier_.pose.solution_count);
    return true;
  }
  carriers_.setCount(static_cast<int>(data_.get(md_carriers_)));
  return carriers_.read(name, idx, indexed, out);
}

bool Interpreter::writeCarrier(std::string_view name, std::span<const Value> idx, bool indexed,
                               const Value& v) {
  if (name == "TCARR" && !indexed) {  // `TCARR=1` read as an assignment
    toolholderNumber(lang::toNumber(v, "toolholder number"));
    return true;
  }
  carriers_.setCount(static_cast<int>(data_.get(md_carriers_)));
  return carriers_.write(name, idx, indexed, v);
}

}  // namespace ncoffset::interp
