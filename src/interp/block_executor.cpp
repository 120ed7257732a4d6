// Executing the words of a block: G groups, axes, feed, M functions, frames and the motion
// (PM-NC "Fundamentals": G0/G1/G2/G3, G17..G19, G90/G91, G70/G71/G700/G710, G53/G153/SUPA,
// G500/G54..G57/G505..G599, TRANS/ROT/SCALE/MIRROR and their A forms).
#include <fmt/format.h>

#include <cmath>

#include "geom/arc.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

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

[[noreturn]] void notModelled(std::string_view what, std::string_view why) {
  raise(alarm_no::kNotModelled, fmt::format("{} is not modelled by ncoffset: {}", what, why));
}

bool isOneOf(std::string_view w, std::initializer_list<std::string_view> list) {
  for (auto x : list)
    if (x == w) return true;
  return false;
}

}  // namespace

double Interpreter::toMm(double v) const {
  return modal_.units == Units::G70 || modal_.units == Units::G700 ? v * 25.4 : v;
}

void Interpreter::collectWord(const Stmt& st) {
  std::string_view name = st.name;
  auto value = [&]() { return st.literal ? st.literal_value : eval_.number(block_, st.expr); };
  if (st.has_equals && st.mode == AxisMode::Default && findVariable(name)) {
    // A user variable with a one-letter name (DEF REAL V): V=2 is an assignment.
    lang::Node target;
    target.kind = lang::NodeKind::Name;
    target.text = name;
    store(target, st.literal ? (st.literal_int ? lang::Value::integer(st.literal_value)
                                               : lang::Value::real(st.literal_value))
                             : eval_.eval(block_, st.expr));
    return;
  }
  if (name.size() == 1) {
    char c = name[0];
    if (int i = axisIndex(c); i >= 0) {
      if (words_.axis[i])
        raise(alarm_no::kAddressTwice, fmt::format("address {} programmed too often", name));
      words_.axis[i] = true;
      words_.axis_value[i] = value();
      words_.axis_mode[i] = st.mode;
      return;
    }
    if (st.mode != AxisMode::Default && c != 'I' && c != 'J' && c != 'K')
      raise(alarm_no::kSyntaxError, fmt::format("AC/IC is not allowed with address {}", name));
    switch (c) {
      case 'I':
      case 'J':
      case 'K': {
        int i = c - 'I';
        if (words_.centre[i])
          raise(alarm_no::kAddressTwice, fmt::format("address {} programmed too often", name));
        words_.centre[i] = true;
        words_.centre_value[i] = value();
        words_.centre_mode[i] = st.mode;
        return;
      }
      case 'G': {
        double g = value();
        if (!(g >= 0 && g <= 9999) || static_cast<int>(g) != g)  // also NaN
          raise(alarm_no::kUnknownGCode, fmt::format("G function G{} is unknown", g));
        gCode(static_cast<int>(g));
        return;
      }
      case 'F': {
        double f = value();
        if (f < 0 || f > 1e9)
          raise(alarm_no::kValueRange, fmt::format("value range exceeded: F{}", f));
        words_.f = f;
        return;
      }
      case 'S':
      case 'H':
        value();
        return;  // spindle speed, auxiliary function: no path effect
      case 'M': {
        double m = value();
        if (m < 0 || m != std::floor(m))
          raise(alarm_no::kValueRange, fmt::format("value range exceeded: M{}", m));
        // M6 (MD22560) changes the tool for the master spindle (MD20090 = 1).
        if (m == data_.get(md_change_m_) && st.ext <= 1) words_.tool_change = true;
        if (st.ext > 0) return;  // M2=3: function of spindle 2
        if (m == 2 || m == 30)
          words_.end_program = true;
        else if (m == 17)
          words_.end_subprogram = true;
        return;  // other M functions (M0, M1, M3..M5, M6, M8, ...) do not move the path
      }
      case 'T': {
        if (st.ext >= 0) raise(alarm_no::kSyntaxError, "T takes no address extension");
        if (!st.literal) {
          Value v = eval_.eval(block_, st.expr);
          if (v.isText()) {
            words_.tool = resolveToolName(v.str);
            return;
          }
        }
        double t = value();
        if (t < 0 || t != std::floor(t) || t > tool::kMaxTool)
          raise(alarm_no::kValueRange,
                fmt::format("value range exceeded: T{} (T numbers are whole, 0..{})", t,
                            tool::kMaxTool));
        words_.tool = static_cast<int>(t);
        return;
      }
      case 'D': {
        if (st.ext >= 0) raise(alarm_no::kSyntaxError, "D takes no address extension");
        double d = value();
        if (d < 0 || d != std::floor(d) || d > tool::kMaxEdge)
          raise(alarm_no::kValueRange,
                fmt::format("value range exceeded: D{} (D numbers are whole, 0..{})", d,
                            tool::kMaxEdge));
        words_.edge = static_cast<int>(d);
        return;
      }
      case 'L': {
        double l = value();
        if (l < 0 || l != std::floor(l) || l > 999999999 || st.has_equals)
          raise(alarm_no::kSyntaxError, "L must be followed by a program number (0..999999999)");
        if (!words_.call.empty())
          raise(alarm_no::kNameNotDefined,
                fmt::format("name {} not defined (a block calls one subprogram; L{} follows)",
                            words_.call, static_cast<long long>(l)));
        call_name_ = fmt::format("L{}", static_cast<long long>(l));
        words_.call = call_name_;
        return;
      }
      case 'P': {
        double p = value();
        if (p != std::floor(p))
          raise(alarm_no::kValueRange,
                fmt::format("value range exceeded: P{} (pass count 1..9999)", p));
        words_.repeat = static_cast<long long>(std::fmax(-1, std::fmin(p, 1e9)));
        return;
      }
      case 'N':
        raise(alarm_no::kSyntaxError, "block number N only at the start of a block");
      default:
        notModelled(
            fmt::format("address {}", name),
            "only the geometry axes X, Y, Z move; other axes and addresses are not modelled");
    }
  }
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
      raise(alarm_no::kCircleTurns,
            fmt::format("wrong number of revolutions in circle programming: TURN={}", t));
    words_.turn = static_cast<int>(t);
    return;
  }
  if (name == "DISC") {
    double d = value();
    if (d < 0 || d > 100 || d != std::floor(d))
      raise(alarm_no::kValueRange, fmt::format("value range exceeded: DISC={} (0..100)", d));
    modal_.disc = std::fmin(d, data_.get(md_max_disc_));
    return;
  }
  if (name == "OFFN") {
    modal_.offn = toMm(value());
    return;
  }
  // SAR distances: within the machine's number range like every position.
  auto distance = [&]() {
    double v = toMm(value());
    if (!std::isfinite(v) || std::fabs(v) > 1e9)
      raise(alarm_no::kValueRange,
            fmt::format("value range exceeded: {}={} (|value| <= 1e9 mm)", name, v));
    return v;
  };
  if (name == "DISR") {
    words_.disr = distance();
    return;
  }
  if (name == "DISCL" || name == "DISRP") {
    if (st.mode == AxisMode::IC)
      raise(alarm_no::kSyntaxError,
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
        if (v.b != 1) raise(alarm_no::kSyntaxError, "PM/PR take one value");
        words_.fad = eval_.number(block_, block_.arg(v, 0));
        if (!std::isfinite(*words_.fad) || *words_.fad < 0 || *words_.fad > 1e9)
          raise(alarm_no::kValueRange, fmt::format("value range exceeded: FAD={}", *words_.fad));
        return;
      }
    }
    words_.fad = value();
    if (!std::isfinite(*words_.fad) || *words_.fad < 0 || *words_.fad > 1e9)
      raise(alarm_no::kValueRange, fmt::format("value range exceeded: FAD={}", *words_.fad));
    return;
  }
  if (name == "SPOS" || name == "SPOSA") {
    value();
    return;
  }  // spindle positioning
  notModelled(fmt::format("address {}=", name),
              "this address changes the path and is not modelled");
}

