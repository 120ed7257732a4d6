// The words of a block (PM-NC "Block structure", "Addresses"): axes, interpolation parameters,
// F, S, H, M, T, D, L, P and the extended addresses (CR=, AR=, TURN=, DISC=, OFFN=, the SAR
// words), collected into BlockWords before the block is executed.
#include <fmt/format.h>

#include <cmath>

#include "core/inline_step.hpp"
#include "core/not_modelled.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using core::notModelled;
using lang::AxisMode;
using lang::Stmt;
using lang::Value;

namespace {

int axisIndex(char c) {
  switch (c) {
    case 'X':
      return 0;
    case 'Y':
      return 1;
    case 'Z':
      return 2;
    default:
      return -1;
  }
}

}  // namespace

NCOFFSET_INLINE_STEP double Interpreter::wordValue(const Stmt& st) {
  return st.literal ? st.literal_value : eval_.number(block_, st.expr);
}

void Interpreter::collectWord(const Stmt& st) {
  std::string_view name = st.name;
  if (st.has_equals && st.mode == AxisMode::Default && vars_.find(name)) {
    // A user variable with a one-letter name (DEF REAL V): V=2 is an assignment.
    lang::Node target;
    target.kind = lang::NodeKind::Name;
    target.text = name;
    store(target, st.literal ? (st.literal_int ? lang::Value::integer(st.literal_value)
                                               : lang::Value::real(st.literal_value))
                             : eval_.eval(block_, st.expr));
    return;
  }
  if (name.size() == 1)
    letterWord(st);
  else
    extendedWord(st);
}

// A single-letter address: an axis, an interpolation parameter, G, F, S, H, M, T, D, L, P.
NCOFFSET_INLINE_STEP void Interpreter::letterWord(const Stmt& st) {
  std::string_view name = st.name;
  auto value = [&]() { return wordValue(st); };
  char c = name[0];
  if (int i = axisIndex(c); i >= 0) {  // also when MD20060 renamed them (docs "Axes")
    if (words_.axis[i])
      raise(AlarmNumber::AddressTwice, fmt::format("address {} programmed too often", name));
    words_.axis[i] = true;
    words_.axis_value[i] = value();
    words_.axis_mode[i] = st.mode;  // DAC/DIC/RAC/RIC: checked where applied (MotionBuilder)
    return;
  }
  if (st.mode != AxisMode::Default && c != 'I' && c != 'J' && c != 'K') {
    if (axisWord(st)) return;  // A=DC(90), X1 renamed (axis_words.cpp)
    raise(AlarmNumber::SyntaxError, fmt::format("AC/IC is not allowed with address {}", name));
  }
  switch (c) {
    case 'I':
    case 'J':
    case 'K': {
      int i = c - 'I';
      if (words_.centre[i])
        raise(AlarmNumber::AddressTwice, fmt::format("address {} programmed too often", name));
      words_.centre[i] = true;
      words_.centre_value[i] = value();
      words_.centre_mode[i] = st.mode;
      return;
    }
    case 'G': {
      double g = value();
      if (!(g >= 0 && g <= 9999) || static_cast<int>(g) != g)  // also NaN
        raise(AlarmNumber::UnknownGCode, fmt::format("G function G{} is unknown", g));
      gCode(static_cast<int>(g));
      return;
    }
    case 'F': {
      double f = value();
      if (f < 0 || f > 1e9)
        raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: F{}", f));
      words_.f = f;
      return;
    }
    case 'S':
      if (events_) {
        spindleEvent(value(), st.ext);
        return;
      }
      value();
      return;
    case 'H':
      value();
      return;  // spindle speed, auxiliary function: no path effect
    case 'M':
    case 'T':
    case 'D':
    case 'L':
    case 'P':
      programWord(c, st);
      return;
    case 'N':
      raise(AlarmNumber::SyntaxError, "block number N only at the start of a block");
    default:
      if (axisWord(st)) return;  // A, B, C, U, V, W, ... (axis_words.cpp)
      if (axes_.configured() && std::string_view("ABCUVW").find(c) != std::string_view::npos)
        raise(AlarmNumber::NameNotDefined,
              fmt::format("name {} not defined: no axis {} in this channel (MD20060/MD20080)", name,
                          name));
      notModelled(fmt::format("address {}", name),
                  "only the geometry axes X, Y, Z move; other axes and addresses are not modelled");
  }
}

