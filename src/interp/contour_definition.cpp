// Contour definitions (PM-NC 12/2019 2.9.9 "Contour definitions", "Chamfer, rounding"), polar
// coordinates (2.9.3 "G110, G111, G112", "AP, RP") and the circle forms CIP (through an
// intermediate point) and CT (tangential): what they make of a block's words before the motion
// builder takes it. docs/contour-definitions.md.
#include <fmt/format.h>

#include <cmath>

#include "core/not_modelled.hpp"
#include "geom/contour.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::AxisMode;
using lang::Stmt;

// CHF=, CHR=, RND=, RNDM=, FRC=, FRCM=, ANG=, AP=, RP=, I1=, J1=, K1=. False for other names.
bool Interpreter::contourWord(const Stmt& st) {
  const std::string_view n = st.name;
  using Kind = CornerRequest::Kind;
  const bool corner = n == "CHF" || n == "CHR" || n == "RND";
  if (!corner && n != "RNDM" && n != "FRC" && n != "FRCM" && n != "ANG" && n != "AP" && n != "RP" &&
      n != "I1" && n != "J1" && n != "K1")
    return false;
  if (!words_.contour) {
    contour_words_ = ContourWords{};
    words_.contour = true;
  }
  ContourWords& cw = contour_words_;
  const double v = st.literal ? st.literal_value : eval_.number(block_, st.expr);
  if (!std::isfinite(v) || std::fabs(v) > 1e9)
    raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {}={}", n, v));
  if (n[0] == 'I' || n[0] == 'J' || n[0] == 'K') {
    const int i = n[0] - 'I';
    cw.inter[i] = true;
    cw.inter_value[i] = v;
    cw.inter_mode[i] = st.mode;
    return true;
  }
  if (n == "AP" || n == "RP") {
    (n == "AP" ? cw.ap : cw.rp) = n == "AP" ? v : toMm(v);
    (n == "AP" ? cw.ap_mode : cw.rp_mode) = st.mode;
    return true;
  }
  if (n == "ANG") {
    cw.ang = v;
    return true;
  }
  if (v < 0)
    raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {}={} (>= 0)", n, v));
  if (corner) {
    // PM-NC "Chamfer, rounding": with RND= and a chamfer in one block, only the rounding is
    // inserted, whatever the order.
    const Kind k = n == "RND" ? Kind::Rnd : n == "CHR" ? Kind::Chr : Kind::Chf;
    if (cw.corner != Kind::Rnd) {
      cw.corner = k;
      cw.corner_value = toMm(v);
    }
    return true;
  }
  if (n == "RNDM")
    cw.rndm = toMm(v);
  else  // FRC/FRCM: a feed as F (G700: inch/min)
    (n == "FRC" ? cw.frc : cw.frcm) = modal_.units == Units::G700 ? v * 25.4 : v;
  return true;
}

// CIP / CT (G group 1): the block's circle is computed from the points (contourBlock).
void Interpreter::circleFormWord(CircleForm form) {
  if (!words_.contour) {
    contour_words_ = ContourWords{};
    words_.contour = true;
  }
  contour_words_.circle = form;
  modal_.motion = Motion::G2;  // a circle; its direction comes from the points
  words_.motion_word = true;
}

// G110 / G111 / G112: the block defines the pole (PM-NC 2.9.3.1).
void Interpreter::poleWord(int g) {
  if (!words_.contour) {
    contour_words_ = ContourWords{};
    words_.contour = true;
  }
  contour_words_.pole = g;
}

CornerRequest Interpreter::cornerRequest() const {
  CornerRequest r;
  const ContourWords* cw = words_.contour ? &contour_words_ : nullptr;
  if (cw && cw->corner != CornerRequest::Kind::None && cw->corner_value > 0) {
    r.kind = cw->corner;
    r.value = cw->corner_value;
  } else if (contour_.rndm > 0 && !(cw && cw->corner != CornerRequest::Kind::None)) {
    r.kind = CornerRequest::Kind::Rnd;  // RNDM: every corner (CHF=0/RND=0 in a block: none)
    r.value = contour_.rndm;
  }
  if (cw && cw->frc && *cw->frc > 0) {
    r.has_feed = true;
    r.feed = *cw->frc;
  } else if (contour_.frcm > 0) {
    r.has_feed = true;
    r.feed = contour_.frcm;
  }
  return r;
}