void Interpreter::gCode(int g) {
  switch (g) {
    case 0:
      modal_.motion = Motion::G0;
      words_.motion_word = true;
      return;
    case 1:
      modal_.motion = Motion::G1;
      words_.motion_word = true;
      return;
    case 2:
      modal_.motion = Motion::G2;
      words_.motion_word = true;
      return;
    case 3:
      modal_.motion = Motion::G3;
      words_.motion_word = true;
      return;
    case 4:
      words_.dwell = true;
      return;
    case 9:
    case 60:
    case 64:
    case 641:
    case 642:
    case 643:
    case 644:
    case 645:
    case 601:
    case 602:
    case 603:
    case 63:
    case 290:
      return;  // exact stop / continuous path / tapping with compensating chuck: no path change
    case 17:
    case 18:
    case 19: {
      Plane p = g == 17 ? Plane::G17 : g == 18 ? Plane::G18 : Plane::G19;
      if (p != modal_.plane && modal_.trc != 40)
        raise(10757,
              "change of compensation plane not possible while tool radius compensation is active");
      modal_.plane = p;
      return;
    }
    case 25:
    case 26:
      words_.axial_offset = g;
      return;  // limits: axis values are not motion
    case 40:
    case 41:
    case 42:
      modal_.trc = g;
      return;
    case 53:
    case 153:
      words_.suppress_frames = g;
      return;
    case 54:
    case 55:
    case 56:
    case 57:
      modal_.frame_select = g;
      words_.frame_select = true;
      return;
    case 500:
      modal_.frame_select = 500;
      words_.frame_select = true;
      return;
    case 58:
    case 59:
      words_.axial_offset = g;
      return;
    case 70:
      modal_.units = Units::G70;
      return;
    case 71:
      modal_.units = Units::G71;
      return;
    case 700:
      modal_.units = Units::G700;
      return;
    case 710:
      modal_.units = Units::G710;
      return;
    case 90:
      modal_.incremental = false;
      return;
    case 91:
      modal_.incremental = true;
      return;
    case 93:
      modal_.feed_type = FeedType::G93;
      return;
    case 94:
      modal_.feed_type = FeedType::G94;
      return;
    case 95:
      modal_.feed_type = FeedType::G95;
      return;
    case 96:
      modal_.feed_type = FeedType::G96;
      return;
    case 97:
      modal_.feed_type = FeedType::G97;
      return;
    case 140:
    case 141:
    case 142:
    case 143:
      modal_.sar_side = g;
      return;
    case 340:
    case 341:
      modal_.sar_plane = g;
      return;
    case 450:
      modal_.corner = CornerMode::TransitionCircle;
      return;
    case 451:
      modal_.corner = CornerMode::Intersection;
      return;
    case 460:
    case 461:
    case 462:
      modal_.trc_strategy = g;
      return;
    case 147:
    case 148:
    case 247:
    case 248:
    case 347:
    case 348:
      if (words_.sar) raise(10743, "SAR programmed several times in one block");
      words_.sar = g;
      return;
    case 33:
    case 34:
    case 35:
    case 331:
    case 332:
      notModelled(fmt::format("G{}", g), "thread cutting / tapping interpolation");
    case 74:
    case 75:
      notModelled(fmt::format("G{}", g), "reference point / fixed point approach");
    case 110:
    case 111:
    case 112:
      notModelled(fmt::format("G{}", g), "polar coordinates");
    case 291:
      notModelled("G291", "ISO dialect mode");
    default:
      break;
  }
  if (g >= 505 && g <= 599) {
    modal_.frame_select = g;
    words_.frame_select = true;
    return;
  }
  raise(alarm_no::kUnknownGCode, fmt::format("G function G{} is unknown", g));
}