// M, T, D, L and P: what the block switches, selects or calls.
NCOFFSET_INLINE_STEP void Interpreter::programWord(char c, const Stmt& st) {
  auto value = [&]() { return wordValue(st); };
  switch (c) {
    case 'M': {
      double m = value();
      if (m < 0 || m != std::floor(m))
        raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: M{}", m));
      // M6 (MD22560) changes the tool for the master spindle (MD20090 = 1).
      if (m == data_.get(md_change_m_) && st.ext <= 1) words_.tool_change = true;
      if (events_) mFunctionEvent(m, st.ext);
      if (st.ext > 0) return;  // M2=3: function of spindle 2
      if (m == 2 || m == 30)
        words_.end_program = true;
      else if (m == 17)
        words_.end_subprogram = true;
      return;  // other M functions (M0, M1, M3..M5, M6, M8, ...) do not move the path
    }
    case 'T': {
      if (st.ext >= 0) raise(AlarmNumber::SyntaxError, "T takes no address extension");
      if (!st.literal) {
        Value v = eval_.eval(block_, st.expr);
        if (v.isText()) {
          words_.tool = tools_.resolveName(v.str);
          return;
        }
      }
      double t = value();
      if (t < 0 || t != std::floor(t) || t > tool::kMaxTool)
        raise(AlarmNumber::ValueRange,
              fmt::format("value range exceeded: T{} (T numbers are whole, 0..{})", t,
                          tool::kMaxTool));
      words_.tool = static_cast<int>(t);
      return;
    }
    case 'D': {
      if (st.ext >= 0) raise(AlarmNumber::SyntaxError, "D takes no address extension");
      double d = value();
      if (d < 0 || d != std::floor(d) || d > tools_.dNumbers().max_d)  // MD18105
        raise(AlarmNumber::ValueRange,
              fmt::format("value range exceeded: D{} (D numbers are whole, 0..{})", d,
                          tools_.dNumbers().max_d));
      words_.edge = static_cast<int>(d);
      return;
    }
    case 'L': {
      double l = value();
      if (l < 0 || l != std::floor(l) || l > 999999999 || st.has_equals)
        raise(AlarmNumber::SyntaxError, "L must be followed by a program number (0..999999999)");
      if (!words_.call.empty())
        raise(AlarmNumber::NameNotDefined,
              fmt::format("name {} not defined (a block calls one subprogram; L{} follows)",
                          words_.call, static_cast<long long>(l)));
      call_name_ = fmt::format("L{}", static_cast<long long>(l));
      words_.call = call_name_;
      return;
    }
    case 'P': {
      double p = value();
      if (p != std::floor(p))
        raise(AlarmNumber::ValueRange,
              fmt::format("value range exceeded: P{} (pass count 1..9999)", p));
      words_.repeat = static_cast<long long>(std::fmax(-1, std::fmin(p, 1e9)));
      return;
    }
    default:
      return;
  }
}

