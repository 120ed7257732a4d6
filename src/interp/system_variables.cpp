// System variables ($P_UIFR, $P_PFRAME, $P_IFRAME, $P_ACTFRAME, $P_UIFRNUM, $P_EP, machine and
// setting data) and the predefined functions of the channel (CTRANS, CROT, ..., MSG, CHANDATA).
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

namespace {

int axisOf(const Value& v, const ChannelAxes& axes) {
  if (v.type == Type::Symbol || v.type == Type::Axis || v.type == Type::String)
    return axes.geometryAxisOf(v.str, "axis");
  raise(AlarmNumber::TypeMismatch, "an axis name (X, Y, Z) is expected");
}

Value frameValue(const Frame& f) {
  return {Type::Frame, 0, {}, std::make_shared<Frame>(f)};
}

const Frame& asFrame(const Value& v, std::string_view what) {
  if (v.type != Type::Frame || !v.frame)
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {} needs a FRAME", what));
  return *v.frame;
}

double& component(Frame& f, std::string_view comp, int axis) {
  if (comp == "TR") return f.coarse[axis];
  if (comp == "FI") return f.fine[axis];
  if (comp == "RT") return f.rotation[axis];
  if (comp == "SC") return f.scale[axis];
  raise(AlarmNumber::NameNotDefined,
        fmt::format("frame component {} not defined (TR, FI, RT, SC, MI)", comp));
}

}  // namespace

Frame* Interpreter::frameByName(std::string_view name, std::span<const Value> idx, bool indexed,
                                bool& whole) {
  whole = false;
  if (name == "$P_UIFR") {
    if (!indexed || (idx.size() != 1 && idx.size() != 3))
      raise(AlarmNumber::ArrayIndex1, "$P_UIFR needs [n] or [n,axis,component]");
    double n = lang::toNumber(idx[0], "frame number");
    double count = data_.get("$MC_MM_NUM_USER_FRAMES");
    if (n < 0 || n >= count || n != std::floor(n))
      raise(AlarmNumber::ArrayIndex1,
            fmt::format("illegal array index 1: $P_UIFR[{}] (0..{}, MD28080)", n, count - 1));
    whole = idx.size() == 1;
    return &frames_.settable(static_cast<size_t>(n));
  }
  Frame* f = nullptr;
  if (name == "$P_PFRAME")
    f = &frames_.programmable();
  else if (name == "$P_IFRAME")
    f = &frames_.settableActive();
  else if (name == "$P_PARTFR")  // the toolholder's system frames (docs/toolholders.md)
    f = &frames_.partFrame();
  else if (name == "$P_TOOLFR")
    f = &frames_.toolFrame();
  else if (name == "$P_WPFRAME")
    f = &frames_.workpieceFrame();
  else
    return nullptr;
  if (indexed && idx.size() != 2)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs no index or [axis,component]", name));
  whole = !indexed;
  return f;
}

int Interpreter::axisIndexOf(const Value& v) const {
  return axisOf(v, axes_);
}