void Interpreter::namedWord(const Stmt& st) {
  std::string_view w = st.name;
  if (w == "NORM") {
    modal_.approach = Approach::Norm;
    return;
  }
  if (w == "KONT") {
    modal_.approach = Approach::Kont;
    return;
  }
  if (w == "KONTC") {
    modal_.approach = Approach::KontC;
    return;
  }
  if (w == "KONTT") {
    modal_.approach = Approach::KontT;
    return;
  }
  if (w == "CDON") {
    modal_.collision = CollisionCheck::Cdon;
    return;
  }
  if (w == "CDOF") {
    modal_.collision = CollisionCheck::Cdof;
    return;
  }
  if (w == "CDOF2") {
    modal_.collision = CollisionCheck::Cdof2;
    return;
  }
  if (w == "SUPA") {
    words_.suppress_frames = 1;
    return;
  }
  if (w == "RET") {
    words_.end_subprogram = true;
    return;
  }
  if (isOneOf(w, {"TRANS", "ATRANS", "ROT", "AROT", "SCALE", "ASCALE", "MIRROR", "AMIRROR"})) {
    if (!words_.frame_command.empty())
      raise(alarm_no::kSyntaxError, "each frame statement must stand in its own block");
    words_.frame_command = w;
    return;
  }
  if (w == "STOPRE") {
    sar_.preprocessorStop();
    trc_.preprocessorStop(data_.get("$SC_STOP_CUTCOM_STOPRE") != 0);
    return;
  }
  if (isOneOf(w, {"STOPRE",  "BRISK",  "SOFT",    "DRIVE",   "FFWON",  "FFWOF",  "CFC",    "CFTCP",
                  "CFIN",    "TOWSTD", "TOWMCS",  "TOWWCS",  "TOWBCS", "TOWTCS", "TOWKCS", "DIAMOF",
                  "TRAFOOF", "SAVE",   "DISPLOF", "DISPLON", "WAITM",  "G64"}))
    return;  // no effect on the path
  if (isOneOf(w,
              {"CIP",    "CT",       "ASPLINE", "BSPLINE", "CSPLINE", "POLY",  "DIAMON", "DIAM90",
               "TRAORI", "TRANSMIT", "TRACYL",  "TRAANG",  "ROTS",    "AROTS", "CROTS",  "MOVT",
               "INVCW",  "INVCCW",   "OEMIPO1", "OEMIPO2", "EXTCALL", "CALL",  "PCALL",  "MCALL"}))
    notModelled(w, "this function changes the path and ncoffset does not model it");
  if (!words_.call.empty())  // every word is read: a second call would drop the first name
    raise(alarm_no::kNameNotDefined,
          fmt::format("name {} not defined (a block calls one subprogram; {} follows)", words_.call,
                      w));
  words_.call = w;
}

