// G functions by group and the named words of a block (NORM/KONT, CDON/CDOF, SUPA, frame
// commands, STOPRE, what has no path effect and what is not modelled). PM-NC "List of G
// functions", W1 2.4.
#include <fmt/format.h>

#include <cmath>

#include "core/inline_step.hpp"
#include "core/not_modelled.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using core::notModelled;
using lang::Stmt;
using lang::Value;

namespace {

bool isOneOf(std::string_view w, std::initializer_list<std::string_view> list) {
  for (auto x : list)
    if (x == w) return true;
  return false;
}

}  // namespace

// Groups 1 (motion), 2 (G4), 6 (plane), 8 (settable frames), 10/11 (exact stop), 3 (G25/G26,
// G53/G153, G58/G59).
NCOFFSET_INLINE_STEP bool Interpreter::gMotionPlaneFrame(int g) {
  switch (g) {
    case 0:
      modal_.motion = Motion::G0;
      words_.motion_word = true;
      return true;
    case 1:
      modal_.motion = Motion::G1;
      words_.motion_word = true;
      return true;
    case 2:
      modal_.motion = Motion::G2;
      words_.motion_word = true;
      return true;
    case 3:
      modal_.motion = Motion::G3;
      words_.motion_word = true;
      return true;
    case 4:
      words_.dwell = true;
      return true;
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
    case 290:
      return true;  // exact stop / continuous path: no path change
    case 63:
      words_.tapping_chuck = true;  // G63: the block's G1 line is a tapping line
      return true;
    case 17:
    case 18:
    case 19: {
      Plane p = g == 17 ? Plane::G17 : g == 18 ? Plane::G18 : Plane::G19;
      if (p != modal_.plane && modal_.trc != core::TrcMode::Off)
        raise(AlarmNumber::TrcPlaneChange,
              "change of compensation plane not possible while tool radius compensation is active");
      modal_.plane = p;
      return true;
    }
    case 25:
    case 26:
      words_.axial_offset = g;
      return true;  // limits: axis values are not motion
    case 53:
    case 153:
      words_.suppress_frames = g;
      return true;
    case 54:
    case 55:
    case 56:
    case 57:
      modal_.frame_select = g;
      words_.frame_select = true;
      return true;
    case 500:
      modal_.frame_select = 500;
      words_.frame_select = true;
      return true;
    case 58:
    case 59:
      words_.axial_offset = g;
      return true;
    default:
      return threadMotionWord(g);  // G33, G34, G35, G331, G332 (threads.cpp)
  }
}
// Groups 7 (G40-G42), 17/18 (G450/G451), 43/44 (G140-G143, G340/G341), 48 (G460-G462) and the
// SAR G codes G147..G348 (W1 2.4).
NCOFFSET_INLINE_STEP bool Interpreter::gCompensation(int g) {
  switch (g) {
    case 40:
      modal_.trc = core::TrcMode::Off;
      return true;
    case 41:
      modal_.trc = core::TrcMode::Left;
      return true;
    case 42:
      modal_.trc = core::TrcMode::Right;
      return true;
    case 140:
      modal_.sar_side = core::SarSide::G140;
      return true;
    case 141:
      modal_.sar_side = core::SarSide::G141;
      return true;
    case 142:
      modal_.sar_side = core::SarSide::G142;
      return true;
    case 143:
      modal_.sar_side = core::SarSide::G143;
      return true;
    case 340:
      modal_.sar_infeed = core::SarInfeed::G340;
      return true;
    case 341:
      modal_.sar_infeed = core::SarInfeed::G341;
      return true;
    case 450:
      modal_.corner = CornerMode::TransitionCircle;
      return true;
    case 451:
      modal_.corner = CornerMode::Intersection;
      return true;
    case 460:
      modal_.trc_strategy = core::TrcStrategy::G460;
      return true;
    case 461:
      modal_.trc_strategy = core::TrcStrategy::G461;
      return true;
    case 462:
      modal_.trc_strategy = core::TrcStrategy::G462;
      return true;
    case 147:
      setSar(core::SarKind::Line147);
      return true;
    case 148:
      setSar(core::SarKind::Line148);
      return true;
    case 247:
      setSar(core::SarKind::Quadrant247);
      return true;
    case 248:
      setSar(core::SarKind::Quadrant248);
      return true;
    case 347:
      setSar(core::SarKind::Semicircle347);
      return true;
    case 348:
      setSar(core::SarKind::Semicircle348);
      return true;
    default:
      return false;
  }
}
// Groups 13 (G70/G71/G700/G710), 14 (G90/G91) and 15 (G93-G97).
NCOFFSET_INLINE_STEP bool Interpreter::gUnitsAndFeed(int g) {
  switch (g) {
    case 70:
      modal_.units = Units::G70;
      return true;
    case 71:
      modal_.units = Units::G71;
      return true;
    case 700:
      modal_.units = Units::G700;
      return true;
    case 710:
      modal_.units = Units::G710;
      return true;
    case 90:
      modal_.incremental = false;
      return true;
    case 91:
      modal_.incremental = true;
      return true;
    case 93:
      setFeedType(FeedType::G93);
      return true;
    case 94:
      setFeedType(FeedType::G94);
      return true;
    case 95:
      setFeedType(FeedType::G95);
      return true;
    case 96:  // constant cutting speed (S in m/min, LIMS= its speed limit): feed per revolution
      setFeedType(FeedType::G96);
      return true;
    case 97:
      setFeedType(FeedType::G97);
      return true;
    case 961:  // constant cutting speed with a linear feed (mm/min)
      setFeedType(FeedType::G961);
      return true;
    case 971:
      setFeedType(FeedType::G971);
      return true;
    // The "frozen" forms (PM-NC "Feedrate for G96/G961/G97/G971"): their feed units; G962 and
    // G972 keep the unit that is active (linear or per revolution).
    case 942:
      setFeedType(FeedType::G94);
      return true;
    case 952:
    case 973:
      setFeedType(FeedType::G95);
      return true;
    case 962:
    case 972:
      return true;
    default:
      return false;
  }
}
// G codes of the control that change the path and are not modelled (alarm 99010).
void Interpreter::gNotModelled(int g) {
  switch (g) {
    case 74:
    case 75:
      notModelled(fmt::format("G{}", g), "reference point / fixed point approach");
    case 291:
      notModelled("G291", "ISO dialect mode");
    case 931:
      notModelled("G931", "feed given as the travel time of the block");
    default:
      return;
  }
}