bool Interpreter::readSystem(std::string_view name, std::span<const Value> idx, bool indexed,
                             Value& out) {
  if (turningDataRead(name, idx, indexed, out)) return true;
  if (axisDataRead(name, idx, indexed, out)) return true;  // axis_words.cpp
  if (int id = data_.find(name); id >= 0) {
    if (data_.isAxisData(id)) {
      if (!indexed || idx.size() != 1)
        raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
      out = Value::real(data_.get(id, axisOf(idx[0], axes_)));
      return true;
    }
    if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
    const DataSpec& s = data_.spec(id);
    out = s.integer ? Value::integer(data_.get(id)) : Value::real(data_.get(id));
    return true;
  }
  if (name == "CHKDNO") return tools_.read(name, idx, indexed, modal_.plane, out);  // no ()
  if (name.empty() || name[0] != '$') return false;
  if (tools_.read(name, idx, indexed, modal_.plane, out)) return true;
  if (readCarrier(name, idx, indexed, out)) return true;
  if (offsetWordRead(name, idx, indexed, out)) return true;
  if (readState(name, idx, indexed, out)) return true;
  if (name == "$P_APR" || name == "$P_AEP") {
    // Smooth approach (W1 2.4.4.4): P3 and P4 of the last evaluated approach, WCS.
    if (!indexed || idx.size() != 1)
      raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
    out = Value::real((name == "$P_APR" ? motion_.approachPoints().apr
                                        : motion_.approachPoints().aep)[axisOf(idx[0], axes_)]);
    return true;
  }
  if (name == "$P_APDV") {
    out = Value::integer(motion_.approachPoints().valid ? 1 : 0);
    return true;
  }
  if (name == "$P_UIFRNUM") {
    int f = modal_.frame_select;
    out = Value::integer(f == 500 ? 0 : f < 100 ? f - 53 : f - 500);
    return true;
  }
  if (name == "$P_ACTFRAME") {
    Frame act = frames_.active();
    if (!indexed) {
      out = frameValue(act);
      return true;
    }
    if (idx.size() != 2) raise(AlarmNumber::ArrayIndex1, "$P_ACTFRAME needs [axis,component]");
    int ax = axisOf(idx[0], axes_);
    std::string comp = lang::toText(idx[1]);
    out = comp == "MI" ? Value::integer(act.mirror[static_cast<size_t>(ax)] ? 1 : 0)
                       : Value::real(component(act, comp, ax));
    return true;
  }
  if (name == "$P_EP") {
    if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_EP needs [axis]");
    const int ax = axisOf(idx[0], axes_);
    out = Value::real(readPosition(motion_.wcs()[ax], ax));  // a diameter under DIAMON/DIAM90
    return true;
  }
  bool whole;
  Frame* f = frameByName(name, idx, indexed, whole);
  if (!f) return predefinedRead(name);  // (c) names: 99010; unknown: false (12550)
  if (whole) {
    out = frameValue(*f);
    return true;
  }
  size_t base = idx.size() == 3 ? 1 : 0;
  int ax = axisOf(idx[base], axes_);
  std::string comp = lang::toText(idx[base + 1]);
  out = comp == "MI" ? Value::integer(f->mirror[static_cast<size_t>(ax)] ? 1 : 0)
                     : Value::real(component(*f, comp, ax));
  return true;
}

void Interpreter::writeSystem(std::string_view name, std::span<const Value> idx, bool indexed,
                              const Value& v) {
  if (turningDataWrite(name, idx, indexed, v)) return;
  if (axisDataWrite(name, idx, indexed, v)) return;  // axis_words.cpp
  if (int id = data_.find(name); id >= 0) {
    if (data_.isAxisData(id)) {
      if (!indexed || idx.size() != 1)
        raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [axis]", name));
      data_.set(id, axisOf(idx[0], axes_), lang::toNumber(v, "machine data"));
      return;
    }
    if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
    data_.set(id, lang::toNumber(v, "machine/setting data"));
    if (data_.spec(id).number == 18110 || data_.spec(id).number == 18112) syncSumOffsetLimits();
    if (data_.spec(id).number == 28050) {  // MD28050 MM_NUM_R_PARAM: number of R parameters
      vars_.resizeR(static_cast<size_t>(data_.get(id)));
    }
    if (const int md = data_.spec(id).number; md >= 18102 && md <= 18106) configureDNumbers();
    return;
  }
  if (tools_.write(name, idx, indexed, v)) return;
  if (writeCarrier(name, idx, indexed, v)) return;
  if (double* counter = partCounter(name)) {  // the workpiece counters (state_variables.cpp)
    if (indexed) raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes no index", name));
    *counter = lang::toNumber(v, "workpiece count");
    return;
  }
  if (name == "$P_UIFRNUM" || name == "$P_ACTFRAME" || name == "$P_EP" || name == "$AA_IW")
    raise(AlarmNumber::NameNotDefined, fmt::format("{} can only be read", name));
  bool whole;
  Frame* f = frameByName(name, idx, indexed, whole);
  if (!f) {
    if (offsetWordWrite(name, idx, indexed, v)) return;  // DL=, TOFFL=, TOFF[ax]=, TOFFR=
    if (predefinedAssign(name, v)) return;               // docs/names.md: ADIS=, ACC[X]=, DL=0, ...
    if (!name.empty() && name[0] == '$')
      raise(AlarmNumber::NameNotDefined,
            fmt::format("name {} not defined or option/function not available", name));
    raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", name));
  }
  if (whole) {
    *f = asFrame(v, name);
  } else {
    size_t base = idx.size() == 3 ? 1 : 0;
    int ax = axisOf(idx[base], axes_);
    std::string comp = lang::toText(idx[base + 1]);
    double x = lang::toNumber(v, "frame component");
    if (!(std::fabs(x) <= 1e9) || ((comp == "RT" || comp == "SC") && !(std::fabs(x) <= 1e6)))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: {}[..,{}] = {}", name, comp, x));
    if (comp == "MI") {
      f->mirror[static_cast<size_t>(ax)] = x != 0;
    } else {
      if (comp == "SC" && std::fabs(x) < 1e-12)
        raise(AlarmNumber::ValueRange, "value range exceeded: scale factor 0");
      if (comp == "TR" || comp == "FI") x = toMm(x);
      component(*f, comp, ax) = x;
    }
  }
  // $P_UIFR takes effect at the next G500/G54..G599 (K2); the active frames at once.
  if (name == "$P_UIFR") return;
  frames_.update();
}