Vec3 Interpreter::bcsOfWcs(Vec3 wcs) const {
  return act_.apply(wcs);
}

void Interpreter::finishBlock() {
  bool frames_changed = false;
  if (words_.frame_select) {
    int n = modal_.frame_select == 500  ? 0
            : modal_.frame_select < 100 ? modal_.frame_select - 53
                                        : modal_.frame_select - 500;
    iframe_ = uifr_[static_cast<size_t>(n)];
    frames_changed = true;
  }
  bool axes_consumed = false;
  if (!words_.frame_command.empty()) {
    doFrameCommand();
    frames_changed = true;
    axes_consumed = true;
  } else if (words_.axial_offset == 58 || words_.axial_offset == 59) {
    // G58 replaces the coarse, G59 the fine translation of the programmable frame, per axis.
    for (int i = 0; i < 3; ++i) {
      if (!words_.axis[i]) continue;
      (words_.axial_offset == 58 ? pframe_.coarse : pframe_.fine)[i] = toMm(words_.axis_value[i]);
    }
    frames_changed = true;
    axes_consumed = true;
  } else if (words_.axial_offset == 25 || words_.axial_offset == 26) {
    axes_consumed = true;  // G25/G26 axis values are working-area limits, not targets
  }
  if (frames_changed) updateActiveFrame();
  executeToolWords();
  if (words_.rpl && words_.frame_command.empty())
    raise(alarm_no::kSyntaxError, "RPL= only with ROT or AROT");

  feed_before_ = modal_.feed;
  if (words_.f && !words_.dwell)
    modal_.feed = modal_.units == Units::G700 ? *words_.f * 25.4 : *words_.f;
  bool any_axis = words_.axis[0] || words_.axis[1] || words_.axis[2];
  bool circle_words = words_.centre[0] || words_.centre[1] || words_.centre[2] || words_.cr ||
                      words_.ar || words_.turn;
  bool is_arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  if (circle_words && !is_arc)
    raise(alarm_no::kCircleProgramming,
          "circle programming error: I, J, K, CR=, AR= or TURN= without G2/G3");
  // A circle may consist of its centre alone (full circle) or of AR= with the centre.
  block_moved_ = false;
  if (!axes_consumed && (any_axis || (is_arc && circle_words) || words_.sar)) doMotion();
  // A block that reaches the main run without moving (M, S, F, zero-length, ...) between two
  // compensated elements counts against MD20250.
  if (!block_moved_ && sar_.active() && !block_.stmts.empty() &&
      block_.stmts.front().kind == lang::StmtKind::Word)
    sar_.blockWithoutMotion();

  if (words_.end_program || words_.end_subprogram) {
    if (levels_.size() > 1)
      returnFromSubprogram();  // M2/M30 in a subprogram act like M17
    else
      endProgram();
    if (!words_.call.empty())
      raise(alarm_no::kSyntaxError, "program call and program end in one block");
    motion_before_ = modal_.motion;
    return;
  }
  motion_before_ = modal_.motion;
  if (!words_.call.empty()) {
    callSubprogram(words_.call, words_.repeat.value_or(1));
  } else if (words_.repeat) {
    raise(alarm_no::kSyntaxError, "pass count P without a subprogram call");
  }
}