// A block with contour words, or any block while RNDM, CIP/CT or a pending ANG block is active.
// True when the block is done (a pole definition, the first block of a two-angle definition);
// false when the motion builder builds it (with the words this made of it) if `builds`.
bool Interpreter::contourBlock(bool axes_consumed, bool& builds, bool& moved) {
  ContourWords none;
  const ContourWords& cw = words_.contour ? contour_words_ : none;
  if (cw.rndm) contour_.rndm = *cw.rndm;
  if (cw.frcm) contour_.frcm = *cw.frcm;
  if (cw.circle)
    contour_.circle = *cw.circle;
  else if (words_.motion_word)
    contour_.circle = CircleForm::Plain;  // G0..G3 end CIP/CT
  const bool done = [&] {
    if (cw.pole) {
      definePole();
      builds = false;
      return true;
    }
    if (axes_consumed) return false;
    if (cw.ap || cw.rp) {
      polarTarget();
      builds = true;
    }
    if (cw.ang || contour_.pending) return angleLine(builds);
    return false;
  }();
  if (!done && builds) {
    if (contour_.circle != CircleForm::Plain) circleForm();
    if (const CornerRequest r = cornerRequest(); r.kind != CornerRequest::Kind::None)
      motion_.cornerRequest(r);
  }
  if (done && contour_.pending) moved = true;  // held, not a block without motion
  contour_active_ =
      contour_.rndm > 0 || contour_.circle != CircleForm::Plain || contour_.pending.has_value();
  return done;
}

// G110: the pole relative to the last programmed point; G111: to the WCS zero; G112: to the
// last pole. Cartesian (the plane's axes) or polar (AP=, RP=) (PM-NC 2.9.3.1).
void Interpreter::definePole() {
  const ContourWords& cw = contour_words_;
  const PlaneAxes pa = planeAxes(modal_.plane);
  const int g = cw.pole;
  const Vec3 base = g == 110 ? motion_.wcs() : g == 111 ? Vec3{} : contour_.pole;
  Vec3 pole = base;
  if (cw.ap || cw.rp) {
    const double a = cw.ap.value_or(0) * kRadPerDegree, r = cw.rp.value_or(0);
    pole[pa.abscissa] += r * std::cos(a);
    pole[pa.ordinate] += r * std::sin(a);
  }
  for (int ax : {pa.abscissa, pa.ordinate}) {
    if (!words_.axis[ax]) continue;
    if (cw.ap || cw.rp)
      raise(AlarmNumber::SyntaxError, "pole given both with AP=/RP= and with coordinates");
    const double f = g == 111 ? modal_.diam_abs[ax] : modal_.diam_inc[ax];
    pole[ax] = base[ax] + toMm(words_.axis_value[ax]) * f;
  }
  pole[pa.applicate] = 0;
  contour_.pole = pole;
  // PM-NC 2.9.3.2: the polar angle is kept until a new pole is defined or the plane changes.
  contour_.ap = 0;
  contour_.polar_plane = modal_.plane;
}

// AP= / RP= in a G0/G1/G2/G3 block: the end point in the plane from the pole; a circle runs
// about the pole (PM-NC 2.9.3.2).
void Interpreter::polarTarget() {
  const ContourWords& cw = contour_words_;
  const PlaneAxes pa = planeAxes(modal_.plane);
  if (words_.axis[pa.abscissa] || words_.axis[pa.ordinate])
    raise(AlarmNumber::SyntaxError,
          "AP=/RP= and a Cartesian coordinate of the plane in one block: give the end point "
          "one way");
  if (modal_.plane != contour_.polar_plane) {
    contour_.ap = 0;
    contour_.polar_plane = modal_.plane;
  }
  if (cw.ap) contour_.ap = cw.ap_mode == AxisMode::IC ? contour_.ap + *cw.ap : *cw.ap;
  if (cw.rp) contour_.rp = cw.rp_mode == AxisMode::IC ? contour_.rp + *cw.rp : *cw.rp;
  if (contour_.rp < 0)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: polar radius RP={} (>= 0)", contour_.rp));
  const double a = contour_.ap * kRadPerDegree;
  setAbsoluteWord(words_, modal_, pa.abscissa,
                  contour_.pole[pa.abscissa] + contour_.rp * std::cos(a), false);
  setAbsoluteWord(words_, modal_, pa.ordinate,
                  contour_.pole[pa.ordinate] + contour_.rp * std::sin(a), false);
  if (modal_.motion == Motion::G2 || modal_.motion == Motion::G3) {
    if (words_.centre[0] || words_.centre[1] || words_.centre[2] || words_.cr || words_.ar)
      raise(AlarmNumber::CircleProgramming,
            "circle programming error: a circle with AP=/RP= runs about the pole; I, J, K, CR= "
            "and AR= are not allowed");
    setAbsoluteWord(words_, modal_, pa.abscissa, contour_.pole[pa.abscissa], true);
    setAbsoluteWord(words_, modal_, pa.ordinate, contour_.pole[pa.ordinate], true);
  }
}

}  // namespace ncoffset::interp