Value Interpreter::call(std::string_view name, std::span<const Value> args) {
  if (name == "CTRANS" || name == "CFINE" || name == "CROT" || name == "CSCALE") {
    if (args.size() % 2 != 0)
      raise(
          AlarmNumber::WrongCallParams,
          fmt::format("wrong number of parameters in call of {}: axis/value pairs expected", name));
    Frame f;
    Vec3 angles;
    for (size_t k = 0; k < args.size(); k += 2) {
      int ax = axisOf(args[k], axes_);
      double x = lang::toNumber(args[k + 1], "frame value");
      if (name == "CTRANS")
        f.coarse[ax] = toMm(x);
      else if (name == "CFINE")
        f.fine[ax] = toMm(x);
      else if (name == "CROT")
        angles[ax] = x;
      else {
        if (std::fabs(x) < 1e-12)
          raise(AlarmNumber::ValueRange, "value range exceeded: scale factor 0");
        f.scale[ax] = x;
      }
    }
    if (name == "CROT") f.rotation = rpyAngles(rpyMatrix(angles));
    return frameValue(f);
  }
  if (name == "CMIRROR") {
    Frame f;
    for (const auto& a : args) f.addMirror(axisOf(a, axes_));
    return frameValue(f);
  }
  if (name == "MSG") {
    if (args.size() > 2) raise(AlarmNumber::WrongCallParams, "MSG takes one text");
    sink_.message({fileName(file_), line_}, args.empty() || args[0].type == Type::Empty
                                                ? std::string()
                                                : lang::toText(args[0]));
    return Value::empty();
  }
  if (name == "CHANDATA") {
    if (args.size() != 1) raise(AlarmNumber::WrongCallParams, "CHANDATA takes a channel number");
    double ch = lang::toNumber(args[0], "channel");
    if (ch != 1)
      raise(AlarmNumber::NotModelled,
            fmt::format("CHANDATA({}): ncoffset models one channel (CHANDATA(1))", ch));
    return Value::empty();
  }
  if (name == "LENTOAX") return callLentoax(args);
  if (diameterAxisCall(name, args)) return Value::empty();
  if (name == "SETMS") {
    // SETMS(n): spindle n becomes the master spindle (PM-NC "Spindle"): no path effect; M6
    // keeps acting for spindle 1 (MD20090 = 1 is what ncoffset models).
    if (args.size() > 1) raise(AlarmNumber::WrongCallParams, "SETMS takes one spindle number");
    return Value::empty();
  }
  if (Value out; toolFunction(name, args, out)) return out;  // tool_functions.cpp
  if (Value out; predefinedCall(name, args, out)) return out;
  // A subprogram returns no value (PROC has no result; FCTDEF polynomials serve synchronized
  // actions only, PM-JP "Polynomial definition"): as a function in an expression its name is
  // not defined (docs/language.md "Subprograms with parameters").
  if (programExists(name))
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined as a function: {} is a subprogram, which returns no "
                      "value (call it in a block of its own, results by VAR parameters)",
                      name, name));
  raise(AlarmNumber::NameNotDefined,
        fmt::format("name {} not defined or option/function not available", name));
}

Value Interpreter::chain(const Value& a, const Value& b) {
  return frameValue(ncoffset::chain(asFrame(a, "':'"), asFrame(b, "':'")));
}

}  // namespace ncoffset::interp