void Interpreter::doMotion() {
  const bool suppress = words_.suppress_frames != 0;
  static const Affine kNoFrame;
  const Affine& frame = suppress ? kNoFrame : act_;
  // Without a frame WCS = BCS: the products below are skipped (the usual case).
  const bool plain = suppress || act_identity_;
  auto toBcs = [&](const Vec3& p) { return plain ? p : frame.apply(p); };
  auto wcsOf = [&](const Vec3& bcs) { return act_identity_ ? bcs : act_inverse_.apply(bcs); };
  // Programming system: the WCS, or the BCS when frames are suppressed (G53/G153/SUPA).
  const Vec3 from = suppress ? bcs_ : wcs_;
  Vec3 target = from;
  for (int i = 0; i < 3; ++i) {
    if (!words_.axis[i]) continue;
    double v = toMm(words_.axis_value[i]);
    bool absolute = words_.axis_mode[i] == AxisMode::AC ||
                    (words_.axis_mode[i] == AxisMode::Default && !modal_.incremental);
    target[i] = absolute ? v : from[i] + v;
    if (!std::isfinite(target[i]) || std::fabs(target[i]) > 1e9)
      raise(alarm_no::kValueRange,
            fmt::format("value range exceeded: position {} of axis {}", target[i], "XYZ"[i]));
  }
  // The interpreter's one motion block, reused: every member is set below (no zeroing of the
  // whole block for every motion). Later stages copy what they keep.
  place::MotionBlock& m = motion_;
  m.motion = modal_.motion;
  // A SAR block is a linear block: its own G0/G1 (G2/G3 modal count as G1) moves P2 -> P0.
  if (words_.sar && (m.motion == Motion::G2 || m.motion == Motion::G3)) m.motion = Motion::G1;
  m.frame = frame;
  m.frame_serial = suppress ? 0 : act_serial_;
  m.frame_identity = plain;
  m.line = line_;
  m.file = file_;
  m.start = suppress ? bcs_ : wcsOf(bcs_);
  m.end = target;
  if (m.motion != Motion::G0) {
    if (modal_.feed <= 0)
      raise(alarm_no::kFeedNotProgrammed, "no feedrate programmed (F) for G1/G2/G3");
    m.feed = modal_.feed;
    m.has_feed = true;
  } else {
    m.feed = 0;
    m.has_feed = false;
  }
  m.sar = nullptr;
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    PlaneAxes pa = planeAxes(modal_.plane);
    if (words_.centre[pa.applicate])
      raise(alarm_no::kCircleProgramming,
            fmt::format("circle programming error: {} is not an interpolation parameter in the "
                        "active plane",
                        "IJK"[pa.applicate]));
    const Mat3& l = frame.linear;
    Vec3 ea, eo;
    ea[pa.abscissa] = 1;
    eo[pa.ordinate] = 1;
    if (!plain && std::fabs(norm(l * ea) - norm(l * eo)) > 1e-9)
      raise(alarm_no::kFrameNotAffine,
            "a circle under different scale factors of the plane axes is an ellipse, which is not "
            "modelled");
    geom::ArcRequest req;
    req.start = {from[pa.abscissa], from[pa.ordinate]};
    req.ccw = m.motion == Motion::G3;
    req.tol_const = data_.get(md_circle_const_);
    req.tol_factor = data_.get(md_circle_factor_);
    if (words_.axis[pa.abscissa] || words_.axis[pa.ordinate])
      req.end = geom::Vec2{target[pa.abscissa], target[pa.ordinate]};
    if (words_.centre[pa.abscissa] || words_.centre[pa.ordinate]) {
      geom::Vec2 c;
      int axes[2] = {pa.abscissa, pa.ordinate};
      double* out[2] = {&c.a, &c.o};
      for (int k = 0; k < 2; ++k) {
        int ax = axes[k];
        double v = words_.centre[ax] ? toMm(words_.centre_value[ax]) : 0;
        // I, J, K are incremental from the start point unless written =AC(..).
        *out[k] = words_.centre_mode[ax] == AxisMode::AC ? v : from[ax] + v;
      }
      req.centre = c;
    }
    if (words_.cr) req.cr = toMm(*words_.cr);
    if (words_.ar) req.ar = *words_.ar;
    geom::ArcSolution sol = geom::solveArc(req);
    target[pa.abscissa] = sol.end.a;
    target[pa.ordinate] = sol.end.o;
    m.end = target;
    m.centre = from;
    m.centre[pa.abscissa] = sol.centre.a;
    m.centre[pa.ordinate] = sol.centre.o;
    m.applicate = pa.applicate;
    m.turns = words_.turn.value_or(0);
  } else {
    m.centre = {};
    m.applicate = 2;
    m.turns = 0;
    // Tool length: each BCS axis takes up the length vector with the first linear block that
    // moves it after the selection (W1 2.1, spec §2.6).
    Vec3 full = toolOffset();
    Vec3 before = applied_offset_;
    if (plain) {
      for (int i = 0; i < 3; ++i)
        if (words_.axis[i]) applied_offset_[i] = full[i];
    } else {
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
          if (words_.axis[i] &&
              std::fabs(frame.linear.m[static_cast<size_t>(k)][static_cast<size_t>(i)]) > 1e-12)
            applied_offset_[k] = full[k];
    }
    Vec3 moved = (toBcs(target) + applied_offset_) - (bcs_ + before);
    if (std::fabs(moved.x) < 1e-12 && std::fabs(moved.y) < 1e-12 && std::fabs(moved.z) < 1e-12 &&
        !words_.sar) {
      wcs_ = suppress ? wcsOf(bcs_) : target;
      return;  // zero-length block: no segment
    }
  }
  m.tool_offset = applied_offset_;
  m.plane = modal_.plane;
  m.trc.mode = modal_.trc;
  m.trc.radius = modal_.offn + (edge_.valid ? edge_.radius : 0.0);
  m.trc.approach = modal_.approach;
  m.trc.corner = modal_.corner;
  m.trc.collision = modal_.collision;
  m.trc.disc = modal_.disc;
  m.trc.strategy = modal_.trc_strategy;
  m.trc.corner_limit = data_.get(md_corner_limit_);
  m.trc.curve_insert_limit = data_.get(md_insert_limit_);
  m.trc.max_dummy_blocks = static_cast<int>(data_.get(md_dummy_blocks_));
  m.trc.check_blocks = static_cast<int>(data_.get(md_check_blocks_));
  // Computed geometry must stay finite and within the machine's number range: a frame with a
  // huge scale or a circle with a huge radius ends here, never as NaN or 1e300 in the output.
  // The end point, and a circle's centre (a line has none).
  const Vec3 checks[] = {toBcs(m.end) + applied_offset_, toBcs(m.centre)};
  const int n_checks = m.motion == Motion::G2 || m.motion == Motion::G3 ? 2 : 1;
  for (int c = 0; c < n_checks; ++c)
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = checks[c];
      if (std::fabs(p[i]) <= 1e9) continue;  // the usual case: one comparison (false for NaN)
      if (!std::isfinite(p[i]))
        raise(alarm_no::kArithmetic,
              "arithmetic error in part program: position is not a finite number");
      raise(alarm_no::kValueRange,
            fmt::format("value range exceeded: position {} of axis {} beyond 1e9 mm", p[i],
                        "XYZ"[i]));
    }
  block_moved_ = true;
  if (words_.sar) {
    sar_request_ = SarRequest{};
    SarRequest& q = sar_request_;
    m.sar = &q;
    q.type = words_.sar;
    q.side = modal_.sar_side;
    q.space = modal_.sar_plane;
    q.has_disr = words_.disr.has_value();
    q.disr = words_.disr.value_or(0);
    q.has_discl = words_.discl.has_value();
    q.discl = words_.discl.value_or(0);
    q.discl_ac = words_.discl_ac;
    q.has_disrp = words_.disrp.has_value();
    q.disrp = words_.disrp.value_or(0);
    q.disrp_ac = words_.disrp_ac;
    q.has_fad = words_.fad.has_value();
    q.fad = words_.fad.value_or(0);
    PlaneAxes pa = planeAxes(modal_.plane);
    q.plane_axis = words_.axis[pa.abscissa] || words_.axis[pa.ordinate];
    q.any_axis = q.plane_axis || words_.axis[pa.applicate];
    q.f_programmed = words_.f.has_value();
    q.feed_value = modal_.feed;
    q.feed_before = feed_before_;
    q.motion_before = motion_before_ == Motion::G0 ? 0 : 1;
    sar_.setMaxDummyBlocks(static_cast<int>(data_.get(md_sar_dummy_blocks_)));
  } else if (words_.disr || words_.discl || words_.disrp || words_.fad) {
    raise(alarm_no::kSyntaxError, "DISR, DISCL, DISRP and FAD only in a SAR block (G147..G348)");
  }
  sar_.motion(m);
  if (auto end = sar_.takeEndOverride()) target = *end;  // implicit retraction end point
  bcs_ = toBcs(target);
  wcs_ = suppress ? wcsOf(bcs_) : target;
}