void Interpreter::gCode(int g) {
  if (gMotionPlaneFrame(g) || gCompensation(g) || gUnitsAndFeed(g)) return;
  if (g == 62 || g == 621) return;  // corner deceleration (group 57): speed, not path
  if (g >= 110 && g <= 112) {
    poleWord(g);  // the pole of polar coordinates (contour_definition.cpp)
    return;
  }
  gNotModelled(g);
  if (g >= 505 && g <= 599) {
    modal_.frame_select = g;
    words_.frame_select = true;
    return;
  }
  raise(AlarmNumber::UnknownGCode, fmt::format("G function G{} is unknown", g));
}

void Interpreter::setSar(core::SarKind kind) {
  if (words_.sar != core::SarKind::None)
    raise(AlarmNumber::SarProgrammedTwice, "SAR programmed several times in one block");
  words_.sar = kind;
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
  if (w == "CUT2D" || w == "CUT2DF" || w == "CUT2DD" || w == "CUT2DFD") {  // group 22
    modal_.cut2d_frame = w == "CUT2DF" || w == "CUT2DFD";
    modal_.cut2d_differential = w == "CUT2DD" || w == "CUT2DFD";
    tools_.setDifferential(modal_.cut2d_differential);
    return;
  }
  if (w == "CUTCONON" || w == "CUTCONOF") {  // group 40: keep radius compensation constant
    modal_.cut_constant = w == "CUTCONON";
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
      raise(AlarmNumber::SyntaxError, "each frame statement must stand in its own block");
    words_.frame_command = w;
    return;
  }
  if (diameterWord(w)) return;
  if (w == "STOPRE") {
    motion_.preprocessorStop(data_.get("$SC_STOP_CUTCOM_STOPRE") != 0);
    return;
  }
  if (isOneOf(w, {"STOPRE",  "BRISK",  "SOFT",    "DRIVE",   "FFWON",  "FFWOF",  "CFC",    "CFTCP",
                  "CFIN",    "TOWSTD", "TOWMCS",  "TOWWCS",  "TOWBCS", "TOWTCS", "TOWKCS", "SETMS",
                  "TRAFOOF", "SAVE",   "DISPLOF", "DISPLON", "WAITM",  "G64"}))
    return;  // no effect on the path
  if (w == "CIP" || w == "CT") {
    circleFormWord(w == "CIP" ? CircleForm::Cip : CircleForm::Ct);
    return;
  }
  if (isOneOf(w, {"ASPLINE", "BSPLINE", "CSPLINE", "POLY", "TRAORI", "TRANSMIT", "TRACYL", "TRAANG",
                  "ROTS", "AROTS", "CROTS", "MOVT", "INVCW", "INVCCW", "OEMIPO1", "OEMIPO2",
                  "EXTCALL"}))
    notModelled(w, "this function changes the path and ncoffset does not model it");
  if (toolholderNamedWord(w)) return;  // TCOABS, TCOFR.., PAROT, TOROT, TOFRAME..
  if (predefinedWord(w)) return;       // docs/names.md: (a)/(b) accepted, (c) alarm 99010
  if (!words_.call.empty())  // every word is read: a second call would drop the first name
    raise(AlarmNumber::NameNotDefined,
          fmt::format("name {} not defined (a block calls one subprogram; {} follows)", words_.call,
                      w));
  words_.call = w;
}

}  // namespace ncoffset::interp