// An address of more than one letter: CR=, AR=, RPL=, TURN=, DISC=, OFFN=, the SAR words, SPOS.
NCOFFSET_INLINE_STEP void Interpreter::extendedWord(const Stmt& st) {
  std::string_view name = st.name;
  auto value = [&]() { return wordValue(st); };
  if (name == "CR") {
    words_.cr = value();
    return;
  }
  if (name == "AR") {
    words_.ar = value();
    return;
  }
  if (name == "RPL") {
    words_.rpl = value();
    return;
  }
  if (name == "TURN") {
    double t = value();
    if (t < 0 || t > 999 || t != std::floor(t))
      raise(AlarmNumber::CircleTurns,
            fmt::format("wrong number of revolutions in circle programming: TURN={}", t));
    words_.turn = static_cast<int>(t);
    return;
  }
  if (name == "DISC") {
    double d = value();
    if (d < 0 || d > 100 || d != std::floor(d))
      raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: DISC={} (0..100)", d));
    modal_.disc = std::fmin(d, data_.get(md_max_disc_));
    return;
  }
  if (name == "OFFN") {
    // A contour offset (PM-NC "tool radius compensation"): within the number range of lengths.
    const double v = toMm(value());
    if (!(std::fabs(v) <= 1e9))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: OFFN={} (|OFFN| <= 1e9 mm)", v));
    modal_.offn = v;
    return;
  }
  if (name == "DISR" || name == "DISCL" || name == "DISRP" || name == "FAD") {
    sarWord(st);
    return;
  }
  if (name == "SPOS" || name == "SPOSA") {  // spindle positioning
    value();
    return;
  }
  if (axisWord(st)) return;  // X1=, A1=, ... (axis_words.cpp)
  if (st.mode > AxisMode::IC)
    raise(AlarmNumber::SyntaxError,
          fmt::format("DAC/DIC/RAC/RIC/DC/ACP/ACN only with an axis, not with {}", name));
  if (turningWord(st)) return;
  if (name == "TCARR") {  // orientable toolholder (toolholder_words.cpp)
    toolholderNumber(value());
    return;
  }
  if (contourWord(st)) return;  // CHF=, RND=, ANG=, AP=, RP=, I1=, ... (contour_definition.cpp)
  // The other extended addresses: (b) accepted, (c) alarm 99010 (docs/names.md).
  if (predefinedAssign(name, Value::real(value()))) return;
  notModelled(fmt::format("address {}=", name),
              "this address changes the path and is not modelled");
}

// DISR=, DISCL=, DISRP=, FAD=: the distances and the feed of a smooth approach (W1 2.4.4).
void Interpreter::sarWord(const Stmt& st) {
  std::string_view name = st.name;
  auto value = [&]() { return wordValue(st); };
  // SAR distances: within the machine's number range like every position.
  auto distance = [&]() {
    double v = toMm(value());
    if (!std::isfinite(v) || std::fabs(v) > 1e9)
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: {}={} (|value| <= 1e9 mm)", name, v));
    return v;
  };
  if (name == "DISR") {
    words_.disr = distance();
    return;
  }
  if (name == "DISCL" || name == "DISRP") {
    if (st.mode == AxisMode::IC)
      raise(AlarmNumber::SyntaxError,
            fmt::format("{}=IC(..) is not allowed (incremental is the default)", name));
    (name == "DISCL" ? words_.discl : words_.disrp) = distance();
    (name == "DISCL" ? words_.discl_ac : words_.disrp_ac) = st.mode == AxisMode::AC;
    return;
  }
  if (name == "FAD") {
    // FAD=PM(..) linear feed, FAD=PR(..) revolutional feed (PM-NC p272): the value is the feed
    // of the slow infeed either way (the CSV carries no feed type).
    if (!st.literal) {
      const lang::Node& v = block_.node(st.expr);
      if (v.kind == lang::NodeKind::Call && (v.text == "PM" || v.text == "PR")) {
        if (v.b != 1) raise(AlarmNumber::SyntaxError, "PM/PR take one value");
        words_.fad = eval_.number(block_, block_.arg(v, 0));
        if (!std::isfinite(*words_.fad) || *words_.fad < 0 || *words_.fad > 1e9)
          raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: FAD={}", *words_.fad));
        return;
      }
    }
    words_.fad = value();
    if (!std::isfinite(*words_.fad) || *words_.fad < 0 || *words_.fad > 1e9)
      raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: FAD={}", *words_.fad));
    return;
  }
}

}  // namespace ncoffset::interp