void Interpreter::doFrameCommand() {
  const std::string_view cmd = words_.frame_command;
  bool any = words_.axis[0] || words_.axis[1] || words_.axis[2] || words_.rpl;
  Vec3 v;
  for (int i = 0; i < 3; ++i)
    if (words_.axis[i]) v[i] = words_.axis_value[i];
  if (words_.rpl && cmd != "ROT" && cmd != "AROT")
    raise(alarm_no::kSyntaxError, "RPL= only with ROT or AROT");
  if (cmd == "TRANS" || cmd == "ATRANS") {
    Vec3 t{toMm(v.x), toMm(v.y), toMm(v.z)};
    if (cmd == "TRANS") {
      pframe_ = Frame();
      pframe_.coarse = t;
    } else {
      pframe_.addTranslation(t);
    }
    return;
  }
  if (cmd == "ROT" || cmd == "AROT") {
    for (double a : {v.x, v.y, v.z, words_.rpl.value_or(0.0)})
      if (!(std::fabs(a) <= 1e6))
        raise(alarm_no::kValueRange, fmt::format("value range exceeded: rotation angle {}", a));
    Mat3 r;
    if (words_.rpl) {
      if (words_.axis[0] || words_.axis[1] || words_.axis[2])
        raise(alarm_no::kSyntaxError, "ROT RPL= cannot be combined with axis angles");
      r = rotationAbout(planeAxes(modal_.plane).applicate, *words_.rpl);
    } else {
      r = rpyMatrix(v);
    }
    if (cmd == "ROT") {
      pframe_ = Frame();
      if (any) pframe_.rotation = rpyAngles(r);
    } else {
      pframe_.addRotation(r);
    }
    return;
  }
  if (cmd == "SCALE" || cmd == "ASCALE") {
    Vec3 s{1, 1, 1};
    for (int i = 0; i < 3; ++i) {
      if (!words_.axis[i]) continue;
      if (std::fabs(v[i]) < 1e-12 || !(std::fabs(v[i]) <= 1e6))
        raise(alarm_no::kValueRange,
              fmt::format("value range exceeded: scale factor {} of {}", v[i], "XYZ"[i]));
      s[i] = v[i];
    }
    if (cmd == "SCALE") {
      pframe_ = Frame();
      pframe_.scale = s;
    } else {
      pframe_.addScale(s);
    }
    return;
  }
  // MIRROR / AMIRROR: the value is arbitrary (write 0); MD10610 = 0: about the programmed axis.
  if (cmd == "MIRROR") pframe_ = Frame();
  for (int i = 0; i < 3; ++i)
    if (words_.axis[i]) pframe_.addMirror(i);
}

void Interpreter::updateActiveFrame() {
  act_ = ncoffset::chain(iframe_, pframe_).affine();
  act_inverse_ = act_.inverse();
  act_identity_ = act_.isIdentity();
  ++act_serial_;
}

}  // namespace ncoffset::interp
